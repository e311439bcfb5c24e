// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory | FileCheck %s --check-prefixes=CHECK,HIP
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=simple | FileCheck %s --check-prefixes=CHECK,SIMPLE
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=hip-cache | FileCheck %s --check-prefixes=CHECK,CACHE

// Every writer sub-steps in one kernel: its source half keeps the value at T,
// so nothing is snapshotted and no parity copy is needed, in any strategy.

// CHECK-LABEL: sim.simulation @no_snapshot
// HIP-SAME: attributes {strategy = #sim<strategy hip>}
// SIMPLE-SAME: attributes {strategy = #sim<strategy simple>}
// CACHE-SAME: attributes {strategy = #sim<strategy "hip-cache">}
// CHECK-NOT: snapshot
// CHECK: sim.component @Source writes(@S, @G) attributes {parity = #sim<parity none>
// HIP: sim.component @Reader writes(@R) attributes {parity = #sim<parity none>, sub_stepping
// SIMPLE: sim.component @Reader writes(@R) attributes {parity = #sim<parity none>, sub_stepping
// @S, read at i..i+1 (a window), is cached; the gather of @G is not.
// CACHE: sim.component @Reader writes(@R) attributes {caches = [@S], parity = #sim<parity none>
// CHECK-NOT: snapshot
sim.simulation @no_snapshot range(1024) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @G : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @R : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@S, @G) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %s = sim.read @S[%i] : f32
    %g = sim.read @G[%i] : f32
    sim.yield %s, %g : f32, f32
  }
  sim.component @Reader writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %a = sim.read @S[%j] : f32
    %b = sim.read @S[%i] : f32
    %c3 = arith.constant 3 : index
    %k = arith.muli %i, %c3 : index
    %g = sim.read @G[%k] : f32
    %s = arith.addf %a, %b : f32
    %r = arith.addf %s, %g : f32
    sim.yield %r : f32
  }
  sim.schedule [@Source]
  sim.observe [@R]
}

// -----

// @Diffuse reads its own neighbours and sub-steps (it has num_steps), so its
// sub-steps ping-pong through memory: it needs a parity copy under hip, and
// @U, which @Sample interpolates, needs a snapshot; so does @dU, the
// derivative that @U's Hermite interpolation reads. @W is written by an
// in_kernel component and needs none. Under simple nothing of this is
// needed.

// CHECK-LABEL: sim.simulation @needs_snapshot
// HIP: sim.buffer @U : f32 interp(#sim.hermite<@dU>) attributes {snapshot} init
// HIP: sim.buffer @dU : f32 attributes {snapshot} init
// CACHE: sim.buffer @U : f32 interp(#sim.hermite<@dU>) attributes {snapshot} init
// SIMPLE: sim.buffer @U : f32 interp(#sim.hermite<@dU>) init
// SIMPLE: sim.buffer @dU : f32 init
// CHECK: sim.buffer @W : f32 init
// HIP: sim.component @Diffuse writes(@U, @dU) attributes {parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>}
// SIMPLE: sim.component @Diffuse writes(@U, @dU) attributes {parity = #sim<parity none>, sub_stepping = #sim<sub_stepping grid_sync>}
// HIP: sim.component @Sample writes(@W) attributes {parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>}
sim.simulation @needs_snapshot range(1024) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 interp(#sim.hermite<@dU>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @dU : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Diffuse writes(@U, @dU) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %u = sim.read @U[%i] : f32
    %ul = sim.read @U[%l] : f32
    %d = arith.subf %ul, %u : f32
    sim.yield %ul, %d : f32, f32
  }
  sim.component @Sample writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %w = sim.read @W[%i] : f32
    %s = arith.addf %u, %w : f32
    sim.yield %s : f32
  }
  sim.schedule [@Diffuse]
  sim.observe [@W]
}

// -----

// @Smooth reads its own neighbours (grid_sync) but has no num_steps: under
// hip it takes the whole big step in one evaluation, from the source half
// into the target half, so nothing ping-pongs: no parity copy, and @U's
// source half still holds its value at T for @Sample (no snapshot).

// CHECK-LABEL: sim.simulation @grid_sync_one_evaluation
// CHECK-NOT: snapshot
// CHECK: sim.component @Smooth writes(@U) attributes {parity = #sim<parity none>, sub_stepping = #sim<sub_stepping grid_sync>}
// CHECK-NOT: snapshot
// CHECK-NOT: copy_if_even
sim.simulation @grid_sync_one_evaluation range(1024) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Smooth writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %ul = sim.read @U[%l] : f32
    sim.yield %ul : f32
  }
  sim.component @Sample writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.observe [@W]
}
