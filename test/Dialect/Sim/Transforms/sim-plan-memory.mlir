// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory | FileCheck %s --check-prefixes=CHECK,HIP
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=simple | FileCheck %s --check-prefixes=CHECK,SIMPLE
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=hip-cache | FileCheck %s --check-prefixes=CHECK,CACHE
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory="strategy=hip-cache group-size=16" | FileCheck %s --check-prefixes=CHECK,CACHE16

// Every writer sub-steps in one kernel: its source half keeps the value at T,
// so nothing is snapshotted and no parity copy is needed, in any strategy.

// CHECK-LABEL: sim.simulation @no_snapshot
// HIP-SAME: attributes {step_cap = 4 : i32, strategy = #sim<strategy hip>}
// SIMPLE-SAME: attributes {step_cap = 1 : i32, strategy = #sim<strategy simple>}
// CACHE-SAME: attributes {step_cap = 4 : i32, strategy = #sim<strategy "hip-cache">}
// CACHE16-SAME: attributes {step_cap = 4 : i32, strategy = #sim<strategy "hip-cache">}
// CHECK-NOT: snapshot
// CHECK: sim.component @Source writes(@S, @G) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>
// HIP: sim.component @Reader writes(@R) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>, sub_stepping
// SIMPLE: sim.component @Reader writes(@R) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>, sub_stepping
// @S, read at i and i+1 (a window i..i+1), is cached; the gather of @G is
// not.
// CACHE: sim.component @Reader writes(@R) attributes {advance = #sim<advance whole_step>, caches = [#sim.cache<@S, 0, 1>], parity = #sim<parity none>
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
// HIP: sim.component @Diffuse writes(@U, @dU) attributes {advance = #sim<advance grid_substeps>, invariant_estimate, local_window = array<i64: -1, 0>, parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>}
// SIMPLE: sim.component @Diffuse writes(@U, @dU) attributes {advance = #sim<advance whole_step>, local_window = array<i64: -1, 0>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping grid_sync>}
// HIP: sim.component @Sample writes(@W) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>}
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
// CHECK: sim.component @Smooth writes(@U) attributes {advance = #sim<advance whole_step>, local_window = array<i64: -1, 0>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping grid_sync>}
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

// -----

// @Lead reads its own neighbours (grid_sync) and has num_steps, but it reads
// @W through the back edge, so it bounds the hip big step: the minimum of
// its num_steps at T is at least m, and it takes the big step in one
// evaluation. Nothing ping-pongs: no parity copy, and @U's source half keeps
// its value at T for @Follow (no snapshot). (Planning a snapshot here left
// it unfilled: the lowering never snapshots a bounding component, and the
// reference executor caught the readers interpolating from zeros.)

// CHECK-LABEL: sim.simulation @grid_sync_bounding
// CHECK-NOT: snapshot
// SIMPLE: sim.component @Lead writes(@U) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping grid_sync>}
// HIP: sim.component @Lead writes(@U) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping grid_sync>}
// CHECK-NOT: snapshot
// CHECK-NOT: copy_if_even
// CHECK: sim.schedule [@Lead, @Follow] bounded_by [@Lead]
sim.simulation @grid_sync_bounding range(1024) dt(1.0e-2 : f32) max_steps(4) {
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
  sim.component @Lead writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %ul = sim.read @U[%l] : f32
    %w = sim.read @W[%i] : f32
    %s = arith.addf %ul, %w : f32
    sim.yield %s : f32
  }
  sim.component @Follow writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.schedule [@Lead]
  sim.observe [@W]
}

// -----

// Caches only where they can be hit. @Reader interpolates:
// - @One at i+2 only: one offset, so no thread reads another's value;
// - @Small at i-1..i+1 (a loop) and at i: cached as the window -1..1;
// - @Wide at i-8..i+8: a halo of 16, cached with 256 threads per group but
//   not with 16;
// - @Mixed at i..i+1 and through a gather: the window is cached, the gather
//   reads global memory.
// Nothing is cached under hip.

// CHECK-LABEL: sim.simulation @cache_conditions
// CACHE: sim.component @Reader writes(@R) attributes {advance = #sim<advance whole_step>, caches = [#sim.cache<@Small, -1, 1>, #sim.cache<@Wide, -8, 8>, #sim.cache<@Mixed, 0, 1>], parity
// CACHE16: sim.component @Reader writes(@R) attributes {advance = #sim<advance whole_step>, caches = [#sim.cache<@Small, -1, 1>, #sim.cache<@Mixed, 0, 1>], parity
// HIP: sim.component @Reader writes(@R) attributes {advance = #sim<advance whole_step>, parity
sim.simulation @cache_conditions range(1024) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @One : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Small : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Wide : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Mixed : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @R : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@One, @Small, @Wide, @Mixed) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c = arith.constant 0.0 : f32
    sim.yield %c, %c, %c, %c : f32, f32, f32, f32
  }
  sim.component @Reader writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %i2 = arith.addi %i, %c2 : index
    %one = sim.read @One[%i2] : f32
    %lo = arith.constant -1 : index
    %zero = arith.constant 0.0 : f32
    %small = scf.for %k = %lo to %c2 step %c1 iter_args(%acc = %zero) -> f32 {
      %j = arith.addi %i, %k : index
      %v = sim.read @Small[%j] : f32
      %s = arith.addf %acc, %v : f32
      scf.yield %s : f32
    }
    %own = sim.read @Small[%i] : f32
    %m8 = arith.constant -8 : index
    %c9 = arith.constant 9 : index
    %wide = scf.for %k = %m8 to %c9 step %c1 iter_args(%acc = %zero) -> f32 {
      %j = arith.addi %i, %k : index
      %v = sim.read @Wide[%j] : f32
      %s = arith.addf %acc, %v : f32
      scf.yield %s : f32
    }
    %i1 = arith.addi %i, %c1 : index
    %m0 = sim.read @Mixed[%i] : f32
    %m1 = sim.read @Mixed[%i1] : f32
    %c3 = arith.constant 3 : index
    %g = arith.muli %i, %c3 : index
    %mg = sim.read @Mixed[%g] : f32
    %a = arith.addf %one, %small : f32
    %b = arith.addf %a, %own : f32
    %c = arith.addf %b, %wide : f32
    %d = arith.addf %c, %m0 : f32
    %e = arith.addf %d, %m1 : f32
    %f = arith.addf %e, %mg : f32
    sim.yield %f : f32
  }
  sim.observe [@R]
}

// -----

// With a single item no thread of a group reads another's value: no cache.

// CHECK-LABEL: sim.simulation @one_item
// CACHE: sim.component @Reader writes(@R) attributes {advance = #sim<advance whole_step>, parity
// CACHE16: sim.component @Reader writes(@R) attributes {advance = #sim<advance whole_step>, parity
sim.simulation @one_item range(1) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @R : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@S) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %s = sim.read @S[%i] : f32
    sim.yield %s : f32
  }
  sim.component @Reader writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %a = sim.read @S[%i] : f32
    %b = sim.read @S[%j] : f32
    %r = arith.addf %a, %b : f32
    sim.yield %r : f32
  }
  sim.observe [@R]
}
