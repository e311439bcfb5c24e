// Harmonic oscillators x'' = -x with phases p = i / 64, advanced by
// semi-implicit Euler (two base steps at a time under hip), whose exact
// solution is x = cos(t + p), v = -sin(t + p): @Energy, the sum of
// (x^2 + v^2) / 2, is range / 2 = 32 on it. @Clock sums @C, the base steps
// each item took, which has no exact solution. For `sim-run --reference
// simple|exact` on totals (test/Integration/reference-totals.test).
sim.simulation @oscillators range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s64 = arith.constant 1.5625e-2 : f64
    %p = arith.mulf %f, %s64 : f64
    %x = math.cos %p : f64
    sim.yield %x : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s64 = arith.constant 1.5625e-2 : f64
    %p = arith.mulf %f, %s64 : f64
    %s = arith.addf %t, %p : f64
    %x = math.cos %s : f64
    sim.yield %x : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s64 = arith.constant 1.5625e-2 : f64
    %p = arith.mulf %f, %s64 : f64
    %s = math.sin %p : f64
    %v = arith.negf %s : f64
    sim.yield %v : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s64 = arith.constant 1.5625e-2 : f64
    %p = arith.mulf %f, %s64 : f64
    %a = arith.addf %t, %p : f64
    %s = math.sin %a : f64
    %v = arith.negf %s : f64
    sim.yield %v : f64
  }
  sim.buffer @C : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }

  sim.component @Osc writes(@V, @X, @C) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %c = sim.read @C[%i] : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %hx = arith.mulf %h, %x : f64
    %v1 = arith.subf %v, %hx : f64
    %hv = arith.mulf %h, %v1 : f64
    %x1 = arith.addf %x, %hv : f64
    %c1 = arith.addf %c, %nf : f64
    sim.yield %v1, %x1, %c1 : f64, f64, f64
  }

  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %x2 = arith.mulf %x, %x : f64
    %v2 = arith.mulf %v, %v : f64
    %sum = arith.addf %x2, %v2 : f64
    %half = arith.constant 0.5 : f64
    %e = arith.mulf %half, %sum : f64
    sim.yield %e : f64
  }
  sim.total @Clock : f64 {
  ^bb0(%i: index):
    %c = sim.read @C[%i] : f64
    sim.yield %c : f64
  }

  sim.observe [@X, @V]
}
