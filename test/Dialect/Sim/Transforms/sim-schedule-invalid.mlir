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
