// The CPU kernels are the GPU kernels' algorithms with a group as a loop
// iteration and a lane as an inner loop: the same names, arguments and plan,
// plus the range of groups to run.
//
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-cpu | FileCheck %s --implicit-check-not=gpu.
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-cpu | sim-opt | FileCheck %s --implicit-check-not=gpu.
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-cpu > %t.cpu
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu > %t.gpu
// RUN: grep "^ *simplan[.]" %t.cpu > %t.cpu.plan
// RUN: grep "^ *simplan[.]" %t.gpu > %t.gpu.plan
// RUN: diff %t.cpu.plan %t.gpu.plan

sim.simulation @pair range(100) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Lead writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %y = sim.read @Y[%i] : f32
    %s = arith.addf %x, %y : f32
    sim.yield %s : f32
  }
  sim.component @Follow writes(@Y) num_steps {
  ^bb0(%i: index, %t: i64):
    %c3 = arith.constant 3 : i32
    sim.yield %c3 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %y = sim.read @Y[%i] : f32
    %s = arith.mulf %x, %y : f32
    sim.yield %s : f32
  }
  sim.schedule [@Lead]
  sim.observe [@Y]
}

// CHECK-LABEL: module @pair_kernels {
//                The estimate of the next big step: each group first reads
//                the running minimum (slot 4) and skips its lanes once it is
//                1, since no estimate is smaller; else it adds its own. The
//                groups start at the one whose first item slot 7 holds
//                (where the last estimate found 1), when the invocation
//                handles it, and go round; a group that brings the slot to
//                1 records its first item there.
// CHECK-LABEL: func.func @estimate_Lead(
// CHECK-SAME:      %[[ECLOCK:[^:]*]]: memref<?xi64>
// CHECK:         %[[HINT:.*]] = memref.atomic_rmw addi %c0_i64, %[[ECLOCK]][%c7]
// CHECK:         %[[HINTITEM:.*]] = arith.index_cast %[[HINT]] : i64 to index
// CHECK:         %[[HINTGROUP:.*]] = arith.divui %[[HINTITEM]],
// CHECK:         %[[OFFSET:.*]] = arith.subi %[[HINTGROUP]], %[[FROM:.*]] : index
// CHECK:         %[[HANDLED:.*]] = arith.cmpi ult, %[[OFFSET]], %[[SPAN:.*]] : index
// CHECK:         %[[SHIFT:.*]] = arith.select %[[HANDLED]], %[[OFFSET]], %c0 : index
// CHECK:         scf.for %[[K:.*]] = %[[FROM]] to %[[TO:.*]] step %c1 {
// CHECK:           %[[SHIFTED:.*]] = arith.addi %[[K]], %[[SHIFT]] : index
// CHECK:           %[[INSIDE:.*]] = arith.cmpi ult, %[[SHIFTED]], %[[TO]] : index
// CHECK:           %[[WRAPPED:.*]] = arith.subi %[[SHIFTED]], %[[SPAN]] : index
// CHECK:           %[[GROUPINDEX:.*]] = arith.select %[[INSIDE]], %[[SHIFTED]], %[[WRAPPED]] : index
// CHECK:           %[[BASE:.*]] = arith.muli %[[GROUPINDEX]],
// CHECK:           %[[SEEN:.*]] = memref.atomic_rmw addi %c0_i64, %[[ECLOCK]][%c4]
// CHECK:           %[[OPEN:.*]] = arith.cmpi sgt, %[[SEEN]], %c1_i64 : i64
// CHECK:           scf.if %[[OPEN]] {
// CHECK:             scf.for
// CHECK:               arith.minsi
// CHECK:             } {simplan.lanes}
// CHECK:             scf.for {{.*}} iter_args
// CHECK:             memref.atomic_rmw mins %{{.*}}, %[[ECLOCK]][%c4]
// CHECK-NEXT:        %[[NOW:.*]] = memref.atomic_rmw addi %c0_i64, %[[ECLOCK]][%c4]
// CHECK-NEXT:        %[[FOUND:.*]] = arith.cmpi eq, %[[NOW]], %c1_i64 : i64
// CHECK-NEXT:        scf.if %[[FOUND]] {
// CHECK-NEXT:          %[[BASE64:.*]] = arith.index_cast %[[BASE]] : index to i64
// CHECK-NEXT:          memref.atomic_rmw assign %[[BASE64]], %[[ECLOCK]][%c7]
// CHECK-NEXT:        }
// CHECK-NEXT:      }
// CHECK-NEXT:    }
// CHECK-LABEL: func.func @substep_Follow(
// CHECK-SAME:      %[[CLOCK:[^:]*]]: memref<?xi64>, %[[X:[^:]*]]: memref<?xf32>, %[[Y:[^:]*]]: memref<?xf32>, %[[RANGE:[^:]*]]: i64, %[[FIRST:[^:]*]]: i64, %[[END:[^:]*]]: i64, %[[GROUP:[^:]*]]: i64) attributes {simplan.clock_slots = 15 : i64, simplan.group_arguments = 3 : i64, simplan.shared = array<i64: 0, 0>}
// CHECK:         %[[G:.*]] = arith.index_cast %[[GROUP]] : i64 to index
//                One register per lane of the group.
// CHECK:         %[[OWN:.*]] = memref.alloca(%[[G]]) : memref<?xf32>
// CHECK:         %[[STEPS:.*]] = memref.alloca(%[[G]]) : memref<?xi32>
//                m = 1: one evaluation per item as evaluate_C does it, own
//                state from its half, straight into the target.
// CHECK:         %[[SINGLE:.*]] = arith.cmpi eq, %{{.*}}, %c1_i64 : i64
// CHECK-NEXT:    scf.if %[[SINGLE]] {
// CHECK:           scf.for %{{.*}} = %{{.*}} to %{{.*}} step %c1 {
// CHECK:             scf.for %{{.*}} = %c0 to %[[G]] step %c1 {
// CHECK-NOT:           %[[OWN]]
// CHECK:               memref.load %[[Y]]
// CHECK-NOT:           %[[OWN]]
// CHECK:               memref.store %{{.*}}, %[[Y]]
// CHECK:             } {simplan.lanes}
// CHECK:         } else {
//                Otherwise each group sub-steps in registers.
// CHECK:         scf.for %[[GI:.*]] = %{{.*}} to %{{.*}} step %c1 {
// CHECK:           %[[BASE:.*]] = arith.muli %[[GI]], %[[G]]
// CHECK:           scf.for %[[LANE:.*]] = %c0 to %[[G]] step %c1 {
// CHECK:             memref.load %[[Y]]
// CHECK:             memref.store %{{.*}}, %[[OWN]][%[[LANE]]]
// CHECK:           scf.while
//                    Estimates of every lane, then their minimum.
// CHECK:             scf.for %[[L2:.*]] = %c0 to %[[G]] step %c1 {
// CHECK:               memref.store %{{.*}}, %[[STEPS]][%[[L2]]]
// CHECK:             scf.for %{{.*}} = %c0 to %[[G]] step %c1 iter_args(%{{.*}} = %c2147483647_i32) -> (i32) {
// CHECK:               memref.load %[[STEPS]]
// CHECK:               arith.minsi
// CHECK:             scf.for %[[L3:.*]] = %c0 to %[[G]] step %c1 {
// CHECK:               memref.load %[[OWN]][%[[L3]]]
// CHECK:               memref.store %{{.*}}, %[[OWN]][%[[L3]]]
// CHECK:           scf.for %[[L4:.*]] = %c0 to %[[G]] step %c1 {
// CHECK:             memref.load %[[OWN]][%[[L4]]]
// CHECK:             memref.store %{{.*}}, %[[Y]]
//                Evaluations counted with one atomic per call.
// CHECK:         memref.atomic_rmw addi %{{.*}}, %[[CLOCK]][%c9]
// CHECK-LABEL: simplan.plan @pair strategy("hip") kernels(@pair_kernels)
