// RUN: sim-opt %s --split-input-file --sim-schedule --verify-diagnostics

// A dependency cycle with no first component named.

// expected-error @+1 {{the components depend on each other in a cycle (@A -> @B -> @A), so a step needs a first component whose reads cross the back edge; name it with 'sim.schedule [@A]' or similar}}
sim.simulation @cycle_without_entry range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @BA : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @BB : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @A writes(@BA) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-note @+1 {{@A reads @BB, which @B writes}}
    %v = sim.read @BB[%i] : f32
    sim.yield %v : f32
  }
  sim.component @B writes(@BB) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-note @+1 {{@B reads @BA, which @A writes}}
    %v = sim.read @BA[%i] : f32
    sim.yield %v : f32
  }
  sim.observe [@BB]
}

// -----

// Naming a first component that does not break the cycle: the cycle between
// B and C stays inside one step.

sim.simulation @cycle_in_step range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @BA : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @BB : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @BC : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @A writes(@BA) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @BC[%i] : f32
    sim.yield %v : f32
  }
  sim.component @B writes(@BB) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @BA[%i] : f32
    // expected-note @+1 {{@B reads @BC, which @C writes}}
    %c = sim.read @BC[%i] : f32
    %s = arith.addf %a, %c : f32
    sim.yield %s : f32
  }
  sim.component @C writes(@BC) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-note @+1 {{@C reads @BB, which @B writes}}
    %v = sim.read @BB[%i] : f32
    sim.yield %v : f32
  }
  // expected-error @+1 {{dependency cycle inside one step: @B -> @C -> @B; only the first component (@A) reads through the back edge}}
  sim.schedule [@A]
  sim.observe [@BC]
}

// -----

// Two independent components: the graph does not decide which goes first.

// expected-error @+1 {{the dependency graph does not decide which component starts a step: any of [@A, @B] could go next; list the order in 'sim.schedule'}}
sim.simulation @ambiguous_start range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @BA : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @BB : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-note @+1 {{@A could go next}}
  sim.component @A writes(@BA) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @BA[%i] : f32
    sim.yield %v : f32
  }
  // expected-note @+1 {{@B could go next}}
  sim.component @B writes(@BB) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @BB[%i] : f32
    sim.yield %v : f32
  }
  sim.observe [@BA, @BB]
}

// -----

// After the first component, two components could go next.

sim.simulation @ambiguous_after_prefix range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @BE : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @BL : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @BR : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @E writes(@BE) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %l = sim.read @BL[%i] : f32
    %r = sim.read @BR[%i] : f32
    %s = arith.addf %l, %r : f32
    sim.yield %s : f32
  }
  // expected-note @+1 {{@L could go next}}
  sim.component @L writes(@BL) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @BE[%i] : f32
    sim.yield %v : f32
  }
  // expected-note @+1 {{@R could go next}}
  sim.component @R writes(@BR) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @BE[%i] : f32
    sim.yield %v : f32
  }
  // expected-error @+1 {{the dependency graph does not decide the order after [@E]: any of [@L, @R] could go next; list the order in 'sim.schedule'}}
  sim.schedule [@E]
  sim.observe [@BE]
}

// -----

// A user order that puts a reader before the writer it depends on.

sim.simulation @order_violation range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @BA : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @BB : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @BC : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @A writes(@BA) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @BC[%i] : f32
    sim.yield %v : f32
  }
  sim.component @B writes(@BB) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @BA[%i] : f32
    sim.yield %v : f32
  }
  sim.component @C writes(@BC) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-note @+1 {{@C reads @BB, which @B writes}}
    %v = sim.read @BB[%i] : f32
    sim.yield %v : f32
  }
  // expected-error @+1 {{places @C before @B, but @C reads what @B writes in the same step; only the first component reads through the back edge}}
  sim.schedule [@A, @C, @B]
  sim.observe [@BC]
}

// -----

// After --sim-insert-interpolation the loads rely on the recorded decisions
// (here the snapshot of @U and the roles behind each load); re-deciding from
// a body without view reads would silently change them, so this stage
// refuses.

// expected-error @+1 {{'sim.simulation' op has explicit loads, so its schedule and read roles are fixed; run --sim-schedule before --sim-insert-interpolation}}
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
