// A component that reads its own interp(none) buffer @R at its own item
// through an index computed from %i (a round trip through i64), next to a
// window read of @P. For own-index.test.
sim.simulation @round_trip range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @P : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %x = arith.sitofp %i64 : i64 to f64
    sim.yield %x : f64
  }
  sim.buffer @R : f64 interp(none) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @M writes(@P, @R) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 4 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %i64 = arith.index_cast %i : index to i64
    %c1 = arith.constant 1 : i64
    %l64 = arith.subi %i64, %c1 : i64
    %l = arith.index_cast %l64 : i64 to index
    %me = arith.index_cast %i64 : i64 to index
    %p = sim.read @P[%me] : f64
    %pl = sim.read @P[%l] : f64
    %r = sim.read @R[%me] : f64
    %d = arith.subf %pl, %p : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %p1 = math.fma %h, %d, %p : f64
    %r1 = arith.addf %r, %h : f64
    sim.yield %p1, %r1 : f64, f64
  }
  sim.observe [@P, @R]
}
