// The loop passes of the GPU pipeline change how loops count, never what
// they compute: the same results, run on the CPU, for empty, reversed, odd
// and even trip counts and for counters at both ends of i32.
//
// RUN: sim-opt %s | mlir-opt --convert-scf-to-cf --convert-vector-to-llvm --convert-to-llvm --reconcile-unrealized-casts | mlir-runner -e main -entry-point-result=void -shared-libs=%mlir_lib_dir/libmlir_c_runner_utils.so | FileCheck %s
// RUN: sim-opt %s --sim-gpu-narrow-loop-counters | mlir-opt --convert-scf-to-cf --convert-vector-to-llvm --convert-to-llvm --reconcile-unrealized-casts | mlir-runner -e main -entry-point-result=void -shared-libs=%mlir_lib_dir/libmlir_c_runner_utils.so | FileCheck %s
// RUN: sim-opt %s --sim-gpu-narrow-loop-counters --sim-gpu-unroll-loops | mlir-opt --convert-scf-to-cf --convert-vector-to-llvm --convert-to-llvm --reconcile-unrealized-casts | mlir-runner -e main -entry-point-result=void -shared-libs=%mlir_lib_dir/libmlir_c_runner_utils.so | FileCheck %s
// RUN: sim-opt %s --sim-gpu-narrow-loop-counters --sim-gpu-unroll-loops=factor=3 | mlir-opt --convert-scf-to-cf --convert-vector-to-llvm --convert-to-llvm --reconcile-unrealized-casts | mlir-runner -e main -entry-point-result=void -shared-libs=%mlir_lib_dir/libmlir_c_runner_utils.so | FileCheck %s
// RUN: sim-opt %s --sim-gpu-unroll-loops=factor=4 | mlir-opt --convert-scf-to-cf --convert-vector-to-llvm --convert-to-llvm --reconcile-unrealized-casts | mlir-runner -e main -entry-point-result=void -shared-libs=%mlir_lib_dir/libmlir_c_runner_utils.so | FileCheck %s
//
// The narrowing pass must have narrowed @by_one (checked here so that the
// runs above test a 32-bit counter):
// RUN: sim-opt %s --sim-gpu-narrow-loop-counters | FileCheck %s --check-prefix=NARROW
// NARROW-LABEL: func.func @by_one
// NARROW: scf.for {{.*}} : i32 {

// A fold over the counter that depends on the order of the iterations:
// acc = acc * 3 + k.
func.func @by_one(%lower32: i32, %upper32: i32) -> i64 {
  %lower = arith.index_cast %lower32 : i32 to index
  %upper = arith.index_cast %upper32 : i32 to index
  %c1 = arith.constant 1 : index
  %zero = arith.constant 0 : i64
  %r = scf.for %k = %lower to %upper step %c1 iter_args(%acc = %zero) -> (i64) {
    %k64 = arith.index_cast %k : index to i64
    %c3 = arith.constant 3 : i64
    %m = arith.muli %acc, %c3 : i64
    %s = arith.addi %m, %k64 : i64
    scf.yield %s : i64
  }
  return %r : i64
}

// The same with a step of 3 (kept in index: 2^31 - 1 + 2 would wrap i32).
func.func @by_three(%lower32: i32, %upper32: i32) -> i64 {
  %lower = arith.index_cast %lower32 : i32 to index
  %upper = arith.index_cast %upper32 : i32 to index
  %c3i = arith.constant 3 : index
  %zero = arith.constant 0 : i64
  %r = scf.for %k = %lower to %upper step %c3i iter_args(%acc = %zero) -> (i64) {
    %k64 = arith.index_cast %k : index to i64
    %c3 = arith.constant 3 : i64
    %m = arith.muli %acc, %c3 : i64
    %s = arith.addi %m, %k64 : i64
    scf.yield %s : i64
  }
  return %r : i64
}

func.func @main() {
  %cases = arith.constant dense<[0, 0, 0, 1, 0, 2, 0, 3, 0, 7, 5, 2, -4, 3, 2147483640, 2147483647, -2147483648, -2147483645]> : vector<18xi32>
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c2 = arith.constant 2 : index
  %c18 = arith.constant 18 : index
  scf.for %i = %c0 to %c18 step %c2 {
    %i1 = arith.addi %i, %c1 : index
    %lower = vector.extract %cases[%i] : i32 from vector<18xi32>
    %upper = vector.extract %cases[%i1] : i32 from vector<18xi32>
    %one = func.call @by_one(%lower, %upper) : (i32, i32) -> i64
    %three = func.call @by_three(%lower, %upper) : (i32, i32) -> i64
    vector.print %one : i64
    vector.print %three : i64
  }
  return
}
// Empty, one, two, three and seven iterations; reversed; crossing zero; the
// top and the bottom of i32.
// CHECK: 0
// CHECK-NEXT: 0
// CHECK-NEXT: 0
// CHECK-NEXT: 0
// CHECK-NEXT: 1
// CHECK-NEXT: 0
// CHECK-NEXT: 5
// CHECK-NEXT: 0
// CHECK-NEXT: 543
// CHECK-NEXT: 15
// CHECK-NEXT: 0
// CHECK-NEXT: 0
// CHECK-NEXT: -3829
// CHECK-NEXT: -37
// CHECK-NEXT: 2347199619063
// CHECK-NEXT: 27917287335
// CHECK-NEXT: -27917287419
// CHECK-NEXT: -2147483648
