// A read at %i + c with c near the largest index (2^63 - 51): for items
// from 51 on, %i + c wraps around the 64-bit integers to a negative index,
// which the boundary rule then moves into the range. For
// window-overflow.test, which substitutes the boundary rule and offset.
sim.simulation @far_offset range(100) dt(1.0e-3 : f32) max_steps(8) {
  sim.buffer @U : f32 boundary(RULE) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 0.3 : f32
    %a = arith.mulf %f, %s : f32
    %v = math.sin %a : f32
    sim.yield %v : f32
  }
  sim.component @A writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i32 = arith.index_cast %i : index to i32
    %c20 = arith.constant 20 : i32
    %lt = arith.cmpi slt, %i32, %c20 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %lt, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %co = arith.constant OFFSET : index
    %ip = arith.addi %i, %co : index
    %im = arith.subi %i, %c1 : index
    %u0 = sim.read @U[%i] : f32
    %up = sim.read @U[%ip] : f32
    %um = sim.read @U[%im] : f32
    %s = arith.addf %up, %um : f32
    %two = arith.constant 2.0 : f32
    %u2 = arith.mulf %two, %u0 : f32
    %l = arith.subf %s, %u2 : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %u1 = math.fma %h, %l, %u0 : f32
    sim.yield %u1 : f32
  }
  sim.observe [@U]
}
