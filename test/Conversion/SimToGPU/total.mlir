// A total becomes a kernel `total_<name>` in phase `total`: every item's
// value, widened to f64, into the total's array. Its loads read the half the
// clock's parity selects (the state at T), under every strategy.
//
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=simple --sim-lower-to-gpu | FileCheck %s

sim.simulation @spin range(32) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Damp writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @V[%i] : f32
    %k = arith.constant 0.5 : f32
    %w = arith.mulf %k, %v : f32
    sim.yield %w : f32
  }
  sim.total @Energy : f32 {
  ^bb0(%i: index):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %v = sim.read @V[%j] : f32
    %e = arith.mulf %v, %v : f32
    sim.yield %e : f32
  }
  sim.observe [@V]
}

// CHECK-LABEL: gpu.func @total_Energy(
// CHECK-SAME:      %[[CLOCK:[^:]*]]: memref<?xi64>, %[[V:[^:]*]]: memref<?xf32>, %[[OUT:[^:]*]]: memref<?xf64>, %[[RANGE:[^:]*]]: i64) kernel attributes {simplan.clock_slots = 12 : i64, simplan.shared = array<i64: 0, 0>} {
// CHECK:         %[[C2:.*]] = arith.constant 2 : index
// CHECK:         %[[PARITY:.*]] = memref.load %[[CLOCK]][%[[C2]]] : memref<?xi64>
// CHECK:         %[[HALF:.*]] = arith.index_cast %[[PARITY]] : i64 to index
// CHECK:         %[[BASE:.*]] = arith.muli %[[HALF]], %{{.*}} : index
// CHECK:         scf.if
// The read of the neighbour follows the boundary rule, in the source half.
// CHECK:           arith.minsi
// CHECK:           %[[AT:.*]] = arith.addi %[[BASE]], %{{.*}} : index
// CHECK:           %[[VALUE:.*]] = memref.load %[[V]][%[[AT]]] : memref<?xf32>
// CHECK:           %[[E:.*]] = arith.mulf %[[VALUE]], %[[VALUE]] : f32
// CHECK:           %[[WIDE:.*]] = arith.extf %[[E]] : f32 to f64
// CHECK:           memref.store %[[WIDE]], %[[OUT]][%{{.*}}] : memref<?xf64>

// CHECK-LABEL: simplan.plan @spin
// CHECK:         simplan.buffer @V : f32 stride(4) observed
// CHECK:         simplan.total @Energy : f32
// CHECK:         simplan.phase total {
// CHECK-NEXT:      simplan.launch @spin_kernels::@total_Energy items [#simplan.arg<clock>, #simplan.arg<buffer @V>, #simplan.arg<total @Energy>, #simplan.arg<range>]
// CHECK-NEXT:    }
