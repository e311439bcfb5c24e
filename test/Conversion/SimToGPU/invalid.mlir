// Scenes the lowering cannot take give an error at the offending op.
//
// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-lower-to-gpu

// The front end has not run: nothing says which strategy to lower for.
// expected-error @+1 {{'sim.simulation' op has no memory plan; run the front end (--sim-front-end) before lowering it}}
sim.simulation @raw range(8) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}

// -----

// A plan without a complete schedule.
// expected-error @+1 {{'sim.simulation' op has no complete schedule; run the front end (--sim-front-end) before lowering it}}
sim.simulation @unscheduled range(8) dt(1.0e-2 : f32) max_steps(2) attributes {step_cap = 1 : i32, strategy = #sim<strategy simple>} {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.load local @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}

// -----

// A parameter type that no kernel argument can carry.
sim.simulation @half range(8) dt(1.0e-2 : f32) max_steps(2) attributes {step_cap = 1 : i32, strategy = #sim<strategy simple>} {
  // expected-error @+1 {{'sim.param' op has type 'f16', which a kernel cannot take as an argument; use i32, i64, index, f32 or f64}}
  sim.param @h = 1.0 : f16
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.load local @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Keep]
  sim.observe [@X]
}

// -----

// The big step is not known yet when the components that bound it estimate
// it, so their num_steps cannot ask for it.
sim.simulation @early range(8) dt(1.0e-2 : f32) max_steps(2) attributes {step_cap = 2 : i32, strategy = #sim<strategy hip>} {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    // expected-error @+1 {{'sim.big_step' op asks for the big step in a body that runs before the big step is decided}}
    %begin, %size = sim.big_step : i64, i64
    %n = arith.trunci %size : i64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.load local @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Keep] bounded_by [@Keep]
  sim.observe [@X]
}

// -----

// A total whose reads --sim-insert-interpolation has not turned into loads.
sim.simulation @rawtotal range(8) dt(1.0e-2 : f32) max_steps(2) attributes {step_cap = 1 : i32, strategy = #sim<strategy simple>} {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.load local @X[%i] : f32
    sim.yield %x : f32
  }
  sim.total @Sum : f32 {
  ^bb0(%i: index):
    // expected-error @+1 {{'sim.read' op is a view read; run --sim-insert-interpolation (or the whole front end) before lowering it}}
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Keep]
  sim.observe [@X]
}
