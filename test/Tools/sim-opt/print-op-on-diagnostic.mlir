// sim-opt defaults --mlir-print-op-on-diagnostic to false: a pass error names
// the operation and its location, and notes point at what matters, without a
// dump of the whole simulation. A user can still ask for the dump.
//
// RUN: not sim-opt %s --sim-insert-interpolation 2>&1 | FileCheck %s --implicit-check-not="see current operation"
// RUN: not sim-opt %s --sim-front-end --sim-plan-memory 2>&1 | FileCheck %s --check-prefix=NOTE --implicit-check-not="see current operation"
// RUN: not sim-opt %s --sim-insert-interpolation --mlir-print-op-on-diagnostic 2>&1 | FileCheck %s --check-prefix=DUMP
// RUN: not sim-opt %s --sim-insert-interpolation --mlir-print-op-on-diagnostic=false 2>&1 | FileCheck %s --implicit-check-not="see current operation"

// CHECK: error: 'sim.simulation' op has no memory plan; run --sim-plan-memory before --sim-insert-interpolation
// CHECK-NEXT: sim.simulation @s
// CHECK-NEXT: ^

// NOTE: error: 'sim.simulation' op has explicit loads, so its memory plan is fixed; run --sim-plan-memory before --sim-insert-interpolation
// NOTE: note: the first explicit access is this 'sim.load'

// DUMP: error: 'sim.simulation' op has no memory plan
// DUMP: note: see current operation:
// DUMP-NEXT: "sim.simulation"()

sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(2) {
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
