// A rod whose right neighbour index is computed in 8-bit integers:
// index_cast (i8(%i) + 1) is %i + 1 up to item 126, -128 at item 127 (the
// sum wraps; clamped to item 0), and negative or small again above. Items
// 100..259 are stiff (num_steps 1), the others take 8 base steps.
sim.simulation @index_i8 range(300) dt(1.0e-2 : f64) max_steps(8) {
  sim.buffer @U : f64 boundary(clamp) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s = arith.constant 0.1 : f64
    %a = arith.mulf %f, %s : f64
    %v = math.sin %a : f64
    sim.yield %v : f64
  }
  sim.component @Rod writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i32 = arith.index_cast %i : index to i32
    %c100 = arith.constant 100 : i32
    %c260 = arith.constant 260 : i32
    %s1 = arith.cmpi sge, %i32, %c100 : i32
    %s2 = arith.cmpi slt, %i32, %c260 : i32
    %stiff = arith.andi %s1, %s2 : i1
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %stiff, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u8 = arith.index_cast %i : index to i8
    %c1 = arith.constant 1 : i8
    %r8 = arith.addi %u8, %c1 : i8
    %ir = arith.index_cast %r8 : i8 to index
    %c1x = arith.constant 1 : index
    %il = arith.subi %i, %c1x : index
    %u = sim.read @U[%i] : f64
    %ul = sim.read @U[%il] : f64
    %ur = sim.read @U[%ir] : f64
    %s0 = arith.addf %ul, %ur : f64
    %two = arith.constant 2.0 : f64
    %u2 = arith.mulf %two, %u : f64
    %lap = arith.subf %s0, %u2 : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %k = arith.constant 5.0 : f64
    %hk = arith.mulf %h, %k : f64
    %un = math.fma %hk, %lap, %u : f64
    sim.yield %un : f64
  }
  sim.observe [@U]
}
