// The lowerings read what the front end recorded and re-derive none of
// it: a record that disagrees with the records it was decided from, or
// with the loads of a body (a hand edit, or one pass rerun after a change),
// is an error at the record, not a silently wrong kernel. Each case is the
// front end's output for one scene (--sim-front-end) with one record edited.
//
// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-lower-to-cpu
// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-lower-to-gpu

// hip: @Smooth reads @B at i-1 and i+1 but is relabelled in_kernel; its
// advance, grid_substeps, no longer follows from the verdict.
sim.simulation @rec range(64) dt(0.00999999977 : f32) max_steps(8) attributes {step_cap = 8 : i32, strategy = #sim<strategy hip>} {
  sim.buffer @A : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %cst = arith.constant 1.000000e+00 : f32
    sim.yield %cst : f32
  }
  sim.buffer @B : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %0 = arith.index_cast %i : index to i64
    %1 = arith.sitofp %0 : i64 to f32
    sim.yield %1 : f32
  }
  sim.component @Drive writes(@A) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = sim.load source @B[%i] : f32
    %1 = arith.fptosi %0 : f32 to i32
    %cst = arith.constant 2.14748365E+9 : f32
    %2 = arith.cmpf oge, %0, %cst : f32
    %cst_0 = arith.constant -2.14748365E+9 : f32
    %3 = arith.cmpf olt, %0, %cst_0 : f32
    %4 = arith.cmpf uno, %0, %0 : f32
    %c-2147483648_i32 = arith.constant -2147483648 : i32
    %5 = arith.select %3, %c-2147483648_i32, %1 : i32
    %c2147483647_i32 = arith.constant 2147483647 : i32
    %6 = arith.select %2, %c2147483647_i32, %5 : i32
    %c0_i32 = arith.constant 0 : i32
    %7 = arith.select %4, %c0_i32, %6 : i32
    sim.yield %7 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %0 = sim.load local @A[%i] : f32
    %1 = sim.load source @B[%i] : f32
    %2 = arith.addf %0, %1 : f32
    sim.yield %2 : f32
  }
  // expected-error @+1 {{records advance grid_substeps without estimates, but under strategy hip its schedule's bounded_by and its sub-stepping verdict give group_substeps without estimates; the records are stale or were edited by hand: run the front end (--sim-front-end) again}}
  sim.component @Smooth writes(@B) attributes {advance = #sim<advance grid_substeps>, local_window = array<i64: -1, 1>, parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = arith.index_cast %i : index to i32
    sim.yield %0 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %begin, %size = sim.big_step : i64, i64
    %0 = arith.extsi %n : i32 to i64
    %1 = arith.addi %t, %0 : i64
    %2 = arith.subi %1, %begin : i64
    %3 = arith.sitofp %2 : i64 to f32
    %4 = arith.sitofp %size : i64 to f32
    %5 = arith.divf %3, %4 : f32
    %c0_i64 = arith.constant 0 : i64
    %6 = arith.cmpi eq, %2, %c0_i64 : i64
    %7 = arith.cmpi eq, %2, %size : i64
    %c1 = arith.constant 1 : index
    %8 = arith.subi %i, %c1 : index
    %9 = arith.addi %i, %c1 : index
    %10 = sim.load local @B[%8] : f32
    %11 = sim.load local @B[%9] : f32
    %12 = scf.if %7 -> (f32) {
      %15 = sim.load target @A[%i] : f32
      scf.yield %15 : f32
    } else {
      %15 = scf.if %6 -> (f32) {
        %16 = sim.load source @A[%i] : f32
        scf.yield %16 : f32
      } else {
        %16 = sim.load source @A[%i] : f32
        %17 = sim.load target @A[%i] : f32
        %cst = arith.constant 1.000000e+00 : f32
        %18 = arith.subf %cst, %5 : f32
        %19 = arith.mulf %18, %16 : f32
        %20 = arith.mulf %5, %17 : f32
        %21 = arith.addf %19, %20 : f32
        scf.yield %21 : f32
      }
      scf.yield %15 : f32
    }
    %13 = arith.addf %10, %11 : f32
    %14 = arith.addf %13, %12 : f32
    sim.yield %14 : f32
  }
  sim.schedule [@Drive, @Smooth] bounded_by [@Drive]
  sim.observe [@B]
}

// -----

// hip: the verdict and the advance both relabelled: the verdict disagrees
// with the neighbour reads (in_kernel threads would read items between
// sub-steps).
sim.simulation @rec range(64) dt(0.00999999977 : f32) max_steps(8) attributes {step_cap = 8 : i32, strategy = #sim<strategy hip>} {
  sim.buffer @A : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %cst = arith.constant 1.000000e+00 : f32
    sim.yield %cst : f32
  }
  sim.buffer @B : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %0 = arith.index_cast %i : index to i64
    %1 = arith.sitofp %0 : i64 to f32
    sim.yield %1 : f32
  }
  sim.component @Drive writes(@A) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = sim.load source @B[%i] : f32
    %1 = arith.fptosi %0 : f32 to i32
    %cst = arith.constant 2.14748365E+9 : f32
    %2 = arith.cmpf oge, %0, %cst : f32
    %cst_0 = arith.constant -2.14748365E+9 : f32
    %3 = arith.cmpf olt, %0, %cst_0 : f32
    %4 = arith.cmpf uno, %0, %0 : f32
    %c-2147483648_i32 = arith.constant -2147483648 : i32
    %5 = arith.select %3, %c-2147483648_i32, %1 : i32
    %c2147483647_i32 = arith.constant 2147483647 : i32
    %6 = arith.select %2, %c2147483647_i32, %5 : i32
    %c0_i32 = arith.constant 0 : i32
    %7 = arith.select %4, %c0_i32, %6 : i32
    sim.yield %7 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %0 = sim.load local @A[%i] : f32
    %1 = sim.load source @B[%i] : f32
    %2 = arith.addf %0, %1 : f32
    sim.yield %2 : f32
  }
  sim.component @Smooth writes(@B) attributes {advance = #sim<advance group_substeps>, local_window = array<i64: -1, 1>, parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = arith.index_cast %i : index to i32
    sim.yield %0 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %begin, %size = sim.big_step : i64, i64
    %0 = arith.extsi %n : i32 to i64
    %1 = arith.addi %t, %0 : i64
    %2 = arith.subi %1, %begin : i64
    %3 = arith.sitofp %2 : i64 to f32
    %4 = arith.sitofp %size : i64 to f32
    %5 = arith.divf %3, %4 : f32
    %c0_i64 = arith.constant 0 : i64
    %6 = arith.cmpi eq, %2, %c0_i64 : i64
    %7 = arith.cmpi eq, %2, %size : i64
    %c1 = arith.constant 1 : index
    %8 = arith.subi %i, %c1 : index
    %9 = arith.addi %i, %c1 : index
    // expected-error @+1 {{reads @B, which @Smooth writes, at i-1, but @Smooth records the sub-stepping verdict in_kernel, which holds only for reads of its own item; the records are stale or were edited by hand: run the front end (--sim-front-end) again}}
    %10 = sim.load local @B[%8] : f32
    %11 = sim.load local @B[%9] : f32
    %12 = scf.if %7 -> (f32) {
      %15 = sim.load target @A[%i] : f32
      scf.yield %15 : f32
    } else {
      %15 = scf.if %6 -> (f32) {
        %16 = sim.load source @A[%i] : f32
        scf.yield %16 : f32
      } else {
        %16 = sim.load source @A[%i] : f32
        %17 = sim.load target @A[%i] : f32
        %cst = arith.constant 1.000000e+00 : f32
        %18 = arith.subf %cst, %5 : f32
        %19 = arith.mulf %18, %16 : f32
        %20 = arith.mulf %5, %17 : f32
        %21 = arith.addf %19, %20 : f32
        scf.yield %21 : f32
      }
      scf.yield %15 : f32
    }
    %13 = arith.addf %10, %11 : f32
    %14 = arith.addf %13, %12 : f32
    sim.yield %14 : f32
  }
  sim.schedule [@Drive, @Smooth] bounded_by [@Drive]
  sim.observe [@B]
}

// -----

// lts: a local_window narrower than the reads of @B.
sim.simulation @rec range(64) dt(0.00999999977 : f32) max_steps(8) attributes {step_cap = 8 : i32, strategy = #sim<strategy lts>} {
  sim.buffer @A : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %cst = arith.constant 1.000000e+00 : f32
    sim.yield %cst : f32
  }
  sim.buffer @B : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %0 = arith.index_cast %i : index to i64
    %1 = arith.sitofp %0 : i64 to f32
    sim.yield %1 : f32
  }
  sim.component @Drive writes(@A) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = sim.load source @B[%i] : f32
    %1 = arith.fptosi %0 : f32 to i32
    %cst = arith.constant 2.14748365E+9 : f32
    %2 = arith.cmpf oge, %0, %cst : f32
    %cst_0 = arith.constant -2.14748365E+9 : f32
    %3 = arith.cmpf olt, %0, %cst_0 : f32
    %4 = arith.cmpf uno, %0, %0 : f32
    %c-2147483648_i32 = arith.constant -2147483648 : i32
    %5 = arith.select %3, %c-2147483648_i32, %1 : i32
    %c2147483647_i32 = arith.constant 2147483647 : i32
    %6 = arith.select %2, %c2147483647_i32, %5 : i32
    %c0_i32 = arith.constant 0 : i32
    %7 = arith.select %4, %c0_i32, %6 : i32
    sim.yield %7 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %0 = sim.load local @A[%i] : f32
    %1 = sim.load source @B[%i] : f32
    %2 = arith.addf %0, %1 : f32
    sim.yield %2 : f32
  }
  sim.component @Smooth writes(@B) attributes {advance = #sim<advance local_steps>, invariant_levels, local_window = array<i64: 0, 1>, parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = arith.index_cast %i : index to i32
    sim.yield %0 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %begin, %size = sim.big_step : i64, i64
    %0 = arith.extsi %n : i32 to i64
    %1 = arith.addi %t, %0 : i64
    %2 = arith.subi %1, %begin : i64
    %3 = arith.sitofp %2 : i64 to f32
    %4 = arith.sitofp %size : i64 to f32
    %5 = arith.divf %3, %4 : f32
    %c0_i64 = arith.constant 0 : i64
    %6 = arith.cmpi eq, %2, %c0_i64 : i64
    %7 = arith.cmpi eq, %2, %size : i64
    %c1 = arith.constant 1 : index
    %8 = arith.subi %i, %c1 : index
    %9 = arith.addi %i, %c1 : index
    // expected-error @+1 {{reads @B, which @Smooth writes, at i-1, outside the local_window [0, 1] that its local steps are planned for; the records are stale or were edited by hand: run the front end (--sim-front-end) again}}
    %10 = sim.load local @B[%8] : f32
    %11 = sim.load local @B[%9] : f32
    %12 = scf.if %7 -> (f32) {
      %15 = sim.load target @A[%i] : f32
      scf.yield %15 : f32
    } else {
      %15 = scf.if %6 -> (f32) {
        %16 = sim.load source @A[%i] : f32
        scf.yield %16 : f32
      } else {
        %16 = sim.load source @A[%i] : f32
        %17 = sim.load target @A[%i] : f32
        %cst = arith.constant 1.000000e+00 : f32
        %18 = arith.subf %cst, %5 : f32
        %19 = arith.mulf %18, %16 : f32
        %20 = arith.mulf %5, %17 : f32
        %21 = arith.addf %19, %20 : f32
        scf.yield %21 : f32
      }
      scf.yield %15 : f32
    }
    %13 = arith.addf %10, %11 : f32
    %14 = arith.addf %13, %12 : f32
    sim.yield %14 : f32
  }
  sim.schedule [@Drive, @Smooth] bounded_by [@Drive]
  sim.observe [@B]
}

// -----

// hip: the schedule reversed after the loads were decided: @Smooth loads
// @A at the end of the step, which @Drive now writes after it.
sim.simulation @rec range(64) dt(0.00999999977 : f32) max_steps(8) attributes {step_cap = 8 : i32, strategy = #sim<strategy hip>} {
  sim.buffer @A : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %cst = arith.constant 1.000000e+00 : f32
    sim.yield %cst : f32
  }
  sim.buffer @B : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %0 = arith.index_cast %i : index to i64
    %1 = arith.sitofp %0 : i64 to f32
    sim.yield %1 : f32
  }
  sim.component @Drive writes(@A) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = sim.load source @B[%i] : f32
    %1 = arith.fptosi %0 : f32 to i32
    %cst = arith.constant 2.14748365E+9 : f32
    %2 = arith.cmpf oge, %0, %cst : f32
    %cst_0 = arith.constant -2.14748365E+9 : f32
    %3 = arith.cmpf olt, %0, %cst_0 : f32
    %4 = arith.cmpf uno, %0, %0 : f32
    %c-2147483648_i32 = arith.constant -2147483648 : i32
    %5 = arith.select %3, %c-2147483648_i32, %1 : i32
    %c2147483647_i32 = arith.constant 2147483647 : i32
    %6 = arith.select %2, %c2147483647_i32, %5 : i32
    %c0_i32 = arith.constant 0 : i32
    %7 = arith.select %4, %c0_i32, %6 : i32
    sim.yield %7 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %0 = sim.load local @A[%i] : f32
    %1 = sim.load source @B[%i] : f32
    %2 = arith.addf %0, %1 : f32
    sim.yield %2 : f32
  }
  sim.component @Smooth writes(@B) attributes {advance = #sim<advance grid_substeps>, local_window = array<i64: -1, 1>, parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = arith.index_cast %i : index to i32
    sim.yield %0 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %begin, %size = sim.big_step : i64, i64
    %0 = arith.extsi %n : i32 to i64
    %1 = arith.addi %t, %0 : i64
    %2 = arith.subi %1, %begin : i64
    %3 = arith.sitofp %2 : i64 to f32
    %4 = arith.sitofp %size : i64 to f32
    %5 = arith.divf %3, %4 : f32
    %c0_i64 = arith.constant 0 : i64
    %6 = arith.cmpi eq, %2, %c0_i64 : i64
    %7 = arith.cmpi eq, %2, %size : i64
    %c1 = arith.constant 1 : index
    %8 = arith.subi %i, %c1 : index
    %9 = arith.addi %i, %c1 : index
    %10 = sim.load local @B[%8] : f32
    %11 = sim.load local @B[%9] : f32
    %12 = scf.if %7 -> (f32) {
      // expected-error @+1 {{loads the target copy of @A, but its writer @Drive runs after @Smooth in the schedule, so only its value at T (the source copy) exists when @Smooth runs; the records are stale or were edited by hand: run the front end (--sim-front-end) again}}
      %15 = sim.load target @A[%i] : f32
      scf.yield %15 : f32
    } else {
      %15 = scf.if %6 -> (f32) {
        %16 = sim.load source @A[%i] : f32
        scf.yield %16 : f32
      } else {
        %16 = sim.load source @A[%i] : f32
        %17 = sim.load target @A[%i] : f32
        %cst = arith.constant 1.000000e+00 : f32
        %18 = arith.subf %cst, %5 : f32
        %19 = arith.mulf %18, %16 : f32
        %20 = arith.mulf %5, %17 : f32
        %21 = arith.addf %19, %20 : f32
        scf.yield %21 : f32
      }
      scf.yield %15 : f32
    }
    %13 = arith.addf %10, %11 : f32
    %14 = arith.addf %13, %12 : f32
    sim.yield %14 : f32
  }
  sim.schedule [@Smooth, @Drive] bounded_by [@Drive]
  sim.observe [@B]
}

// -----

// hip: bounded_by names the other component.
sim.simulation @rec range(64) dt(0.00999999977 : f32) max_steps(8) attributes {step_cap = 8 : i32, strategy = #sim<strategy hip>} {
  sim.buffer @A : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %cst = arith.constant 1.000000e+00 : f32
    sim.yield %cst : f32
  }
  sim.buffer @B : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %0 = arith.index_cast %i : index to i64
    %1 = arith.sitofp %0 : i64 to f32
    sim.yield %1 : f32
  }
  // expected-error @+1 {{records advance whole_step with estimates, but under strategy hip its schedule's bounded_by and its sub-stepping verdict give group_substeps without estimates; the records are stale or were edited by hand: run the front end (--sim-front-end) again}}
  sim.component @Drive writes(@A) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = sim.load source @B[%i] : f32
    %1 = arith.fptosi %0 : f32 to i32
    %cst = arith.constant 2.14748365E+9 : f32
    %2 = arith.cmpf oge, %0, %cst : f32
    %cst_0 = arith.constant -2.14748365E+9 : f32
    %3 = arith.cmpf olt, %0, %cst_0 : f32
    %4 = arith.cmpf uno, %0, %0 : f32
    %c-2147483648_i32 = arith.constant -2147483648 : i32
    %5 = arith.select %3, %c-2147483648_i32, %1 : i32
    %c2147483647_i32 = arith.constant 2147483647 : i32
    %6 = arith.select %2, %c2147483647_i32, %5 : i32
    %c0_i32 = arith.constant 0 : i32
    %7 = arith.select %4, %c0_i32, %6 : i32
    sim.yield %7 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %0 = sim.load local @A[%i] : f32
    %1 = sim.load source @B[%i] : f32
    %2 = arith.addf %0, %1 : f32
    sim.yield %2 : f32
  }
  sim.component @Smooth writes(@B) attributes {advance = #sim<advance grid_substeps>, local_window = array<i64: -1, 1>, parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = arith.index_cast %i : index to i32
    sim.yield %0 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %begin, %size = sim.big_step : i64, i64
    %0 = arith.extsi %n : i32 to i64
    %1 = arith.addi %t, %0 : i64
    %2 = arith.subi %1, %begin : i64
    %3 = arith.sitofp %2 : i64 to f32
    %4 = arith.sitofp %size : i64 to f32
    %5 = arith.divf %3, %4 : f32
    %c0_i64 = arith.constant 0 : i64
    %6 = arith.cmpi eq, %2, %c0_i64 : i64
    %7 = arith.cmpi eq, %2, %size : i64
    %c1 = arith.constant 1 : index
    %8 = arith.subi %i, %c1 : index
    %9 = arith.addi %i, %c1 : index
    %10 = sim.load local @B[%8] : f32
    %11 = sim.load local @B[%9] : f32
    %12 = scf.if %7 -> (f32) {
      %15 = sim.load target @A[%i] : f32
      scf.yield %15 : f32
    } else {
      %15 = scf.if %6 -> (f32) {
        %16 = sim.load source @A[%i] : f32
        scf.yield %16 : f32
      } else {
        %16 = sim.load source @A[%i] : f32
        %17 = sim.load target @A[%i] : f32
        %cst = arith.constant 1.000000e+00 : f32
        %18 = arith.subf %cst, %5 : f32
        %19 = arith.mulf %18, %16 : f32
        %20 = arith.mulf %5, %17 : f32
        %21 = arith.addf %19, %20 : f32
        scf.yield %21 : f32
      }
      scf.yield %15 : f32
    }
    %13 = arith.addf %10, %11 : f32
    %14 = arith.addf %13, %12 : f32
    sim.yield %14 : f32
  }
  sim.schedule [@Drive, @Smooth] bounded_by [@Smooth]
  sim.observe [@B]
}

// -----

// A hip plan relabelled traditional.
sim.simulation @rec range(64) dt(0.00999999977 : f32) max_steps(8) attributes {step_cap = 8 : i32, strategy = #sim<strategy traditional>} {
  sim.buffer @A : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %cst = arith.constant 1.000000e+00 : f32
    sim.yield %cst : f32
  }
  sim.buffer @B : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %0 = arith.index_cast %i : index to i64
    %1 = arith.sitofp %0 : i64 to f32
    sim.yield %1 : f32
  }
  sim.component @Drive writes(@A) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = sim.load source @B[%i] : f32
    %1 = arith.fptosi %0 : f32 to i32
    %cst = arith.constant 2.14748365E+9 : f32
    %2 = arith.cmpf oge, %0, %cst : f32
    %cst_0 = arith.constant -2.14748365E+9 : f32
    %3 = arith.cmpf olt, %0, %cst_0 : f32
    %4 = arith.cmpf uno, %0, %0 : f32
    %c-2147483648_i32 = arith.constant -2147483648 : i32
    %5 = arith.select %3, %c-2147483648_i32, %1 : i32
    %c2147483647_i32 = arith.constant 2147483647 : i32
    %6 = arith.select %2, %c2147483647_i32, %5 : i32
    %c0_i32 = arith.constant 0 : i32
    %7 = arith.select %4, %c0_i32, %6 : i32
    sim.yield %7 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %0 = sim.load local @A[%i] : f32
    %1 = sim.load source @B[%i] : f32
    %2 = arith.addf %0, %1 : f32
    sim.yield %2 : f32
  }
  // expected-error @+1 {{records advance grid_substeps without estimates, but under strategy traditional its schedule's bounded_by and its sub-stepping verdict give whole_step with estimates; the records are stale or were edited by hand: run the front end (--sim-front-end) again}}
  sim.component @Smooth writes(@B) attributes {advance = #sim<advance grid_substeps>, local_window = array<i64: -1, 1>, parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = arith.index_cast %i : index to i32
    sim.yield %0 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %begin, %size = sim.big_step : i64, i64
    %0 = arith.extsi %n : i32 to i64
    %1 = arith.addi %t, %0 : i64
    %2 = arith.subi %1, %begin : i64
    %3 = arith.sitofp %2 : i64 to f32
    %4 = arith.sitofp %size : i64 to f32
    %5 = arith.divf %3, %4 : f32
    %c0_i64 = arith.constant 0 : i64
    %6 = arith.cmpi eq, %2, %c0_i64 : i64
    %7 = arith.cmpi eq, %2, %size : i64
    %c1 = arith.constant 1 : index
    %8 = arith.subi %i, %c1 : index
    %9 = arith.addi %i, %c1 : index
    %10 = sim.load local @B[%8] : f32
    %11 = sim.load local @B[%9] : f32
    %12 = scf.if %7 -> (f32) {
      %15 = sim.load target @A[%i] : f32
      scf.yield %15 : f32
    } else {
      %15 = scf.if %6 -> (f32) {
        %16 = sim.load source @A[%i] : f32
        scf.yield %16 : f32
      } else {
        %16 = sim.load source @A[%i] : f32
        %17 = sim.load target @A[%i] : f32
        %cst = arith.constant 1.000000e+00 : f32
        %18 = arith.subf %cst, %5 : f32
        %19 = arith.mulf %18, %16 : f32
        %20 = arith.mulf %5, %17 : f32
        %21 = arith.addf %19, %20 : f32
        scf.yield %21 : f32
      }
      scf.yield %15 : f32
    }
    %13 = arith.addf %10, %11 : f32
    %14 = arith.addf %13, %12 : f32
    sim.yield %14 : f32
  }
  sim.schedule [@Drive, @Smooth] bounded_by [@Drive]
  sim.observe [@B]
}

// -----

// simple: a load of an earlier component's buffer swapped to the source
// copy (the value at T instead of T + m).
sim.simulation @rec range(64) dt(0.00999999977 : f32) max_steps(8) attributes {step_cap = 1 : i32, strategy = #sim<strategy simple>} {
  sim.buffer @A : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %cst = arith.constant 1.000000e+00 : f32
    sim.yield %cst : f32
  }
  sim.buffer @B : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %0 = arith.index_cast %i : index to i64
    %1 = arith.sitofp %0 : i64 to f32
    sim.yield %1 : f32
  }
  sim.component @Drive writes(@A) attributes {advance = #sim<advance whole_step>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = sim.load source @B[%i] : f32
    %1 = arith.fptosi %0 : f32 to i32
    %cst = arith.constant 2.14748365E+9 : f32
    %2 = arith.cmpf oge, %0, %cst : f32
    %cst_0 = arith.constant -2.14748365E+9 : f32
    %3 = arith.cmpf olt, %0, %cst_0 : f32
    %4 = arith.cmpf uno, %0, %0 : f32
    %c-2147483648_i32 = arith.constant -2147483648 : i32
    %5 = arith.select %3, %c-2147483648_i32, %1 : i32
    %c2147483647_i32 = arith.constant 2147483647 : i32
    %6 = arith.select %2, %c2147483647_i32, %5 : i32
    %c0_i32 = arith.constant 0 : i32
    %7 = arith.select %4, %c0_i32, %6 : i32
    sim.yield %7 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %0 = sim.load local @A[%i] : f32
    %1 = sim.load source @B[%i] : f32
    %2 = arith.addf %0, %1 : f32
    sim.yield %2 : f32
  }
  sim.component @Smooth writes(@B) attributes {advance = #sim<advance whole_step>, local_window = array<i64: -1, 1>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping grid_sync>} num_steps {
  ^bb0(%i: index, %t: i64):
    %0 = arith.index_cast %i : index to i32
    sim.yield %0 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %0 = arith.subi %i, %c1 : index
    %1 = arith.addi %i, %c1 : index
    %2 = sim.load local @B[%0] : f32
    %3 = sim.load local @B[%1] : f32
    // expected-error @+1 {{loads the source copy of @A, but under strategy simple its evaluate body reads a buffer that @Drive wrote earlier in the step at the end of the big step (the target copy); the records are stale or were edited by hand: run the front end (--sim-front-end) again}}
    %4 = sim.load source @A[%i] : f32
    %5 = arith.addf %2, %3 : f32
    %6 = arith.addf %5, %4 : f32
    sim.yield %6 : f32
  }
  sim.schedule [@Drive, @Smooth] bounded_by [@Drive]
  sim.observe [@B]
}

// -----

// hip-cache: @Pull reads @U at a parameter's distance (a gather), but its
// cache load is marked in_window: lowered without a check, it would read
// shared memory outside the cache.
sim.simulation @clamped range(16) dt(1.000000e-01 : f32) max_steps(4) attributes {step_cap = 4 : i32, strategy = #sim<strategy "hip-cache">} {
  sim.param @lead = 3 : i64
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %0 = arith.index_cast %i : index to i32
    %1 = arith.sitofp %0 : i32 to f32
    sim.yield %1 : f32
  }
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %cst = arith.constant 0.000000e+00 : f32
    sim.yield %cst : f32
  }
  sim.component @Drive writes(@U) attributes {advance = #sim<advance group_substeps>, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %c4_i32 = arith.constant 4 : i32
    sim.yield %c4_i32 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %0 = sim.load local @U[%i] : f32
    %1 = arith.addf %0, %dt : f32
    sim.yield %1 : f32
  }
  sim.component @Pull writes(@S) attributes {advance = #sim<advance group_substeps>, caches = [#sim.cache<@U, -1, 1>], parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
  ^bb0(%i: index, %t: i64):
    %c1_i32 = arith.constant 1 : i32
    sim.yield %c1_i32 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %begin, %size = sim.big_step : i64, i64
    %0 = arith.extsi %n : i32 to i64
    %1 = arith.addi %t, %0 : i64
    %2 = arith.subi %1, %begin : i64
    %3 = arith.sitofp %2 : i64 to f32
    %4 = arith.sitofp %size : i64 to f32
    %5 = arith.divf %3, %4 : f32
    %c0_i64 = arith.constant 0 : i64
    %6 = arith.cmpi eq, %2, %c0_i64 : i64
    %7 = arith.cmpi eq, %2, %size : i64
    sim.fill_cache @U window(-1, 1) {
    ^bb0(%arg0: index):
      %20 = scf.if %7 -> (f32) {
        %21 = sim.load target @U[%arg0] : f32
        scf.yield %21 : f32
      } else {
        %21 = scf.if %6 -> (f32) {
          %22 = sim.load source @U[%arg0] : f32
          scf.yield %22 : f32
        } else {
          %22 = sim.load source @U[%arg0] : f32
          %23 = sim.load target @U[%arg0] : f32
          %cst = arith.constant 1.000000e+00 : f32
          %24 = arith.subf %cst, %5 : f32
          %25 = arith.mulf %24, %22 : f32
          %26 = arith.mulf %5, %23 : f32
          %27 = arith.addf %25, %26 : f32
          scf.yield %27 : f32
        }
        scf.yield %21 : f32
      }
      sim.yield %20 : f32
    }
    %c1 = arith.constant 1 : index
    %8 = sim.get_param @lead : i64
    %9 = arith.index_cast %8 : i64 to index
    %10 = arith.addi %i, %9 : index
    %11 = arith.subi %i, %c1 : index
    %12 = arith.addi %i, %c1 : index
    %13 = arith.maxsi %10, %11 : index
    %14 = arith.minsi %13, %12 : index
    %15 = sim.load cache @U[%14] in_window : f32
    %16 = sim.load cache @U[%11] in_window : f32
    // expected-error @+1 {{is marked in_window, but reads @U through a gather, outside the window [-1, 1] of its fill; the records are stale or were edited by hand: run the front end (--sim-front-end) again}}
    %17 = sim.load cache @U[%10]  in_window : f32
    %18 = arith.addf %15, %16 : f32
    %19 = arith.addf %18, %17 : f32
    sim.yield %19 : f32
  }
  sim.schedule [@Drive, @Pull]
  sim.observe [@S]
}
