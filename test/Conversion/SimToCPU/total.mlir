// The CPU lowering of a total: the same kernel and plan as the GPU's (the
// plan text of both is identical), with a group as a loop iteration.
//
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-cpu | FileCheck %s --implicit-check-not=gpu.
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-cpu > %t.cpu
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu > %t.gpu
// RUN: grep "^ *simplan[.]" %t.cpu > %t.cpu.plan
// RUN: grep "^ *simplan[.]" %t.gpu > %t.gpu.plan
// RUN: diff %t.cpu.plan %t.gpu.plan

sim.simulation @spin range(32) dt(1.0e-2 : f64) max_steps(2) {
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f64
    sim.yield %one : f64
  }
  sim.component @Damp writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %v = sim.read @V[%i] : f64
    %k = arith.constant 0.5 : f64
    %w = arith.mulf %k, %v : f64
    sim.yield %w : f64
  }
  sim.total @Momentum : f64 {
  ^bb0(%i: index):
    %v = sim.read @V[%i] : f64
    sim.yield %v : f64
  }
  sim.observe [@V]
}

// CHECK-LABEL: func.func @total_Momentum(
// CHECK-SAME:      %[[CLOCK:[^:]*]]: memref<?xi64>, %[[V:[^:]*]]: memref<?xf64>, %[[OUT:[^:]*]]: memref<?xf64>, %{{[^:]*}}: i64,
// CHECK:         memref.load %[[CLOCK]]
// CHECK:         scf.for
// CHECK:           %[[VALUE:.*]] = memref.load %[[V]][%{{.*}}] : memref<?xf64>
// CHECK:           memref.store %[[VALUE]], %[[OUT]][%{{.*}}] : memref<?xf64>

// CHECK-LABEL: simplan.plan @spin
// CHECK:         simplan.total @Momentum : f64
// CHECK:         simplan.phase total {
// CHECK-NEXT:      simplan.launch @spin_kernels::@total_Momentum items [#simplan.arg<clock>, #simplan.arg<buffer @V>, #simplan.arg<total @Momentum>, #simplan.arg<range>]
