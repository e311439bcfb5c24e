// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=lts --verify-diagnostics | FileCheck %s

// Under lts a component with num_steps that reads its own buffer through a
// window takes local time steps: it ping-pongs per block, so it needs the
// parity copy, and the buffer a later component interpolates a snapshot.

// CHECK-LABEL: sim.simulation @stencil
// CHECK-SAME: strategy = #sim<strategy lts>
// CHECK: sim.buffer @U : f32 attributes {snapshot}
// CHECK: sim.component @Diffuse writes(@U) attributes {advance = #sim<advance local_steps>, invariant_levels, local_window = array<i64: -1, 1>, parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>}
// CHECK: sim.component @Follow writes(@Q) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>
sim.simulation @stencil range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Q : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{under lts its blocks of 32 items take local time steps (window i-1..i+1)}}
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : f32
    // expected-note @+1 {{reads @U at i-1}}
    %ul = sim.read @U[%l] : f32
    %ur = sim.read @U[%r] : f32
    %s = arith.addf %ul, %ur : f32
    %d = arith.subf %s, %u : f32
    sim.yield %d : f32
  }
  sim.component @Follow writes(@Q) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.observe [@Q]
}

// -----

// Nothing that lts could use: a remark, and hip's plan.

// CHECK-LABEL: sim.simulation @pointwise
// CHECK: sim.component @Decay writes(@U) attributes {advance = #sim<advance group_substeps>
// expected-remark @+1 {{strategy lts: no component takes local time steps, so the plan is hip's; a component takes them when it has num_steps, reads a buffer it writes at other items through a window}}
sim.simulation @pointwise range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %h = arith.constant 0.5 : f32
    %d = arith.mulf %u, %h : f32
    sim.yield %d : f32
  }
  sim.observe [@U]
}

// -----

// max_steps 1: every big step is one base step, so no component takes local
// time steps, though the stencil could with a larger max_steps; the remark
// says so instead of pointing at the sub-stepping remarks.

// CHECK-LABEL: sim.simulation @one_base_step
// CHECK: sim.component @Diffuse writes(@U) attributes {advance = #sim<advance whole_step>
// expected-remark @+1 {{strategy lts: max_steps is 1, so every big step is one base step and every strategy steps as simple does: no component takes local time steps (what the remarks of --sim-substep-legality say about lts holds from max_steps 2)}}
sim.simulation @one_base_step range(64) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{under lts its blocks of 32 items take local time steps (window i-1..i+1)}}
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : f32
    // expected-note @+1 {{reads @U at i-1}}
    %ul = sim.read @U[%l] : f32
    %ur = sim.read @U[%r] : f32
    %s = arith.addf %ul, %ur : f32
    %d = arith.subf %s, %u : f32
    sim.yield %d : f32
  }
  sim.observe [@U]
}
