// A read through the time levels of a #sim.hermite buffer whose derivative
// the same component writes (lts, docs/Model.md "What a read returns"):
// where the neighbour is ahead in time, the derivative's two levels are
// loaded at the same item and parity as the buffer's, and the Hermite
// cubic weighs the previous and the latest of both. On the CPU both halves
// with a select per lane, as for the buffer (local-steps-level-reads.mlir);
// on the GPU the half the block's parity says and the other one.
//
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-gpu | FileCheck %s --check-prefix=GPU

sim.simulation @chain range(100) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @X : f32 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @Chain writes(@X, @V) num_steps {
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
    %xl = sim.read @X[%il] : f32
    %x0 = sim.read @X[%i] : f32
    %v0 = sim.read @V[%i] : f32
    %d = arith.subf %xl, %x0 : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %v1 = math.fma %h, %d, %v0 : f32
    %x1 = math.fma %h, %v1, %x0 : f32
    sim.yield %x1, %v1 : f32, f32
  }
  sim.observe [@X]
}

// CHECK-LABEL: func.func @local_step_Chain(
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
// CHECK:           arith.divf %{{.*}}, %{{.*}} : f32
// CHECK-NEXT:      %[[SPAN:.*]] = arith.mulf %{{.*}}, %arg5 : f32
// CHECK:           %[[DSOURCE:.*]] = memref.load %arg2[%{{.*}}] : memref<?xf32>
// CHECK:           %[[DOTHER:.*]] = memref.load %arg2[%{{.*}}] : memref<?xf32>
// CHECK-NEXT:      %[[DLATEST:.*]] = arith.select %[[ODD]], %[[DOTHER]], %[[DSOURCE]] : f32
// CHECK-NEXT:      %[[DPREVIOUS:.*]] = arith.select %[[ODD]], %[[DSOURCE]], %[[DOTHER]] : f32
// CHECK:           %[[H10H:.*]] = arith.mulf %{{.*}}, %[[SPAN]] : f32
// CHECK-NEXT:      %[[H11H:.*]] = arith.mulf %{{.*}}, %[[SPAN]] : f32
// CHECK-NEXT:      arith.mulf %{{.*}}, %[[PREVIOUS]] : f32
// CHECK-NEXT:      arith.mulf %[[H10H]], %[[DPREVIOUS]] : f32
// CHECK:           arith.mulf %{{.*}}, %[[LATEST]] : f32
// CHECK:           arith.mulf %[[H11H]], %[[DLATEST]] : f32
// CHECK:       return

// GPU-LABEL: gpu.func @local_step_Chain(
// GPU:         arith.xori %{{.*}}, %c-1_i64 : i64
// GPU-NEXT:    arith.andi
// GPU-NEXT:    arith.andi
// GPU-NEXT:    arith.cmpi ne, %{{.*}}, %{{.*}} : i64
// GPU-NEXT:    arith.extui
// GPU-NEXT:    %[[PARITY:.*]] = arith.xori %{{.*}}, %{{.*}} : i64
// GPU:         %[[LATEST:.*]] = memref.load %arg1[%{{.*}}] : memref<?xf32>
// GPU-NEXT:    %[[IN_STEP:.*]] = arith.cmpi eq, %{{.*}}, %{{.*}} : i64
// GPU-NEXT:    scf.if %[[IN_STEP]] -> (f32) {
// GPU-NEXT:      scf.yield %[[LATEST]] : f32
// GPU-NEXT:    } else {
// GPU-NEXT:      arith.xori %[[PARITY]], %{{.*}} : i64
// GPU:           %[[PREVIOUS:.*]] = memref.load %arg1[%{{.*}}] : memref<?xf32>
// GPU:           %[[SPAN:.*]] = arith.mulf %{{.*}}, %arg5 : f32
// GPU-NEXT:      arith.index_cast %[[PARITY]] : i64 to index
// GPU:           %[[DLATEST:.*]] = memref.load %arg2[%{{.*}}] : memref<?xf32>
// GPU-NEXT:      arith.xori %[[PARITY]], %{{.*}} : i64
// GPU:           %[[DPREVIOUS:.*]] = memref.load %arg2[%{{.*}}] : memref<?xf32>
// GPU:           arith.mulf %{{.*}}, %[[PREVIOUS]] : f32
// GPU-NEXT:      arith.mulf %{{.*}}, %[[DPREVIOUS]] : f32
// GPU:           arith.mulf %{{.*}}, %[[LATEST]] : f32
// GPU:           arith.mulf %{{.*}}, %[[DLATEST]] : f32
// GPU:       gpu.return
