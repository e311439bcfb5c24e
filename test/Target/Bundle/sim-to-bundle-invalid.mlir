// Errors of sim-translate --sim-to-bundle: what a bundle cannot hold, and a
// strategy that does not compile (its errors name the strategy).
//
// RUN: sim-translate --sim-to-bundle %s --split-input-file --verify-diagnostics -o %t.simb

// expected-error @+1 {{there is no sim.simulation to write to a bundle}}
module {
}

// -----

// expected-note @+1 {{the first one}}
sim.simulation @first range(16) dt(1.0e-2 : f32) max_steps(2) {
}
// expected-error @+1 {{a bundle holds one scene; this is a second sim.simulation}}
sim.simulation @second range(16) dt(1.0e-2 : f32) max_steps(2) {
}

// -----

sim.simulation @flag range(16) dt(1.0e-2 : f32) max_steps(2) {
  // expected-error @+1 {{'sim.param' op has type 'i1', which a bundle cannot hold (parameters are i32, i64, index, f32 or f64)}}
  sim.param @on = true
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}

// -----

// A momentum without a value between the ends of a big step, read
// interpolated: simple and traditional compile, hip does not.
// expected-note @+1 {{while compiling the bundle's strategy 'hip' (--sim-strategies chooses the strategies)}}
sim.simulation @leapfrog range(64) dt(1.0e-2 : f32) max_steps(4) {
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
    %p = sim.read @P[%i] : f32
    %x = sim.read @X[%i] : f32
    %q = arith.subf %p, %x : f32
    sim.yield %q : f32
  }
  // The drift sub-steps, so it would read @P inside the big step.
  sim.component @Drift writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    // expected-error @+1 {{'sim.read' op reads @P at an intermediate time of the big step (@Drift's evaluate interpolates buffers advanced earlier in the step under hip), but @P is declared interp(none)}}
    %p = sim.read @P[%i] : f32
    %y = arith.addf %x, %p : f32
    sim.yield %y : f32
  }
  sim.schedule [@Kick]
  sim.observe [@X]
}
