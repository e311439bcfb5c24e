// Scenes the reference lowering cannot take give an error at the offending op.
//
// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-lower-to-reference

// No schedule: the executor would not know the order of a step.
// expected-error @+1 {{'sim.simulation' op has no complete schedule; run --sim-schedule before --sim-lower-to-reference}}
sim.simulation @unscheduled range(8) dt(1.0e-2 : f32) max_steps(2) {
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

// Scheduled, but without the sub-stepping verdict the executor needs for
// its groups.
sim.simulation @noverdict range(8) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has no sub-stepping verdict; run --sim-substep-legality before --sim-lower-to-reference}}
  sim.component @Keep writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Keep]
  sim.observe [@X]
}

// -----

// Past the memory plan: the reads are no longer views of the semantics.
// expected-error @+1 {{'sim.simulation' op is past --sim-plan-memory; the reference lowering starts from the scheduled IR (run --sim-prune, --sim-schedule and --sim-substep-legality, or --sim-reference-pipeline)}}
sim.simulation @planned range(8) dt(1.0e-2 : f32) max_steps(2) attributes {strategy = #sim<strategy simple>} {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) attributes {parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.load local @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Keep]
  sim.observe [@X]
}

// -----

// A parameter type the executor cannot hold.
sim.simulation @half range(8) dt(1.0e-2 : f32) max_steps(2) {
  // expected-error @+1 {{'sim.param' op has type 'f16', which the reference executor cannot hold; use i32, i64, index, f32 or f64}}
  sim.param @h = 1.0 : f16
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) attributes {sub_stepping = #sim<sub_stepping in_kernel>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Keep]
  sim.observe [@X]
}
