// RUN: sim-opt %s --split-input-file --sim-prune --verify-diagnostics

// expected-error @+1 {{has no 'sim.observe', so nothing is needed; list the observed output buffers before pruning}}
sim.simulation @unobserved range(16) dt(1.0e-2 : f32) max_steps(2) {
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
}

// -----

// After --sim-insert-interpolation the loads rely on the recorded decisions
// (here the snapshot of @U and the roles behind each load); re-deciding from
// a body without view reads would silently change them, so this stage
// refuses.

// expected-error @+1 {{'sim.simulation' op has explicit loads, so its components and buffers are fixed; run --sim-prune before --sim-insert-interpolation}}
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
