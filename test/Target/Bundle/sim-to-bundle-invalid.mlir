// Errors of sim-translate --sim-to-bundle: what a bundle cannot hold, and a
// strategy that does not compile (its errors name the strategy).
//
// RUN: sim-translate --sim-to-bundle --sim-cpu-isas=host %s --split-input-file --verify-diagnostics -o %t.simb

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

// -----

// A symbol with the name that the lowering gives the kernels of the scene
// (it was "redefinition of symbol named 'decay_kernels'").
// expected-note @+2 {{the simulation is here}}
// expected-note @+1 {{while compiling the bundle's strategy 'simple' (--sim-strategies chooses the strategies)}}
sim.simulation @decay range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}
// expected-error @+1 {{simulation @decay needs the name 'decay_kernels' for its kernels (--sim-lower-to-gpu puts them in a module of that name); rename this symbol}}
func.func private @decay_kernels()

// -----

// The same for the module of its reference functions, which are compiled
// after every strategy (lts among them, which says why it takes hip's plan).
// expected-remark @+3 {{strategy lts: no component takes local time steps, so the plan is hip's; a component takes them when it has num_steps, reads a buffer it writes at other items through a window (@B[%i + c]) and does not bound the big step (read through the back edge), or when it reads at its own items what the component that bounds the big step computes from its state (a pair, docs/Model.md); the remarks of --sim-substep-legality say why each component that reads its own buffers at other items, and each pair, does not}}
// expected-note @+2 {{the simulation is here}}
// expected-note @+1 {{while compiling the bundle's reference functions}}
sim.simulation @decay range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}
// expected-error @+1 {{simulation @decay needs the name 'decay_reference' for its reference functions (--sim-lower-to-reference puts them in a module of that name); rename this symbol}}
func.func private @decay_reference()

// -----

// A scene in a nested module: it was "there is no sim.simulation to write
// to a bundle".
module {
  // expected-note @+1 {{the enclosing op is here}}
  module @inner {
    // expected-error @+1 {{'sim.simulation' op must be directly in the top-level module, where the passes and sim-translate look for simulations, not in a nested 'builtin.module' @inner; move it to the top level}}
    sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(2) {
    }
  }
}
