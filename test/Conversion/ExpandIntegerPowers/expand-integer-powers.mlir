// RUN: sim-opt %s --sim-expand-integer-powers --split-input-file | FileCheck %s

// math.ipowi becomes exponentiation by squaring over every bit of the
// exponent (32 rounds for i32), each round's product selected in or not;
// a negative exponent selects 1, +-1 or 0 by the base.

// CHECK-LABEL: func.func @scalar
// CHECK-NOT: math.ipowi
// CHECK-COUNT-32: arith.shrui %arg1
// CHECK: %[[NEGATIVE:.*]] = arith.cmpi slt, %arg1
// CHECK: arith.cmpi eq, %arg0
// CHECK: arith.cmpi eq, %arg0
// CHECK: %[[R:.*]] = arith.select %[[NEGATIVE]],
// CHECK-NEXT: return %[[R]] : i32
func.func @scalar(%b: i32, %p: i32) -> i32 {
  %r = math.ipowi %b, %p : i32
  return %r : i32
}

// -----

// Vectors of i64: the same rounds on whole vectors, 64 of them.

// CHECK-LABEL: func.func @vector
// CHECK-NOT: math.ipowi
// CHECK: arith.constant dense<1> : vector<4xi64>
// CHECK-COUNT-64: arith.shrui %arg1, %{{.*}} : vector<4xi64>
// CHECK: arith.select %{{.*}} : vector<4xi1>, vector<4xi64>
// CHECK: return
func.func @vector(%b: vector<4xi64>, %p: vector<4xi64>) -> vector<4xi64> {
  %r = math.ipowi %b, %p : vector<4xi64>
  return %r : vector<4xi64>
}

// -----

// Other math ops stay as they are.

// CHECK-LABEL: func.func @others
// CHECK: math.fpowi
// CHECK: math.powf
func.func @others(%x: f32, %n: i32) -> f32 {
  %a = math.fpowi %x, %n : f32, i32
  %b = math.powf %a, %x : f32
  return %b : f32
}
