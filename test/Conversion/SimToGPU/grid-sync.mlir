// A component that reads its own buffer at a neighbour (grid_sync) takes
// its hip sub-steps as rounds of launches with a grid-wide sub-step decided
// on the device: a snapshot of @U before (a later component interpolates
// it), max_steps rounds, and the parity copy after.
//
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu -o /dev/null 2>&1 | FileCheck %s --check-prefix=REMARK
// RUN: sim-opt %s --sim-front-end=strategy=simple --sim-lower-to-gpu | FileCheck %s --check-prefix=SIMPLE
// With a num_steps that reads %t every round estimates, and
// substep_advance clears the estimate for the next:
// RUN: sed 's/%c2 = arith.constant 2 : i32/%c2 = arith.trunci %%t : i64 to i32/' %s \
// RUN:   | sim-opt --sim-front-end=strategy=hip --sim-lower-to-gpu | FileCheck %s --check-prefix=TIMED
// TIMED-LABEL: gpu.func @substep_estimate_Diffuse(
// TIMED:         %[[MORE:.*]] = arith.cmpi sgt, %{{.*}}, %c1_i64
// TIMED-NEXT:    scf.if %[[MORE]]
// TIMED-LABEL: gpu.func @substep_advance_Diffuse(
// TIMED:         memref.store %{{.*}}, %{{.*}}[%c12]
// TIMED-NEXT:    memref.store %{{.*}}, %{{.*}}[%c13]

sim.simulation @diffuse range(100) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  // REMARK: remark: @Diffuse takes its sub-steps as 3 rounds of launches with a grid-wide sub-step decided on the device, a snapshot of @U before them, and a copy after an even number of sub-steps
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %left = sim.read @U[%l] : f32
    %u = sim.read @U[%i] : f32
    %s = arith.addf %left, %u : f32
    sim.yield %s : f32
  }
  sim.component @Watch writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.schedule [@Diffuse]
  sim.observe [@W]
}

// CHECK-LABEL: gpu.func @advance(
//                The sub-step clock of @Diffuse (slots 10..13) restarts at T.
// CHECK:         memref.store %{{.*}}, %{{.*}}[%c10]
// CHECK:         memref.store %{{.*}}, %{{.*}}[%c11]
// CHECK:         memref.store %{{.*}}, %{{.*}}[%c12]
// CHECK:         memref.store %{{.*}}, %{{.*}}[%c13]
// CHECK-LABEL: gpu.func @snapshot_U(
// CHECK-SAME:      %{{.*}}: memref<?xi64>, %[[U:.*]]: memref<?xf32>, %[[SNAP:.*]]: memref<?xf32>, %{{.*}}: i64) kernel
// CHECK:         %[[V:.*]] = memref.load %[[U]]
// CHECK:         memref.store %[[V]], %[[SNAP]]
// CHECK-LABEL: gpu.func @substep_estimate_Diffuse(
//                Estimates only with more than one base step left after the
//                pending sub-step (T + m - (t + n) > 1).
// CHECK:         %[[T:.*]] = memref.load %{{.*}}[%c0]
// CHECK:         %[[M:.*]] = memref.load %{{.*}}[%c1]
// CHECK:         %[[SUB_T:.*]] = memref.load %{{.*}}[%c10]
// CHECK:         %[[SUB_N:.*]] = memref.load %{{.*}}[%c11]
// CHECK:         %[[NOW:.*]] = arith.addi %[[SUB_T]], %[[SUB_N]]
// CHECK:         %[[END:.*]] = arith.addi %[[T]], %[[M]]
// CHECK:         %[[LEFT:.*]] = arith.subi %[[END]], %[[NOW]]
// CHECK:         %[[MORE:.*]] = arith.cmpi sgt, %[[LEFT]], %c1_i64
//                @Diffuse's num_steps is a constant (invariant_estimate): only
//                the big step's first round (no sub-step done or pending)
//                estimates, and substep_advance keeps its minimum for the
//                others (advance clears it for the next big step).
// CHECK:         %[[DONE:.*]] = arith.addi
// CHECK:         %[[FIRST:.*]] = arith.cmpi eq, %[[DONE]], %c0_i64
// CHECK:         %[[DUE:.*]] = arith.andi %[[MORE]], %[[FIRST]]
// CHECK:         scf.if %[[DUE]]
// CHECK:         gpu.subgroup_reduce minsi
// CHECK:         memref.atomic_rmw mins %{{.*}}, %{{.*}}[%c13] : (i64, memref<?xi64>) -> i64
// CHECK-LABEL: gpu.func @substep_advance_Diffuse(
// CHECK:         memref.load %{{.*}}[%c13]
// CHECK:         memref.store %{{.*}}, %{{.*}}[%c10]
// CHECK:         memref.store %{{.*}}, %{{.*}}[%c11]
// CHECK:         memref.store %{{.*}}, %{{.*}}[%c12]
// CHECK-NOT:     memref.store %{{.*}}, %{{.*}}[%c13]
// CHECK:         gpu.return
// CHECK-LABEL: gpu.func @substep_Diffuse(
// CHECK-SAME:      %{{.*}}: memref<?xi64>, %[[U:.*]]: memref<?xf32>, %{{.*}}: i64) kernel
//                Reads the half the sub-step count selects, writes the other.
// CHECK:         %[[COUNT:.*]] = memref.load %{{.*}}[%c12]
// CHECK:         %[[ODD:.*]] = arith.andi %[[COUNT]], %c1_i64
// CHECK:         %[[READ:.*]] = arith.xori %{{.*}}, %[[ODD]]
// CHECK:         arith.xori %[[READ]], %c1_i64
// CHECK:         scf.for
// CHECK:           memref.load %[[U]]
// CHECK:           memref.load %[[U]]
// CHECK:           memref.store %{{.*}}, %[[U]]
// CHECK-NOT:     gpu.barrier
// CHECK-LABEL: gpu.func @parity_Diffuse(
// CHECK:         arith.andi %{{.*}}, %c1_i64
// CHECK:         arith.cmpi eq
// CHECK:         scf.if
// CHECK:           memref.load
// CHECK:           memref.store
// CHECK-LABEL: gpu.func @evaluate_Watch(
// CHECK-SAME:      %[[SNAP:[^:]*]]: memref<?xf32>, %{{.*}}: i64) kernel
// CHECK:         memref.load %[[SNAP]]
// CHECK-LABEL: simplan.plan @diffuse strategy("hip")
// CHECK:         simplan.buffer @U : f32 stride(4) snapshot
// CHECK:         simplan.component @Diffuse writes [@U] evaluations(8) advance grid_substeps sub_clock(10){{$}}
// CHECK-NEXT:    simplan.component @Watch writes [@W] evaluations(9) advance whole_step{{$}}
// CHECK:         simplan.phase step {
// CHECK-NEXT:      simplan.launch @diffuse_kernels::@advance single [#simplan.arg<clock>]
// CHECK-NEXT:      simplan.launch @diffuse_kernels::@snapshot_U items [#simplan.arg<clock>, #simplan.arg<buffer @U>, #simplan.arg<snapshot @U>, #simplan.arg<range>]
// CHECK-NEXT:      simplan.repeat 3 {
// CHECK-NEXT:        simplan.launch @diffuse_kernels::@substep_estimate_Diffuse items
// CHECK-NEXT:        simplan.launch @diffuse_kernels::@substep_advance_Diffuse single
// CHECK-NEXT:        simplan.launch @diffuse_kernels::@substep_Diffuse items [#simplan.arg<clock>, #simplan.arg<buffer @U>, #simplan.arg<range>] for @Diffuse
// CHECK-NEXT:      }
// CHECK-NEXT:      simplan.launch @diffuse_kernels::@parity_Diffuse items
// CHECK-NEXT:      simplan.launch @diffuse_kernels::@evaluate_Watch items

// Under simple nothing ping-pongs: no snapshot, no rounds.
// SIMPLE-LABEL: simplan.plan @diffuse strategy("simple")
// SIMPLE:         simplan.buffer @U : f32 stride(4){{$}}
// SIMPLE-NOT:     simplan.repeat
// SIMPLE-NOT:     snapshot
