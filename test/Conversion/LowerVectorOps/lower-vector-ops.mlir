// RUN: sim-opt %s --sim-lower-vector-ops --split-input-file | FileCheck %s

// High-level vector ops become 1-D ones that the LLVM and NVVM conversions
// lower: a dot product (vector.contract) as a multiplication and a
// reduction, an outer product as vector.fma rows, a multi-reduction as
// vector.reduction, a transpose element by element, vector.step as a
// constant.

// CHECK-LABEL: func.func @dot
// CHECK-NOT: vector.contract
// CHECK: arith.mulf %{{.*}}, %{{.*}} : vector<4xf32>
// CHECK: vector.reduction <add>, %{{.*}}, %{{.*}} : vector<4xf32> into f32
func.func @dot(%a: vector<4xf32>, %b: vector<4xf32>, %acc: f32) -> f32 {
  %r = vector.contract {indexing_maps = [affine_map<(d0) -> (d0)>, affine_map<(d0) -> (d0)>, affine_map<(d0) -> ()>], iterator_types = ["reduction"], kind = #vector.kind<add>} %a, %b, %acc : vector<4xf32>, vector<4xf32> into f32
  return %r : f32
}

// -----

// CHECK-LABEL: func.func @outer
// CHECK-NOT: vector.outerproduct
// CHECK-COUNT-2: arith.mulf %{{.*}}, %{{.*}} : vector<3xf32>
// CHECK: return
func.func @outer(%a: vector<2xf32>, %b: vector<3xf32>) -> vector<2x3xf32> {
  %r = vector.outerproduct %a, %b : vector<2xf32>, vector<3xf32>
  return %r : vector<2x3xf32>
}

// -----

// CHECK-LABEL: func.func @multi_reduction
// CHECK-NOT: vector.multi_reduction
// CHECK: vector.reduction <add>
func.func @multi_reduction(%a: vector<4xf32>, %acc: f32) -> f32 {
  %r = vector.multi_reduction <add>, %a, %acc [0] : vector<4xf32> to f32
  return %r : f32
}

// -----

// CHECK-LABEL: func.func @step
// CHECK-NOT: vector.step
// CHECK: arith.constant dense<[0, 1, 2, 3]> : vector<4xindex>
func.func @step() -> vector<4xindex> {
  %s = vector.step : vector<4xindex>
  return %s : vector<4xindex>
}

// -----

// Over every dimension of a 2-D vector: no strided slice is left.

// CHECK-LABEL: func.func @multi_reduction_2d
// CHECK-NOT: vector.multi_reduction
// CHECK-NOT: strided_slice
// CHECK: vector.reduction <add>
func.func @multi_reduction_2d(%a: vector<2x3xf32>, %acc: f32) -> f32 {
  %r = vector.multi_reduction <add>, %a, %acc [0, 1] : vector<2x3xf32> to f32
  return %r : f32
}

// -----

// fpowi of vectors: LLVM's powi takes one exponent, so one per element.

// CHECK-LABEL: func.func @vector_power
// CHECK-COUNT-3: math.fpowi %{{.*}}, %{{.*}} : f64, i64
// CHECK-NOT: math.fpowi
func.func @vector_power(%b: vector<3xf64>, %e: vector<3xi64>) -> vector<3xf64> {
  %r = math.fpowi %b, %e : vector<3xf64>, vector<3xi64>
  return %r : vector<3xf64>
}

// -----

// Without such an op nothing changes (no folding either).

// CHECK-LABEL: func.func @untouched
// CHECK: %[[C:.*]] = arith.constant 1.000000e+00 : f32
// CHECK: %[[S:.*]] = arith.addf %[[C]], %[[C]] : f32
// CHECK: vector.reduction <add>
func.func @untouched(%a: vector<4xf32>) -> f32 {
  %c = arith.constant 1.0 : f32
  %s = arith.addf %c, %c : f32
  %r = vector.reduction <add>, %a, %s : vector<4xf32> into f32
  return %r : f32
}

// -----

// A shape_cast alone (no other op of the pass in the body) is lowered.
// CHECK-LABEL: func.func @shape_cast_alone
// CHECK-NOT: vector.shape_cast
// CHECK: vector.extract
// CHECK: vector.shuffle
func.func @shape_cast_alone(%a: vector<2x2xf32>) -> vector<4xf32> {
  %r = vector.shape_cast %a : vector<2x2xf32> to vector<4xf32>
  return %r : vector<4xf32>
}

// -----

// A broadcast of a 1-D vector to an n-D one as rows inserted one by one
// (a scalar's the LLVM conversions lower themselves).
// CHECK-LABEL: func.func @broadcast_rows
// CHECK-NOT: vector.broadcast
// CHECK-COUNT-3: vector.insert %{{.*}}, %{{.*}} [{{[0-9]}}] : vector<4xf32> into vector<3x4xf32>
func.func @broadcast_rows(%x: vector<4xf32>) -> vector<3x4xf32> {
  %r = vector.broadcast %x : vector<4xf32> to vector<3x4xf32>
  return %r : vector<3x4xf32>
}

// -----

// A mask made at run time as a comparison of its bound with vector.step.
// CHECK-LABEL: func.func @create_mask
// CHECK-NOT: vector.create_mask
// CHECK: arith.cmpi sgt, %{{.*}}, %{{.*}} : vector<4xi64>
func.func @create_mask(%n: index) -> vector<4xi1> {
  %m = vector.create_mask %n : vector<4xi1>
  return %m : vector<4xi1>
}

// -----

// A scan as additions of slices, in order.
// CHECK-LABEL: func.func @scan
// CHECK-NOT: vector.scan
// CHECK: arith.addf
func.func @scan(%a: vector<4xf32>, %init: vector<f32>) -> vector<4xf32> {
  %s, %acc = vector.scan <add>, %a, %init {inclusive = true, reduction_dim = 0 : i64} : vector<4xf32>, vector<f32>
  return %s : vector<4xf32>
}
