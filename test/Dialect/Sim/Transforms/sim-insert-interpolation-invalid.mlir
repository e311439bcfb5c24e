// RUN: sim-opt %s --split-input-file --sim-insert-interpolation --verify-diagnostics

// expected-error @+1 {{'sim.simulation' op has no memory plan; run --sim-plan-memory before --sim-insert-interpolation}}
sim.simulation @no_plan range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] own : f32
    sim.yield %x : f32
  }
  sim.schedule [@C]
  sim.observe [@X]
}

// -----

// expected-error @+1 {{'sim.simulation' op has no complete schedule; run --sim-schedule before --sim-insert-interpolation}}
sim.simulation @no_schedule range(16) dt(1.0e-2 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] own : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}

// -----

sim.simulation @no_role range(16) dt(1.0e-2 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.read' op has no read role; run --sim-schedule before --sim-insert-interpolation}}
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@C]
  sim.observe [@X]
}

// -----

// @V, the derivative of @X's Hermite interpolation, is written by @Reader
// itself: its value at the end of the big step does not exist yet.

sim.simulation @derivative_too_late range(16) dt(1.0e-2 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @X : f32 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Writer writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] own : f32
    sim.yield %x : f32
  }
  sim.component @Reader writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.read' op interpolates @X with #sim.hermite<@V>, which needs @V at the end of the big step, but @Reader writes @V itself, so it is not there while @Reader runs; use #sim.linear or #sim.cubic for @X, or write @V in a component that runs before}}
    %x = sim.read @X[%i] interpolate : f32
    sim.yield %x : f32
  }
  sim.schedule [@Writer, @Reader]
  sim.observe [@V]
}

// -----

// A hand-written plan that --sim-plan-memory would have rejected: the read
// of an interp(none) buffer needs an intermediate value under hip, where
// @Drift sub-steps.

sim.simulation @not_interpolable range(16) dt(1.0e-2 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  // expected-note @+1 {{@P is declared interp(none) here}}
  sim.buffer @P : f32 interp(none) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Kick writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %p = sim.read @P[%i] own : f32
    sim.yield %p : f32
  }
  sim.component @Drift writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.read' op reads @P at an intermediate time of the big step (@Drift's evaluate interpolates buffers advanced earlier in the step under hip), but @P is declared interp(none)}}
    %p = sim.read @P[%i] interpolate : f32
    sim.yield %p : f32
  }
  sim.schedule [@Kick, @Drift]
  sim.observe [@X]
}
