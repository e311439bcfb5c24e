// Harmonic oscillators that declare their energy and momentum as totals.
//
// @Osc advances X'' = -w^2 X (w = 1 + i / 64) with semi-implicit
// (symplectic) Euler, 1 + i % 2 base steps at a time. @Energy is the sum of
// 0.5 v^2 + 0.5 w^2 x^2 over the items, @Momentum the sum of v. The
// modified energy of symplectic Euler is conserved, so the energy stays
// within about h w of its initial value (h <= 0.02, w < 2).
sim.simulation @totals range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f64
    sim.yield %one : f64
  }

  sim.component @Osc writes(@V, @X) num_steps {
  ^bb0(%i: index, %t: i64):
    %i32 = arith.index_cast %i : index to i32
    %c2 = arith.constant 2 : i32
    %c1 = arith.constant 1 : i32
    %r = arith.remsi %i32, %c2 : i32
    %n = arith.addi %r, %c1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s = arith.constant 1.5625e-2 : f64
    %one = arith.constant 1.0 : f64
    %fs = arith.mulf %f, %s : f64
    %w = arith.addf %fs, %one : f64
    %w2 = arith.mulf %w, %w : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %wx = arith.mulf %w2, %x : f64
    %acc = arith.negf %wx : f64
    %hv = arith.mulf %h, %acc : f64
    %v1 = arith.addf %v, %hv : f64
    %hx = arith.mulf %h, %v1 : f64
    %x1 = arith.addf %x, %hx : f64
    sim.yield %v1, %x1 : f64, f64
  }

  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s = arith.constant 1.5625e-2 : f64
    %one = arith.constant 1.0 : f64
    %fs = arith.mulf %f, %s : f64
    %w = arith.addf %fs, %one : f64
    %wx = arith.mulf %w, %x : f64
    %wx2 = arith.mulf %wx, %wx : f64
    %v2 = arith.mulf %v, %v : f64
    %sum = arith.addf %v2, %wx2 : f64
    %half = arith.constant 0.5 : f64
    %e = arith.mulf %half, %sum : f64
    sim.yield %e : f64
  }
  sim.total @Momentum : f64 {
  ^bb0(%i: index):
    %v = sim.read @V[%i] : f64
    sim.yield %v : f64
  }

  sim.observe [@X]
}
