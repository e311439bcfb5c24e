// Lowering needs the whole front end: after the memory plan but before
// interpolation insertion, component bodies still hold view reads.
//
// RUN: sim-opt %s --verify-diagnostics --sim-schedule --sim-substep-legality --sim-plan-memory --sim-lower-to-gpu
// RUN: not sim-opt %s --sim-front-end --sim-lower-to-gpu=group-size=100 2>&1 | FileCheck %s --check-prefix=GROUP
// RUN: not sim-opt %s --sim-front-end --sim-lower-to-gpu=group-size=4294967328 2>&1 | FileCheck %s --check-prefix=HUGE

sim.simulation @midway range(8) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.read' op is a view read; run --sim-insert-interpolation (or the whole front end) before lowering it}}
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}

// HUGE: invalid-pipeline.mlir:8:1: error: --sim-lower-to-gpu needs a group size that is a multiple of 32 (a warp) from 32 to 65536, not 4294967328
// GROUP: invalid-pipeline.mlir:8:1: error: --sim-lower-to-gpu needs a group size that is a multiple of 32 (a warp) from 32 to 65536, not 100
