// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality="remarks=false" --sim-plan-memory=strategy=hip --verify-diagnostics | FileCheck %s
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality="remarks=false" --sim-plan-memory=strategy=hip-cache --verify-diagnostics | FileCheck %s
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality="remarks=false" --sim-plan-memory=strategy=lts --verify-diagnostics | FileCheck %s --check-prefix=LTS
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality="remarks=false" --sim-plan-memory=strategy=simple --verify-diagnostics | FileCheck %s --check-prefix=SIMPLE

// invariant_estimate: a grid_substeps component (it reads its own buffer
// at other items, so every item sub-steps with the grid-wide minimum) whose
// num_steps reads neither %t nor a buffer has the same minimum in every
// round of a big step: its first round's estimate is kept for the others.
// Under lts such a component takes local steps (invariant_levels instead);
// under simple nothing sub-steps.

// num_steps from the item and a parameter: invariant. num_steps that reads
// its own state, or %t: not.

// CHECK-LABEL: sim.simulation @material
// CHECK: sim.component @Diffuse writes(@U) attributes {advance = #sim<advance grid_substeps>, invariant_estimate, local_window = array<i64: -1, 0>, parity
// CHECK: sim.component @ByState writes(@V) attributes {advance = #sim<advance grid_substeps>, local_window = array<i64: -1, 0>, parity
// CHECK: sim.component @ByTime writes(@W) attributes {advance = #sim<advance grid_substeps>, local_window = array<i64: 0, 1>, parity
// LTS-LABEL: sim.simulation @material
// LTS: sim.component @Diffuse writes(@U) attributes {advance = #sim<advance local_steps>, invariant_levels, local_window
// SIMPLE-LABEL: sim.simulation @material
// SIMPLE-NOT: invariant
sim.simulation @material range(64) dt(1.0e-2 : f32) max_steps(8) {
  sim.param @scale = 3.0 : f32
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %k = arith.sitofp %i64 : i64 to f32
    %s = sim.get_param @scale : f32
    %q = arith.mulf %k, %s : f32
    %n = arith.fptosi %q : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %ul = sim.read @U[%l] : f32
    sim.yield %ul : f32
  }
  sim.component @ByState writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %v = sim.read @V[%i] : f32
    %n = arith.fptosi %v : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %vl = sim.read @V[%l] : f32
    sim.yield %vl : f32
  }
  sim.component @ByTime writes(@W) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.trunci %t : i64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %r = arith.addi %i, %c1 : index
    %wr = sim.read @W[%r] : f32
    sim.yield %wr : f32
  }
  sim.schedule [@Diffuse, @ByState, @ByTime]
  sim.observe [@U, @V, @W]
}

// -----

// num_steps that reads a buffer another component writes: not invariant.
// A component that sub-steps per group (it reads no other item of its own
// buffers) has no rounds to keep an estimate for.

// CHECK-LABEL: sim.simulation @coupled
// CHECK: sim.component @Source writes(@S) attributes {advance = #sim<advance group_substeps>, parity
// CHECK: sim.component @Diffuse writes(@U) attributes {advance = #sim<advance grid_substeps>, local_window = array<i64: -1, 0>, parity
// LTS-LABEL: sim.simulation @coupled
// LTS-NOT: invariant
// SIMPLE-LABEL: sim.simulation @coupled
// SIMPLE-NOT: invariant
sim.simulation @coupled range(64) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %s = sim.read @S[%i] : f32
    sim.yield %s : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %s = sim.read @S[%i] : f32
    %n = arith.fptosi %s : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %ul = sim.read @U[%l] : f32
    sim.yield %ul : f32
  }
  sim.observe [@U]
}
