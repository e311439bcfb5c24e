// RUN: sim-opt %s --split-input-file --sim-plan-memory --verify-diagnostics

sim.simulation @no_verdict range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has no sub-stepping verdict; run --sim-substep-legality before --sim-plan-memory}}
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] own : f32
    sim.yield %x : f32
  }
  sim.schedule [@C]
  sim.observe [@X]
}

// -----

sim.simulation @no_roles range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) attributes {sub_stepping = #sim<sub_stepping in_kernel>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.read' op has no read role; run --sim-schedule before --sim-plan-memory}}
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}
