// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=simple | FileCheck %s --check-prefixes=CHECK,SIMPLE
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=traditional | FileCheck %s --check-prefixes=CHECK,TRAD
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=hip | FileCheck %s --check-prefixes=CHECK,HIP
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=lts | FileCheck %s --check-prefixes=CHECK,LTS

// How each component takes a big step (`advance`), whether its num_steps
// decides the big step (`estimates`), and the largest big step (`step_cap`),
// recorded once per strategy:
// - simple: every component one evaluation of one base step, nobody
//   estimates;
// - traditional: every component one evaluation of the whole big step,
//   every component with num_steps estimates;
// - hip: @Lead reads @Tail through the back edge, so it bounds the big step
//   and takes it whole; @Middle sub-steps in one kernel (it reads its own
//   buffer at its own item); @Tail reads its own buffer at i+1, so it
//   sub-steps grid-wide; @Plain has no num_steps and takes the step whole.
// - lts: as hip, but @Tail's own read is a window (local_window [0, 1]), so
//   its blocks of 32 items take local time steps.

// CHECK-LABEL: sim.simulation @stepping
// SIMPLE-SAME: attributes {step_cap = 1 : i32, strategy = #sim<strategy simple>}
// TRAD-SAME: attributes {step_cap = 3 : i32, strategy = #sim<strategy traditional>}
// HIP-SAME: attributes {step_cap = 3 : i32, strategy = #sim<strategy hip>}
// LTS-SAME: attributes {step_cap = 3 : i32, strategy = #sim<strategy lts>}
// SIMPLE: sim.component @Lead writes(@L) attributes {advance = #sim<advance whole_step>, parity
// TRAD: sim.component @Lead writes(@L) attributes {advance = #sim<advance whole_step>, estimates, parity
// HIP: sim.component @Lead writes(@L) attributes {advance = #sim<advance whole_step>, estimates, parity
// LTS: sim.component @Lead writes(@L) attributes {advance = #sim<advance whole_step>, estimates, parity
// SIMPLE: sim.component @Middle writes(@M) attributes {advance = #sim<advance whole_step>, parity
// TRAD: sim.component @Middle writes(@M) attributes {advance = #sim<advance whole_step>, estimates, parity
// HIP: sim.component @Middle writes(@M) attributes {advance = #sim<advance group_substeps>, parity = #sim<parity none>
// LTS: sim.component @Middle writes(@M) attributes {advance = #sim<advance group_substeps>, parity = #sim<parity none>
// SIMPLE: sim.component @Tail writes(@T) attributes {advance = #sim<advance whole_step>, local_window = array<i64: 0, 1>, parity = #sim<parity none>
// TRAD: sim.component @Tail writes(@T) attributes {advance = #sim<advance whole_step>, estimates, local_window = array<i64: 0, 1>, parity = #sim<parity none>
// HIP: sim.component @Tail writes(@T) attributes {advance = #sim<advance grid_substeps>, invariant_estimate, local_window = array<i64: 0, 1>, parity = #sim<parity copy_if_even>
// LTS: sim.component @Tail writes(@T) attributes {advance = #sim<advance local_steps>, invariant_levels, local_window = array<i64: 0, 1>, parity = #sim<parity copy_if_even>
// CHECK: sim.component @Plain writes(@P) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>
// CHECK: sim.schedule [@Lead, @Middle, @Tail, @Plain] bounded_by [@Lead]
sim.simulation @stepping range(64) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @L : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @M : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @T : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @P : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Lead writes(@L) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %t0 = sim.read @T[%i] : f32
    sim.yield %t0 : f32
  }
  sim.component @Middle writes(@M) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %m = sim.read @M[%i] : f32
    %l = sim.read @L[%i] : f32
    %s = arith.addf %m, %l : f32
    sim.yield %s : f32
  }
  sim.component @Tail writes(@T) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %t1 = sim.read @T[%j] : f32
    %m = sim.read @M[%i] : f32
    %s = arith.addf %t1, %m : f32
    sim.yield %s : f32
  }
  sim.component @Plain writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %t0 = sim.read @T[%i] : f32
    sim.yield %t0 : f32
  }
  sim.schedule [@Lead]
  sim.observe [@P]
}

// -----

// With max_steps 1 every big step is one base step: no strategy estimates
// (nothing can lengthen the step) and nobody sub-steps (a sub-step would be
// the whole step), so hip and traditional take it as simple does.
// CHECK-LABEL: sim.simulation @one_step
// SIMPLE-SAME: attributes {step_cap = 1 : i32, strategy = #sim<strategy simple>}
// TRAD-SAME: attributes {step_cap = 1 : i32, strategy = #sim<strategy traditional>}
// HIP-SAME: attributes {step_cap = 1 : i32, strategy = #sim<strategy hip>}
// LTS-SAME: attributes {step_cap = 1 : i32, strategy = #sim<strategy lts>}
// CHECK: sim.component @Lead writes(@L) attributes {advance = #sim<advance whole_step>, parity
// CHECK: sim.component @Middle writes(@M) attributes {advance = #sim<advance whole_step>, parity
// CHECK: sim.component @Tail writes(@T) attributes {advance = #sim<advance whole_step>, local_window = array<i64: 0, 1>, parity = #sim<parity none>
// CHECK: sim.component @Plain writes(@P) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>
sim.simulation @one_step range(64) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @L : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @M : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @T : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @P : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Lead writes(@L) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %t0 = sim.read @T[%i] : f32
    sim.yield %t0 : f32
  }
  sim.component @Middle writes(@M) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %m = sim.read @M[%i] : f32
    %l = sim.read @L[%i] : f32
    %s = arith.addf %m, %l : f32
    sim.yield %s : f32
  }
  sim.component @Tail writes(@T) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %t1 = sim.read @T[%j] : f32
    %m = sim.read @M[%i] : f32
    %s = arith.addf %t1, %m : f32
    sim.yield %s : f32
  }
  sim.component @Plain writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %t0 = sim.read @T[%i] : f32
    sim.yield %t0 : f32
  }
  sim.schedule [@Lead]
  sim.observe [@P]
}
