// RUN: sim-opt %s --sim-fused-multiply-add --split-input-file | FileCheck %s

// A one-dimensional vector.fma becomes the intrinsic on the same type.
// CHECK-LABEL: func.func @vector_fma
// CHECK-SAME: (%[[A:.*]]: vector<4xf32>, %[[B:.*]]: vector<4xf32>, %[[C:.*]]: vector<4xf32>)
// CHECK-NEXT: %[[R:.*]] = llvm.intr.fma(%[[A]], %[[B]], %[[C]]) : (vector<4xf32>, vector<4xf32>, vector<4xf32>) -> vector<4xf32>
// CHECK-NEXT: return %[[R]]
// CHECK-NOT: vector.fma
func.func @vector_fma(%a: vector<4xf32>, %b: vector<4xf32>, %c: vector<4xf32>) -> vector<4xf32> {
  %r = vector.fma %a, %b, %c : vector<4xf32>
  return %r : vector<4xf32>
}

// -----

// f64 vectors too.
// CHECK-LABEL: func.func @vector_fma_f64
// CHECK: llvm.intr.fma({{.*}}) : (vector<3xf64>, vector<3xf64>, vector<3xf64>) -> vector<3xf64>
// CHECK-NOT: vector.fma
func.func @vector_fma_f64(%a: vector<3xf64>, %b: vector<3xf64>, %c: vector<3xf64>) -> vector<3xf64> {
  %r = vector.fma %a, %b, %c : vector<3xf64>
  return %r : vector<3xf64>
}

// -----

// An n-D fma is split into 1-D rows first, each fused.
// CHECK-LABEL: func.func @vector_fma_2d
// CHECK-COUNT-2: llvm.intr.fma({{.*}}) : (vector<4xf32>, vector<4xf32>, vector<4xf32>) -> vector<4xf32>
// CHECK-NOT: vector.fma
func.func @vector_fma_2d(%a: vector<2x4xf32>, %b: vector<2x4xf32>, %c: vector<2x4xf32>) -> vector<2x4xf32> {
  %r = vector.fma %a, %b, %c : vector<2x4xf32>
  return %r : vector<2x4xf32>
}

// -----

// math.fma already lowers to llvm.intr.fma; the pass leaves it, and every
// other op, as it is (no folding: the constant stays).
// CHECK-LABEL: func.func @math_fma_untouched
// CHECK-NEXT: arith.constant 1.000000e+00 : f32
// CHECK-NEXT: math.fma
// CHECK-NEXT: arith.addf
func.func @math_fma_untouched(%a: f32, %b: f32) -> f32 {
  %one = arith.constant 1.0 : f32
  %r = math.fma %a, %b, %one : f32
  %s = arith.addf %r, %one : f32
  return %s : f32
}
