// Kernel names from symbols that are not identifiers: every kernel name is
// `<family>_<symbol>` with the symbol escaped into letters, digits and `_`
// (KernelNames.h), so that it is a PTX `.entry` and, as `sim_cpu_<kernel>`,
// a C function. Ordinary symbols keep their names (@G, @C0, @a_b); other
// bytes become `__` and two hex digits, an `_` before one of them too; the
// escaped @"a b" and @a_b stay apart; names longer than 128 characters are
// cut and end in a hash of the whole name; and a name that another kernel
// already has (`substep_` + @estimate_G, `substep_estimate_` + @G) gets a
// suffix. The plan keeps the symbols as written.
// test/Conversion/SimToCPU/symbol-names.test, test/Target/PTX/symbol-names.test
// and test/Target/Bundle/symbol-names.test lower this scene too.
//
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu 2>/dev/null | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=simple --sim-lower-to-gpu 2>/dev/null | FileCheck %s --check-prefix=SIMPLE

sim.simulation @"rod 2" range(100) dt(1.0e-2 : f32) max_steps(3) {
  sim.param @"k-1" = 2.0 : f32
  sim.buffer @"B 4" : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @"a b" : f32 init {
  ^bb0(%i: index):
    %b = sim.read @"B 4"[%i] : f32
    sim.yield %b : f32
  }
  sim.buffer @a_b : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @"4.x$" : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @"Δx" : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @"a__b" : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @Loooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooong : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @LoooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooonG : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  // Reads its own buffer at a neighbour: grid-wide rounds under hip.
  sim.component @G writes(@"B 4") num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %left = sim.read @"B 4"[%l] : f32
    %u = sim.read @"B 4"[%i] : f32
    %s = arith.addf %left, %u : f32
    sim.yield %s : f32
  }
  sim.component @estimate_G writes(@"a b") num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %b = sim.read @"B 4"[%i] : f32
    %k = sim.get_param @"k-1" : f32
    %s = arith.mulf %b, %k : f32
    sim.yield %s : f32
  }
  sim.component @C0 writes(@a_b, @"4.x$", @"Δx", @"a__b", @Loooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooong, @LoooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooonG) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @"a b"[%i] : f32
    %b = sim.read @a_b[%i] : f32
    %c = sim.read @"4.x$"[%i] : f32
    %d = sim.read @"Δx"[%i] : f32
    %e = sim.read @"a__b"[%i] : f32
    %f = sim.read @Loooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooong[%i] : f32
    %g = sim.read @LoooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooonG[%i] : f32
    %s = arith.addf %a, %b : f32
    sim.yield %s, %c, %d, %e, %f, %g : f32, f32, f32, f32, f32, f32
  }
  sim.total @"E-total" : f64 {
  ^bb0(%i: index):
    %x = sim.read @a_b[%i] : f32
    %y = arith.extf %x : f32 to f64
    sim.yield %y : f64
  }
  sim.schedule [@G]
  sim.observe [@"a b", @a_b, @"4.x$", @"Δx", @"a__b", @Loooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooong, @LoooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooooonG]
}

// CHECK-LABEL: gpu.module @"rod 2_kernels"
// CHECK:         gpu.func @reset_clock(
// CHECK:         gpu.func @init_B__204(
// CHECK:         gpu.func @init_a__20b(
// CHECK:         gpu.func @init_a_b(
// CHECK:         gpu.func @init_4__2ex__24(
// CHECK:         gpu.func @init___ce__94x(
// CHECK:         gpu.func @init_a__5f_b(
// CHECK:         gpu.func @init_L{{o+}}_77879ce4655d8e5a(
// CHECK:         gpu.func @init_L{{o+}}_986332a65a8b87eb(
// CHECK:         gpu.func @advance(
// CHECK:         gpu.func @snapshot_B__204(
// CHECK:         gpu.func @substep_estimate_G(
// CHECK:         gpu.func @substep_advance_G(
// CHECK:         gpu.func @substep_G(
// CHECK:         gpu.func @parity_G(
// CHECK:         gpu.func @substep_estimate_G_1(
// CHECK:         gpu.func @evaluate_C0(
// CHECK:         gpu.func @exact_4__2ex__24(
// CHECK:         gpu.func @total_E__2dtotal(

// The plan names the kernels by their escaped names and the buffers by
// their symbols.
// CHECK-LABEL: simplan.plan @"rod 2" strategy("hip") kernels(@"rod 2_kernels")
// CHECK:         simplan.launch @"rod 2_kernels"::@init_B__204 items [#simplan.arg<buffer @"B 4">, #simplan.arg<range>]
// CHECK:         simplan.launch @"rod 2_kernels"::@init_a__20b items [#simplan.arg<buffer @"a b">, #simplan.arg<range>]
// CHECK:         simplan.launch @"rod 2_kernels"::@init_a_b items [#simplan.arg<buffer @a_b>, #simplan.arg<range>]
// CHECK:         simplan.launch @"rod 2_kernels"::@substep_G items [#simplan.arg<clock>, #simplan.arg<buffer @"B 4">, #simplan.arg<range>] for @G
// CHECK:         simplan.launch @"rod 2_kernels"::@substep_estimate_G_1 items [{{.*}}#simplan.arg<param @"k-1">{{.*}}] for @estimate_G
// CHECK:         simplan.launch @"rod 2_kernels"::@total_E__2dtotal items [{{.*}}#simplan.arg<total @"E-total">

// SIMPLE-LABEL: gpu.module @"rod 2_kernels"
// SIMPLE:         gpu.func @evaluate_G(
// SIMPLE:         gpu.func @evaluate_estimate_G(
// SIMPLE:         gpu.func @evaluate_C0(
// SIMPLE-LABEL: simplan.plan @"rod 2" strategy("simple")
// SIMPLE:         simplan.launch @"rod 2_kernels"::@evaluate_estimate_G items
