// RUN: sim-opt %s --split-input-file --allow-unregistered-dialect --pass-pipeline='builtin.module(gpu.module(sim-gpu-unroll-loops))' | FileCheck %s
// RUN: sim-opt %s --split-input-file --allow-unregistered-dialect --pass-pipeline='builtin.module(gpu.module(sim-gpu-unroll-loops{factor=1}))' | FileCheck %s --check-prefix=OFF

// A load loop of unknown trip count (32-bit counter): the trip count in 64
// bits, a main loop of two bodies per iteration (the second at counter + 1,
// carrying the first's results), then the original loop for the rest.
// CHECK-LABEL: func.func @load_loop
// CHECK-DAG: %[[LOWER:.*]] = arith.extsi %arg0 : i32 to i64
// CHECK-DAG: %[[UPPER:.*]] = arith.extsi %arg1 : i32 to i64
// CHECK: %[[TRIPS:.*]] = arith.subi %[[UPPER]], %[[LOWER]] : i64
// CHECK: %[[REST:.*]] = arith.remsi %[[TRIPS]], %{{.*}} : i64
// CHECK: %[[SPAN:.*]] = arith.subi %[[TRIPS]], %[[REST]] : i64
// CHECK: %[[END64:.*]] = arith.addi %[[LOWER]], %[[SPAN]] : i64
// CHECK: %[[ANY:.*]] = arith.cmpi sgt, %[[TRIPS]], %{{.*}} : i64
// CHECK: %[[CLAMPED:.*]] = arith.select %[[ANY]], %[[END64]], %[[LOWER]] : i64
// CHECK: %[[END:.*]] = arith.trunci %[[CLAMPED]] : i64 to i32
// CHECK: %[[TWO:.*]] = arith.constant 2 : i32
// CHECK: %[[MAIN:.*]] = scf.for %[[K:.*]] = %arg0 to %[[END]] step %[[TWO]] iter_args(%[[X:.*]] = %arg2) -> (f32) : i32 {
// CHECK:   %[[Y0:.*]] = "test.round"(%[[X]], %[[K]]) : (f32, i32) -> f32
// CHECK:   %[[K1:.*]] = arith.addi %[[K]], %{{.*}} : i32
// CHECK:   %[[Y1:.*]] = "test.round"(%[[Y0]], %[[K1]]) : (f32, i32) -> f32
// CHECK:   scf.yield %[[Y1]] : f32
// CHECK: }
// CHECK: %[[REST_LOOP:.*]] = scf.for %{{.*}} = %[[END]] to %arg1 step %{{.*}} iter_args(%{{.*}} = %[[MAIN]]) -> (f32) : i32 {
// CHECK:   "test.round"
// CHECK: return %[[REST_LOOP]] : f32
// OFF-LABEL: func.func @load_loop
// OFF-COUNT-1: scf.for
// OFF-NOT: scf.for
// OFF: return
gpu.module @kernels {
  func.func @load_loop(%lower: i32, %upper: i32, %x0: f32) -> f32 {
    %c1 = arith.constant 1 : i32
    %x = scf.for %k = %lower to %upper step %c1 iter_args(%x1 = %x0) -> (f32) : i32 {
      %y = "test.round"(%x1, %k) : (f32, i32) -> f32
      scf.yield %y : f32
    }
    return %x : f32
  }
}

// -----

// An index counter with a step of 3: the trip count rounded up, in index.
// CHECK-LABEL: func.func @index_step
// CHECK: %[[SPAN:.*]] = arith.subi %arg1, %arg0 : index
// CHECK: %[[UP:.*]] = arith.addi %[[SPAN]], %{{.*}} : index
// CHECK: %[[TRIPS:.*]] = arith.divsi %[[UP]], %{{.*}} : index
// CHECK: scf.for %{{.*}} = %arg0 to %{{.*}} step %{{.*}} {
// CHECK-COUNT-2: "test.use"
// CHECK: }
// CHECK: scf.for %{{.*}} = %{{.*}} to %arg1 step %{{.*}} {
// CHECK-NEXT: "test.use"
gpu.module @kernels {
  func.func @index_step(%lower: index, %upper: index) {
    %c3 = arith.constant 3 : index
    scf.for %k = %lower to %upper step %c3 {
      "test.use"(%k) : (index) -> ()
    }
    return
  }
}

// -----

// Left alone: a constant trip count (LLVM unrolls it), an outer loop (only
// its inner loop is unrolled), an unknown step and an unsigned comparison.
// CHECK-LABEL: func.func @left_alone
// CHECK: scf.for %{{.*}} = %c0 to %c9 step %c1 {
// CHECK-NEXT: "test.use"
// CHECK-NEXT: }
// CHECK: scf.for %{{.*}} = %c0 to %arg0 step %c1 {
// CHECK: scf.for %{{.*}} = %c0 to %{{.*}} step %{{.*}} {
// CHECK-COUNT-2: "test.inner"
// CHECK: scf.for %{{.*}} = %{{.*}} to %arg0 step %c1 {
// CHECK: scf.for %{{.*}} = %c0 to %arg0 step %arg1 {
// CHECK-NEXT: "test.use"
// CHECK: scf.for unsigned %{{.*}} = %c0 to %arg0 step %c1 {
// CHECK-NEXT: "test.use"
gpu.module @kernels {
  func.func @left_alone(%n: index, %step: index) {
    %c0 = arith.constant 0 : index
    %c1 = arith.constant 1 : index
    %c9 = arith.constant 9 : index
    scf.for %k = %c0 to %c9 step %c1 {
      "test.use"(%k) : (index) -> ()
    }
    scf.for %i = %c0 to %n step %c1 {
      scf.for %k = %c0 to %n step %c1 {
        "test.inner"(%i, %k) : (index, index) -> ()
      }
    }
    scf.for %k = %c0 to %n step %step {
      "test.use"(%k) : (index) -> ()
    }
    scf.for unsigned %k = %c0 to %n step %c1 {
      "test.use"(%k) : (index) -> ()
    }
    return
  }
}
