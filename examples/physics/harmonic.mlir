// harmonic: harmonic oscillators, each driving a faster resonator (f64).
//
// Physics. Item i is one driver oscillator x'' = -w^2 x with w = 1 + i / 16
// (x(0) = 1, x'(0) = 0, so x = cos(w t)) that drives a resonator of
// frequency k = @ratio * w (default 2) at rest: y'' = -k^2 y + x(t),
// y(0) = y'(0) = 0, whose exact solution is
// y = (cos(w t) - cos(k t)) / (k^2 - w^2). Items are independent; w (and so
// the step counts) differs per item.
//
// Components (both velocity Verlet, one Verlet step of h = n dt per
// evaluation):
//   @Driver    writes @V (dx/dt, interp(none)) and @X (x, interpolated with
//              cubic Hermite through @V); reads only its own item.
//   @Resonator writes @W (dy/dt), @Y (y) and @F (the forcing x at its own
//              local time, kept so that Verlet has x at both ends of its
//              step); reads @X[i] interpolated at the end of each sub-step.
// Nothing reads through the back edge, so under hip the big step is
// max_steps (8) and each component sub-steps with its own num_steps; under
// traditional the big step is the global minimum (1 for the fastest item).
//
// num_steps: n = floor(@c / (freq * dt)), i.e. at most @c radians of phase per
// step (freq = w for @Driver, k for @Resonator). With dt = 1e-3 and
// @c = 0.04 over 256 items (w from 1 to 16.9) the driver takes 2 (w > 13.3)
// to 8 (capped, w < 5) base steps and the resonator 1 (w > 10) to 8, half as
// many as the driver, so under hip the resonator reads the driver inside
// the big steps (max_steps, 8): the
// interpolation of @X is what it sees there. python/accuracy_study.py
// substitutes #sim.linear and #sim.cubic for the Hermite interpolation of @X
// (the line marked `study-interp`).
//
// Items are grouped: hip sub-steps a thread group with its smallest
// num_steps, so w grows slowly with i (groups of 32 items span a factor
// below 2 in w); the study runs with --group-size 32.
//
// Observed: @X and @Y, both with exact bodies (`sim-run --reference exact`).
sim.simulation @harmonic range(256) dt(1.0e-3 : f64) max_steps(8) {
  // Radians of phase per (sub-)step that num_steps allows.
  sim.param @c = 4.0e-2 : f64
  // Resonator frequency over driver frequency (must not be 1).
  sim.param @ratio = 2.0 : f64

  sim.buffer @V : f64 interp(none) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @X : f64 interp(#sim.hermite<@V>) init { // study-interp
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f64
    sim.yield %one : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %sixteenth = arith.constant 6.25e-2 : f64
    %one = arith.constant 1.0 : f64
    %w = math.fma %fi, %sixteenth, %one : f64
    %wt = arith.mulf %w, %t : f64
    %x = math.cos %wt : f64
    sim.yield %x : f64
  }
  sim.buffer @W : f64 interp(none) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @Y : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %sixteenth = arith.constant 6.25e-2 : f64
    %one = arith.constant 1.0 : f64
    %w = math.fma %fi, %sixteenth, %one : f64
    %ratio = sim.get_param @ratio : f64
    %k = arith.mulf %w, %ratio : f64
    %wt = arith.mulf %w, %t : f64
    %kt = arith.mulf %k, %t : f64
    %cw = math.cos %wt : f64
    %ck = math.cos %kt : f64
    %num = arith.subf %cw, %ck : f64
    %k2 = arith.mulf %k, %k : f64
    %w2 = arith.mulf %w, %w : f64
    %den = arith.subf %k2, %w2 : f64
    %y = arith.divf %num, %den : f64
    sim.yield %y : f64
  }
  sim.buffer @F : f64 interp(none) init {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : f64
    sim.yield %x : f64
  }

  sim.component @Driver writes(@V, @X) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %sixteenth = arith.constant 6.25e-2 : f64
    %one = arith.constant 1.0 : f64
    %w = math.fma %fi, %sixteenth, %one : f64
    %c = sim.get_param @c : f64
    %dt = sim.get_param @dt : f64
    %wdt = arith.mulf %w, %dt : f64
    %q = arith.divf %c, %wdt : f64
    %cap = arith.constant 1.0e6 : f64
    %qc = arith.minimumf %q, %cap : f64
    %n = arith.fptosi %qc : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %sixteenth = arith.constant 6.25e-2 : f64
    %one = arith.constant 1.0 : f64
    %w = math.fma %fi, %sixteenth, %one : f64
    %half = arith.constant 0.5 : f64
    %w2 = arith.mulf %w, %w : f64
    %nw2 = arith.negf %w2 : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %hh = arith.mulf %h, %half : f64
    // Velocity Verlet: half kick, drift, half kick.
    %a0 = arith.mulf %nw2, %x : f64
    %vh = math.fma %hh, %a0, %v : f64
    %x1 = math.fma %h, %vh, %x : f64
    %a1 = arith.mulf %nw2, %x1 : f64
    %v1 = math.fma %hh, %a1, %vh : f64
    sim.yield %v1, %x1 : f64, f64
  }

  sim.component @Resonator writes(@W, @Y, @F) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %sixteenth = arith.constant 6.25e-2 : f64
    %one = arith.constant 1.0 : f64
    %w = math.fma %fi, %sixteenth, %one : f64
    %ratio = sim.get_param @ratio : f64
    %k = arith.mulf %w, %ratio : f64
    %c = sim.get_param @c : f64
    %dt = sim.get_param @dt : f64
    %kdt = arith.mulf %k, %dt : f64
    %q = arith.divf %c, %kdt : f64
    %cap = arith.constant 1.0e6 : f64
    %qc = arith.minimumf %q, %cap : f64
    %n = arith.fptosi %qc : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %y = sim.read @Y[%i] : f64
    %u = sim.read @W[%i] : f64
    %f0 = sim.read @F[%i] : f64
    // The driver at the end of this sub-step (interpolated under hip).
    %f1 = sim.read @X[%i] : f64
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %sixteenth = arith.constant 6.25e-2 : f64
    %one = arith.constant 1.0 : f64
    %w = math.fma %fi, %sixteenth, %one : f64
    %half = arith.constant 0.5 : f64
    %ratio = sim.get_param @ratio : f64
    %k = arith.mulf %w, %ratio : f64
    %k2 = arith.mulf %k, %k : f64
    %nk2 = arith.negf %k2 : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %hh = arith.mulf %h, %half : f64
    %a0 = math.fma %nk2, %y, %f0 : f64
    %uh = math.fma %hh, %a0, %u : f64
    %y1 = math.fma %h, %uh, %y : f64
    %a1 = math.fma %nk2, %y1, %f1 : f64
    %u1 = math.fma %hh, %a1, %uh : f64
    sim.yield %u1, %y1, %f1 : f64, f64, f64
  }

  sim.schedule [@Driver, @Resonator]
  sim.observe [@X, @Y]
}
