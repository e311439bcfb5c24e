// A rod whose neighbour indices are computed in unsigned 32-bit integers
// (as `sim.u32(i) - 1` in Python writes them): `index_castui` zero-extends,
// so the left neighbour of item 0 is item 2^32 - 1 (clamped to the last
// item), not item -1. Both neighbours are gathers. The stiff cells
// (num_steps 1) are the first 40.
sim.simulation @index_castui range(100) dt(1.0e-2 : f64) max_steps(8) {
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
    %c40 = arith.constant 40 : i32
    %stiff = arith.cmpi slt, %i32, %c40 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %stiff, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u32 = arith.index_castui %i : index to i32
    %c1 = arith.constant 1 : i32
    %l32 = arith.subi %u32, %c1 : i32
    %r32 = arith.addi %u32, %c1 : i32
    %il = arith.index_castui %l32 : i32 to index
    %ir = arith.index_castui %r32 : i32 to index
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
