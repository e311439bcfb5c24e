// A grid_sync component that bounds the hip big step takes the step in one
// evaluation (the front end records `advance = whole_step`), so the plan
// gives it no sub-step clock and no rounds: its clock is the 8 fixed slots,
// one evaluation counter per component and the histogram of sizes 0..3,
// 14 slots (the copies of this decision that the lowering used to keep
// allocated 4 more, never read).
//
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu | FileCheck %s

// CHECK-LABEL: simplan.plan @bounding strategy("hip")
// CHECK-SAME:    max_steps(3) step_cap(3) group_size(256) clock_slots(14) histogram(10)
// CHECK:         simplan.component @Lead writes [@L] evaluations(8) advance whole_step estimates{{$}}
// CHECK-NEXT:    simplan.component @Tail writes [@T] evaluations(9) advance whole_step{{$}}
// CHECK:         simplan.phase step {
// CHECK-NEXT:      simplan.launch @bounding_kernels::@estimate_Lead items
// CHECK-NEXT:      simplan.launch @bounding_kernels::@advance single
// CHECK-NEXT:      simplan.launch @bounding_kernels::@evaluate_Lead items
// CHECK-NEXT:      simplan.launch @bounding_kernels::@evaluate_Tail items
// CHECK-NEXT:    }
// CHECK-NOT:     simplan.repeat

sim.simulation @bounding range(64) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @L : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @T : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // Reads its own buffer at i + 1 (grid_sync) and @T through the back edge.
  sim.component @Lead writes(@L) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %next = sim.read @L[%j] : f32
    %t0 = sim.read @T[%i] : f32
    %s = arith.addf %next, %t0 : f32
    sim.yield %s : f32
  }
  sim.component @Tail writes(@T) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %l = sim.read @L[%i] : f32
    sim.yield %l : f32
  }
  sim.schedule [@Lead]
  sim.observe [@T]
}
