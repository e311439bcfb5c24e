// RUN: sim-opt %s --sim-front-end=strategy=simple --sim-lower-to-gpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=simple --sim-lower-to-cpu | FileCheck %s --check-prefix=CPU

// Scene symbols may hold any character; kernel names hold letters, digits
// and '_' only (PTX entries and the CPU objects' exports), the others
// replaced by '_', and a suffix keeps them unique. Both targets name the
// kernels alike, so they make the same plan.
sim.simulation @names range(8) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @"X 0" : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X_0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 2.0 : f32
    sim.yield %c : f32
  }
  sim.component @"a-b" writes(@"X 0") evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @"X 0"[%i] : f32
    sim.yield %x : f32
  }
  sim.component @"a.b" writes(@X_0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X_0[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@"a-b", @"a.b"]
  sim.observe [@"X 0", @X_0]
}

// CHECK-LABEL: gpu.module @names_kernels
// CHECK:         gpu.func @init_X_0(
// CHECK:         gpu.func @init_X_0_1(
// CHECK:         gpu.func @evaluate_a_b(
// CHECK:         gpu.func @evaluate_a_b_1(
// CHECK-LABEL: simplan.plan @names
// CHECK:         simplan.launch @names_kernels::@init_X_0 items [#simplan.arg<buffer @"X 0">, #simplan.arg<range>]
// CHECK-NEXT:    simplan.launch @names_kernels::@init_X_0_1 items [#simplan.arg<buffer @X_0>, #simplan.arg<range>]
// CHECK:         simplan.launch @names_kernels::@evaluate_a_b items {{.*}} for @"a-b"
// CHECK-NEXT:    simplan.launch @names_kernels::@evaluate_a_b_1 items {{.*}} for @a.b

// CPU-LABEL: module @names_kernels
// CPU:         func.func @init_X_0(
// CPU:         func.func @init_X_0_1(
// CPU:         func.func @evaluate_a_b(
// CPU:         func.func @evaluate_a_b_1(
