// RUN: sim-opt %s --split-input-file --sim-report-memory --verify-diagnostics -o /dev/null
// RUN: not sim-opt %s --sim-report-memory=group-size=0 -o /dev/null 2>&1 | FileCheck %s --check-prefix=GROUP
// RUN: not sim-opt %examples/paper/fig5.mlir --sim-front-end=strategy=hip-cache --sim-report-memory=group-size=9223372036854775807 -o /dev/null 2>&1 | FileCheck %s --check-prefix=CACHE

// Byte counts past 2^63 - 1 are an error, never a wrapped negative number.
// CACHE: error: 'sim.simulation' op needs more than 9223372036854775807 bytes for the shared-memory caches of @C2 (group-size 9223372036854775807); the memory report cannot count them

// GROUP: sim-report-memory-invalid.mlir:{{[1-9][0-9]*}}:1: error: --sim-report-memory needs a positive group-size, but got 0

// expected-error @+1 {{'sim.simulation' op has no memory plan; run --sim-plan-memory before --sim-report-memory}}
sim.simulation @unplanned range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}

