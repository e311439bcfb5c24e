// RUN: sim-opt %s --split-input-file --sim-plan-memory --verify-diagnostics
// RUN: not sim-opt %s --split-input-file --sim-plan-memory=group-size=0 -o /dev/null 2>&1 | FileCheck %s --check-prefix=GROUP

// GROUP: error: --sim-plan-memory needs a positive group-size, but got 0

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

// -----

// After --sim-insert-interpolation the loads rely on the recorded decisions
// (here the snapshot of @U and the roles behind each load); re-deciding from
// a body without view reads would silently change them, so this stage
// refuses.

// expected-error @+1 {{'sim.simulation' op has explicit loads, so its memory plan is fixed; run --sim-plan-memory before --sim-insert-interpolation}}
sim.simulation @past_interpolation range(16) dt(1.0e-2 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @U : f32 attributes {snapshot} init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Diffuse writes(@U) attributes {parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>} num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    // expected-note @+1 {{the first explicit access is this 'sim.load'}}
    %u = sim.load local @U[%l] : f32
    sim.yield %u : f32
  }
  sim.component @Sample writes(@W) attributes {parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %T, %m = sim.big_step : i64, i64
    %u0 = sim.load snapshot @U[%i] : f32
    %u1 = sim.load target @U[%i] : f32
    %u = arith.addf %u0, %u1 : f32
    sim.yield %u : f32
  }
  sim.schedule [@Diffuse, @Sample]
  sim.observe [@W]
}
