// The error of an interpolation function alone, on a smooth exact signal.
//
// @Driver advances an oscillator x(t) = cos(w t), v(t) = -w sin(w t) with
// w = 1 + i / 64 per item *exactly* (its evaluate writes the analytic values
// at t + n), in one evaluation per big step: without num_steps it takes the
// whole big step, and with nothing read through the back edge the hip big
// step is max_steps (8) base steps. @Probe, later in the step, sub-steps one
// base step at a time, so under hip it reads @X interpolated at the interior
// fractions 1/8 .. 7/8 of every big step, and keeps the largest difference
// from the exact cos(w (t + n) dt) seen so far in @E. So @E is the
// interpolation's error and nothing else (no integrator error): halving dt
// halves the big step h = 8 dt, and @E falls as h^p for an interpolation of
// order p (docs/Model.md: linear 2, the smoothstep cubic 1, Hermite with the
// derivative @V 4). test/Examples/interp-convergence.test fits p.
//
// The line marked study-interp is where a study substitutes #sim.linear or
// #sim.cubic for the Hermite interpolation.
sim.simulation @interp_probe range(64) dt(1.0e-2 : f64) max_steps(8) {
  sim.buffer @V : f64 interp(none) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f64
    sim.yield %zero : f64
  }
  sim.buffer @X : f64 interp(#sim.hermite<@V>) init { // study-interp
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f64
    sim.yield %one : f64
  }
  sim.buffer @E : f64 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f64
    sim.yield %zero : f64
  }

  sim.component @Driver writes(@V, @X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %i32 = arith.index_cast %i : index to i32
    %fi = arith.sitofp %i32 : i32 to f64
    %c64 = arith.constant 64.0 : f64
    %one = arith.constant 1.0 : f64
    %wi = arith.divf %fi, %c64 : f64
    %w = arith.addf %one, %wi : f64
    %n64 = arith.extsi %n : i32 to i64
    %end = arith.addi %t, %n64 : i64
    %endf = arith.sitofp %end : i64 to f64
    %time = arith.mulf %endf, %dt : f64
    %phase = arith.mulf %w, %time : f64
    %x = math.cos %phase : f64
    %s = math.sin %phase : f64
    %ws = arith.mulf %w, %s : f64
    %v = arith.negf %ws : f64
    sim.yield %v, %x : f64, f64
  }

  sim.component @Probe writes(@E) num_steps {
  ^bb0(%i: index, %t: i64):
    %one = arith.constant 1 : i32
    sim.yield %one : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    %e = sim.read @E[%i] : f64
    %i32 = arith.index_cast %i : index to i32
    %fi = arith.sitofp %i32 : i32 to f64
    %c64 = arith.constant 64.0 : f64
    %one = arith.constant 1.0 : f64
    %wi = arith.divf %fi, %c64 : f64
    %w = arith.addf %one, %wi : f64
    %n64 = arith.extsi %n : i32 to i64
    %end = arith.addi %t, %n64 : i64
    %endf = arith.sitofp %end : i64 to f64
    %time = arith.mulf %endf, %dt : f64
    %phase = arith.mulf %w, %time : f64
    %exact = math.cos %phase : f64
    %diff = arith.subf %x, %exact : f64
    %abs = math.absf %diff : f64
    %max = arith.maximumf %e, %abs : f64
    sim.yield %max : f64
  }

  sim.observe [@E]
}
