// A read through the time levels (lts: item i - 1 of a block that may be at
// another sub-step). On the CPU, where a chunk's lanes run side by side, it
// loads the item from both halves at halves every lane shares (wide loads
// whatever the blocks' parities) and selects the latest and the previous
// level per lane; on the GPU a thread loads the half its block's parity
// says, and the previous level only when it interpolates.
//
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-gpu | FileCheck %s --check-prefix=GPU

sim.simulation @rod range(100) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %c50 = arith.constant 50 : i64
    %stiff = arith.cmpi sge, %i64, %c50 : i64
    %c1 = arith.constant 1 : i32
    %c8 = arith.constant 8 : i32
    %n = arith.select %stiff, %c1, %c8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ul = sim.read @U[%il] : f32
    %u0 = sim.read @U[%i] : f32
    %d = arith.subf %ul, %u0 : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %u1 = math.fma %h, %d, %u0 : f32
    sim.yield %u1 : f32
  }
  sim.observe [@U]
}

// The level's time (`slot` rounded up to a multiple of the sub-step) and
// whether the block took an odd number of sub-steps, then the two halves.
// CHECK-LABEL: func.func @local_step_Diffuse(
// CHECK:         arith.xori %{{.*}}, %c-1_i64 : i64
// CHECK-NEXT:    arith.andi
// CHECK-NEXT:    arith.andi
// CHECK-NEXT:    %[[ODD:.*]] = arith.cmpi ne, %{{.*}}, %{{.*}} : i64
// CHECK:         %[[SOURCE:.*]] = memref.load %arg1[%{{.*}}] : memref<?xf32>
// CHECK:         %[[OTHER:.*]] = memref.load %arg1[%{{.*}}] : memref<?xf32>
// CHECK-NEXT:    %[[LATEST:.*]] = arith.select %[[ODD]], %[[OTHER]], %[[SOURCE]] : f32
// CHECK-NEXT:    %[[PREVIOUS:.*]] = arith.select %[[ODD]], %[[SOURCE]], %[[OTHER]] : f32
// CHECK-NEXT:    %[[IN_STEP:.*]] = arith.cmpi eq, %{{.*}}, %{{.*}} : i64
// CHECK-NEXT:    scf.if %[[IN_STEP]] -> (f32) {
// CHECK-NEXT:      scf.yield %[[LATEST]] : f32
// CHECK-NEXT:    } else {
// CHECK-NOT:       memref.load
// CHECK:           %[[FRACTION:.*]] = arith.divf %{{.*}}, %{{.*}} : f32
// CHECK:           arith.mulf %{{.*}}, %[[PREVIOUS]] : f32
// CHECK:           arith.mulf %[[FRACTION]], %[[LATEST]] : f32
// CHECK:       return

// GPU-LABEL: gpu.func @local_step_Diffuse(
// GPU:         arith.xori %{{.*}}, %c-1_i64 : i64
// GPU-NEXT:    arith.andi
// GPU-NEXT:    arith.andi
// GPU-NEXT:    %[[ODD:.*]] = arith.cmpi ne, %{{.*}}, %{{.*}} : i64
// GPU-NEXT:    arith.extui %[[ODD]] : i1 to i64
// GPU:         %[[LATEST:.*]] = memref.load %arg1[%{{.*}}] : memref<?xf32>
// GPU-NEXT:    %[[IN_STEP:.*]] = arith.cmpi eq, %{{.*}}, %{{.*}} : i64
// GPU-NEXT:    scf.if %[[IN_STEP]] -> (f32) {
// GPU-NEXT:      scf.yield %[[LATEST]] : f32
// GPU-NEXT:    } else {
// GPU:           %[[PREVIOUS:.*]] = memref.load %arg1[%{{.*}}] : memref<?xf32>
// GPU:           arith.divf
// GPU:           arith.mulf %{{.*}}, %[[PREVIOUS]] : f32
// GPU:       gpu.return
