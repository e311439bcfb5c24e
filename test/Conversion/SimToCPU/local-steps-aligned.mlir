// lts on the CPU, a window wider than a block (@U[i - 40]): a run of blocks
// next to another sub-step evaluates through the time levels, block by
// block, unless every block its window reaches is aligned at the slot: its
// latest level is at the slot (its sub-step divides the slot) and in the
// half the run reads (bit `level` of the slot). A read through the time
// levels then returns that half's value as is, so such a block reads in
// step: plain loads, no selects of levels (docs/Model.md, "What a read
// returns"). Every block is aligned at slot 0.
//
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu | FileCheck %s

sim.simulation @rod range(200) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %c100 = arith.constant 100 : i64
    %stiff = arith.cmpi sge, %i64, %c100 : i64
    %c1 = arith.constant 1 : i32
    %c8 = arith.constant 8 : i32
    %n = arith.select %stiff, %c1, %c8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c40 = arith.constant 40 : index
    %il = arith.subi %i, %c40 : index
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

// The blocks the window of a block reaches: from the one 40 items before
// its first item (or block 0) to its own (the window's upper end is 0).
// CHECK-LABEL: func.func @local_step_Diffuse(
// CHECK-SAME:      %{{.*}}: memref<?xi64>, %[[U:arg1]]: memref<?xf32>, %[[LEVELS:arg2]]: memref<?xi64>
// CHECK:             arith.cmpi uge, %[[FIRST:[0-9]+]], %c40 : index
// CHECK:             %[[BELOW:.*]] = arith.subi %[[FIRST]], %c40 : index
// CHECK:             %[[LOW:.*]] = arith.select %{{.*}}, %[[BELOW]], %c0 : index
// CHECK:             %[[LOW_BLOCK:.*]] = arith.divui %[[LOW]], %c32 : index
// CHECK:             %[[ALIGNED:.*]] = scf.for %{{.*}} = %[[LOW_BLOCK]] to %{{.*}} step %c1 iter_args(%[[ALL:.*]] = %true) -> (i1) {
// CHECK:               %[[STEP:.*]] = memref.load %[[LEVELS]][%{{.*}}] : memref<?xi64>
// CHECK:               %[[MASK:.*]] = arith.subi %[[STEP]], %c1_i64 : i64
// CHECK:               %[[OFF:.*]] = arith.andi %[[SLOT:.*]], %[[MASK]] : i64
// CHECK:               %[[AT_SLOT:.*]] = arith.cmpi eq, %[[OFF]], %c0_i64 : i64
// CHECK:               %[[BIT:.*]] = arith.andi %[[SLOT]], %[[STEP]] : i64
// CHECK:               %[[SAME_HALF:.*]] = arith.cmpi eq, %{{.*}}, %[[READ_PARITY:.*]] : i64
// CHECK:               %[[THIS:.*]] = arith.andi %[[AT_SLOT]], %[[SAME_HALF]] : i1
// CHECK:               %[[BOTH:.*]] = arith.andi %[[ALL]], %[[THIS]] : i1
// CHECK:               scf.yield %[[BOTH]] : i1
// In step: the half the run reads, one load per read.
// CHECK:             scf.if %[[ALIGNED]] {
// CHECK:               scf.for
// CHECK-NOT:             arith.select
// CHECK:                 memref.load %[[U]]
// CHECK-NOT:             arith.select
// CHECK:                 memref.load %[[U]]
// CHECK-NOT:             arith.select
// CHECK:                 memref.store %{{.*}}, %[[U]]
// CHECK:               } {simplan.lanes}
// Else through the time levels: both halves, the levels selected per lane.
// CHECK-NEXT:        } else {
// CHECK:               scf.for
// CHECK:                 arith.select
// CHECK:                 memref.store %{{.*}}, %[[U]]
// CHECK:               } {simplan.lanes}
// CHECK:             }
// CHECK:             memref.atomic_rmw addi
