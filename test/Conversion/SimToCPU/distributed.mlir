// A plan for many processes (--sim-front-end=distributed=true): the kernels
// address one rank's block (item i at element i - first + halo, halves
// `extent` elements apart), reads of other items come from the ghost items
// without the boundary rule (clamped into the rank's storage for the padding
// lanes of a last group), and the launches record the all-reduce of every
// estimate before the launch that consumes it and the exchange of every
// buffer that a read reaches at other items after each launch that writes
// it.
//
// RUN: sim-opt %s --sim-front-end="strategy=hip distributed=true" --sim-lower-to-cpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end="strategy=hip distributed=true" --sim-lower-to-gpu | FileCheck %s --check-prefix=GPU
// RUN: sim-opt %s --sim-front-end="strategy=hip" --sim-lower-to-cpu | FileCheck %s --check-prefix=ONE

sim.simulation @diffuse range(100) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @U : f32 boundary(zero) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
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

// CHECK-LABEL: func.func @init_U(
// CHECK-SAME:      %[[U:[a-z0-9]*]]: memref<?xf32>, %[[RANGE:[a-z0-9]*]]: i64, %[[FIRST:[a-z0-9]*]]: i64,
// CHECK:         %[[FIRSTI:.*]] = arith.index_cast %[[FIRST]] : i64 to index
// CHECK:         scf.for %[[G:.*]] =
// CHECK:           %[[BASE:.*]] = arith.addi %{{.*}}, %[[FIRSTI]] : index
// CHECK:             %[[ITEM:.*]] = arith.addi %[[BASE]], %{{.*}} : index
// CHECK:             %[[SHIFT:.*]] = arith.subi %[[ITEM]], %[[FIRSTI]] : index
// CHECK:             %[[AT:.*]] = arith.addi %[[SHIFT]], %c1{{.*}} : index
// CHECK:             memref.store %{{.*}}, %[[U]][%[[AT]]]

// The left neighbour: zero outside [0, range), else its element, clamped
// into [0, extent).
// CHECK-LABEL: func.func @substep_Diffuse(
// CHECK:         %[[LEFT:.*]] = arith.subi %{{.*}}, %c1{{.*}} : index
// CHECK:         arith.cmpi ult, %[[LEFT]], %{{.*}} : index
// CHECK:         arith.subi %[[LEFT]], %{{.*}} : index
// CHECK:         arith.maxsi
// CHECK:         arith.minsi
// CHECK:         memref.load
// CHECK:         arith.select

// CHECK-LABEL: simplan.plan @diffuse
// CHECK-SAME:      distributed halo(1) {
// CHECK:         simplan.buffer @U : f32 stride(4) snapshot halo [1, 0]
// CHECK:         simplan.buffer @W : f32 stride(4) observed{{$}}
// CHECK:         simplan.launch @diffuse_kernels::@init_U items {{.*}} exchange [@U]
// CHECK-NEXT:    simplan.launch @diffuse_kernels::@init_W items
// CHECK-NOT:     exchange
// CHECK:         simplan.launch @diffuse_kernels::@advance single [#simplan.arg<clock>]{{$}}
//                @Watch reads the snapshot at its own item only: it stays on
//                its rank (distributed-snapshot.mlir has one that travels).
// CHECK:         simplan.launch @diffuse_kernels::@snapshot_U items [{{.*}}]{{$}}
// CHECK:         simplan.repeat 3 {
// CHECK:           simplan.launch @diffuse_kernels::@substep_advance_Diffuse single [#simplan.arg<clock>] reduce_min [13]
//                  A sub-step sends the half it wrote, the parity copy the
//                  target half.
// CHECK:           simplan.launch @diffuse_kernels::@substep_Diffuse items {{.*}} for @Diffuse exchange_sub_step [@U]{{$}}
// CHECK:         simplan.launch @diffuse_kernels::@parity_Diffuse items {{.*}} for @Diffuse exchange_targets [@U]{{$}}
// CHECK:         simplan.launch @diffuse_kernels::@evaluate_Watch items {{.*}} for @Watch{{$}}

// The GPU kernels take the same arguments; a block's grid runs once.
// GPU-LABEL: gpu.func @init_U(
// GPU-SAME:      %{{.*}}: memref<?xf32>, %{{.*}}: i64, %{{.*}}: i64) kernel
// GPU-LABEL: simplan.plan @diffuse
// GPU-SAME:      distributed halo(1) {

// One process: no first item, no extent, no communication.
// ONE-LABEL: func.func @init_U(
// ONE-SAME:      %{{.*}}: memref<?xf32>, %{{.*}}: i64, %{{.*}}: i64, %{{.*}}: i64, %{{.*}}: i64) attributes
// ONE-NOT:   distributed
// ONE-NOT:   exchange
// ONE-NOT:   reduce_min
