// RUN: sim-opt %s --split-input-file --allow-unregistered-dialect --pass-pipeline='builtin.module(gpu.module(sim-gpu-narrow-loop-counters))' | FileCheck %s

// A scene's load loop: bounded by an i32 parameter, counted in i32; the
// body does not use the counter.
// CHECK-LABEL: func.func @parameter_bound
// CHECK-DAG: %[[ZERO:.*]] = arith.constant 0 : i32
// CHECK-DAG: %[[ONE:.*]] = arith.constant 1 : i32
// CHECK: scf.for %{{.*}} = %[[ZERO]] to %arg0 step %[[ONE]] iter_args(%{{.*}} = %arg1) -> (f32) : i32 {
// CHECK-NOT: arith.index_cast %{{.*}} : i32 to index
// CHECK: arith.mulf
gpu.module @kernels {
  func.func @parameter_bound(%rounds: i32, %x0: f32) -> f32 {
    %c0 = arith.constant 0 : index
    %c1 = arith.constant 1 : index
    %n = arith.index_cast %rounds : i32 to index
    %x = scf.for %k = %c0 to %n step %c1 iter_args(%x1 = %x0) -> (f32) {
      %y = arith.mulf %x1, %x1 : f32
      scf.yield %y : f32
    }
    return %x : f32
  }
}

// -----

// A counter the body uses reaches it as index again; narrower bounds are
// extended (signed from index_cast, unsigned from index_castui).
// CHECK-LABEL: func.func @used_counter
// CHECK-DAG: %[[LOWER:.*]] = arith.extsi %arg0 : i16 to i32
// CHECK-DAG: %[[UPPER:.*]] = arith.extui %arg1 : i8 to i32
// CHECK: scf.for %[[K:.*]] = %[[LOWER]] to %[[UPPER]] step %{{.*}} : i32 {
// CHECK-NEXT: %[[INDEX:.*]] = arith.index_cast %[[K]] : i32 to index
// CHECK-NEXT: memref.store %{{.*}}, %arg2[%[[INDEX]]]
gpu.module @kernels {
  func.func @used_counter(%lower: i16, %upper: i8, %out: memref<?xf32>) {
    %c2 = arith.constant 2 : index
    %zero = arith.constant 0.0 : f32
    %lb = arith.index_cast %lower : i16 to index
    %ub = arith.index_castui %upper : i8 to index
    scf.for %k = %lb to %ub step %c2 {
      memref.store %zero, %out[%k] : memref<?xf32>
    }
    return
  }
}

// -----

// Bounds that may not fit, or whose last increment could wrap, keep index:
// a 64-bit bound, an unsigned 32-bit bound, an upper bound of 2^31 - 1 with
// a step of 2, an unknown step and an unsigned comparison.
// CHECK-LABEL: func.func @kept_wide
// CHECK: scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} {
// CHECK: scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} {
// CHECK: scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} {
// CHECK: scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} {
// CHECK: scf.for unsigned %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} {
// CHECK-NOT: : i32 {
gpu.module @kernels {
  func.func @kept_wide(%wide: i64, %unsigned: i32, %step: index) {
    %c0 = arith.constant 0 : index
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %largest = arith.constant 2147483647 : index
    %n64 = arith.index_cast %wide : i64 to index
    %nu = arith.index_castui %unsigned : i32 to index
    scf.for %k = %c0 to %n64 step %c1 {
      "test.use"(%k) : (index) -> ()
    }
    scf.for %k = %c0 to %nu step %c1 {
      "test.use"(%k) : (index) -> ()
    }
    scf.for %k = %c0 to %largest step %c2 {
      "test.use"(%k) : (index) -> ()
    }
    scf.for %k = %c0 to %c2 step %step {
      "test.use"(%k) : (index) -> ()
    }
    scf.for unsigned %k = %c0 to %c2 step %c1 {
      "test.use"(%k) : (index) -> ()
    }
    return
  }
}

// -----

// The largest bound whose increment cannot wrap: 2^31 - 1 with a step of 1.
// CHECK-LABEL: func.func @largest_bound
// CHECK: %[[LARGEST:.*]] = arith.constant 2147483647 : i32
// CHECK: scf.for %{{.*}} = %arg0 to %[[LARGEST]] step %{{.*}} : i32 {
gpu.module @kernels {
  func.func @largest_bound(%first: i32) {
    %c1 = arith.constant 1 : index
    %lb = arith.index_cast %first : i32 to index
    %largest = arith.constant 2147483647 : index
    scf.for %k = %lb to %largest step %c1 {
      "test.use"(%k) : (index) -> ()
    }
    return
  }
}

// -----

// A constant trip count (a window loop, which LLVM unrolls completely) keeps
// index.
// CHECK-LABEL: func.func @window
// CHECK: scf.for %{{.*}} = %c-4 to %c5 step %c1 {
gpu.module @kernels {
  func.func @window() {
    %c-4 = arith.constant -4 : index
    %c1 = arith.constant 1 : index
    %c5 = arith.constant 5 : index
    scf.for %k = %c-4 to %c5 step %c1 {
      "test.use"(%k) : (index) -> ()
    }
    return
  }
}
