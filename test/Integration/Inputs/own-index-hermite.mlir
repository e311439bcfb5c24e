// A component that reads its own #sim.hermite buffer @Q at its own item
// through `0 + %i`, next to a window read of @P. For own-index.test.
sim.simulation @plus_zero range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @P : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %x = arith.sitofp %i64 : i64 to f64
    sim.yield %x : f64
  }
  sim.buffer @Q : f64 interp(#sim.hermite<@P>) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @M writes(@P, @Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 4 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c0 = arith.constant 0 : index
    %c1 = arith.constant 1 : index
    %me = arith.addi %c0, %i : index
    %l = arith.subi %i, %c1 : index
    %p = sim.read @P[%i] : f64
    %pl = sim.read @P[%l] : f64
    %q = sim.read @Q[%me] : f64
    %d = arith.subf %pl, %p : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %p1 = math.fma %h, %d, %p : f64
    %q1 = arith.addf %q, %h : f64
    sim.yield %p1, %q1 : f64, f64
  }
  sim.observe [@P, @Q]
}
