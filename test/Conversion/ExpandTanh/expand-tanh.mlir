// RUN: sim-opt %s --sim-expand-tanh --split-input-file | FileCheck %s

// An f32 tanh becomes fdlibm's arithmetic: the bits of x, expm1f's argument
// reduction by ln2 (hi 0x3f317180 = 0.693138123) and its polynomial, and the
// selects of tanhf's special cases; no libm call is left.
// CHECK-LABEL: func.func @scalar
// CHECK-SAME:      (%[[X:.*]]: f32) -> f32
// CHECK:         %[[BITS:.*]] = arith.bitcast %[[X]] : f32 to i32
// CHECK:         arith.constant 0.693138123 : f32
// CHECK:         arith.fptosi %{{.*}} : f32 to i32
// CHECK:         arith.constant -0.0333333351 : f32
// CHECK:         arith.divf
// CHECK:         arith.select %{{.*}}, %{{.*}}, %{{.*}} : f32
// CHECK:         return %{{.*}} : f32
// CHECK-NOT:     math.tanh
func.func @scalar(%x: f32) -> f32 {
  %y = math.tanh %x : f32
  return %y : f32
}

// -----

// Two divisions per element, no more: expm1f's, and tanhf's by t + 2 with
// the numerator of the lane's path selected first (2 for |x| >= 1, -t
// below). inf needs none (the |x| >= 22 path gives +-1), and a NaN comes
// back as x + x, the NaN glibc's 1/x +- 1 returns.
// CHECK-LABEL: func.func @divisions
// CHECK-SAME:      (%[[X:.*]]: f32) -> f32
// CHECK-COUNT-2: arith.divf
// CHECK-NOT:     arith.divf
// CHECK:         %[[TWICE:.*]] = arith.addf %[[X]], %[[X]] : f32
// CHECK-NEXT:    %[[NAN:.*]] = arith.select %{{.*}}, %[[TWICE]], %{{.*}} : f32
// CHECK-NEXT:    return %[[NAN]] : f32
func.func @divisions(%x: f32) -> f32 {
  %y = math.tanh %x : f32
  return %y : f32
}

// -----

// Vectors of f32 (the lanes of --sim-vectorize-lanes) in the same shape,
// with i32 vectors for the bits.
// CHECK-LABEL: func.func @lanes
// CHECK:         arith.bitcast %{{.*}} : vector<16xf32> to vector<16xi32>
// CHECK:         arith.fptosi %{{.*}} : vector<16xf32> to vector<16xi32>
// CHECK:         arith.select %{{.*}}, %{{.*}}, %{{.*}} : vector<16xi1>, vector<16xf32>
// CHECK-NOT:     math.tanh
func.func @lanes(%x: vector<16xf32>) -> vector<16xf32> {
  %y = math.tanh %x : vector<16xf32>
  return %y : vector<16xf32>
}

// -----

// f64 stays libm's.
// CHECK-LABEL: func.func @double
// CHECK-NEXT:    math.tanh %{{.*}} : f64
func.func @double(%x: f64) -> f64 {
  %y = math.tanh %x : f64
  return %y : f64
}
