// lts on the CPU around a wrapping range (boundary(wrap)): limit_levels_C
// sweeps until no block changes (the shortest way to a block may wrap past
// the sweeps' start), each sweep looking only at the side it comes from,
// and finds a neighbour block around the range with one conditional
// addition or subtraction of the blocks, no remainder.
//
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu | FileCheck %s

sim.simulation @ring range(100) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @U : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
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

// CHECK-LABEL: func.func @limit_levels_Diffuse(
// CHECK-NOT:     arith.remsi
// CHECK:         scf.while
// The forward sweep lowers block g to twice its neighbours below it alone:
// at distance d, g - d, plus the blocks when that is below 0.
// CHECK:           scf.for {{.*}} iter_args(%{{.*}} = %false) -> (i1)
// CHECK:             scf.for %[[D:arg[0-9]+]] = %c1_i64 to
// CHECK-NEXT:          %[[BELOW:.*]] = arith.subi %[[G:.*]], %[[D]] : i64
// CHECK-NEXT:          %[[NEGATIVE:.*]] = arith.cmpi slt, %[[BELOW]], %c0_i64 : i64
// CHECK-NEXT:          %[[AROUND:.*]] = arith.addi %[[BELOW]], %[[BLOCKS:.*]] : i64
// CHECK-NEXT:          arith.select %[[NEGATIVE]], %[[AROUND]], %[[BELOW]] : i64
// CHECK-NOT:           arith.addi %[[G]], %[[D]] : i64
// CHECK:               scf.yield
// The backward sweep, to those above it alone: g + d, less the blocks when
// that is past the last.
// CHECK:           scf.for {{.*}} iter_args(%{{.*}} = %{{.*}}) -> (i1)
// CHECK:             scf.for %[[D2:arg[0-9]+]] = %c1_i64 to
// CHECK-NEXT:          %[[ABOVE:.*]] = arith.addi %[[G2:.*]], %[[D2]] : i64
// CHECK-NEXT:          %[[PAST:.*]] = arith.cmpi sge, %[[ABOVE]], %[[BLOCKS]] : i64
// CHECK-NEXT:          %[[BACK:.*]] = arith.subi %[[ABOVE]], %[[BLOCKS]] : i64
// CHECK-NEXT:          arith.select %[[PAST]], %[[BACK]], %[[ABOVE]] : i64
// CHECK-NOT:           arith.subi %[[G2]], %[[D2]] : i64
// CHECK:               scf.yield
// CHECK-NOT:     arith.remsi
// CHECK:       return
