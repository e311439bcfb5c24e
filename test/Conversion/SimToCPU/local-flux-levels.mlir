// levels_C of a flux pair under lts on the CPU: the flux writer's estimate
// at interface j bounds the blocks of its readers j - o (o in flux_window,
// here -1..0). The lanes store the interfaces' codes in a phase without
// atomics; one atomic maximum per block then combines the lanes that reach
// the block; under clamp (or wrap) only a group at an end of the range
// also takes the per-reader atomics of the boundary rule, in a phase of
// its own; under zero there is no such phase (second RUN).
//
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu \
// RUN:   | sim-opt --sim-vectorize-lanes="width=8 report=true" -o /dev/null 2>&1 \
// RUN:   | FileCheck %s --check-prefix=WIDE
// RUN: sed 's/boundary(clamp)/boundary(zero)/' %s \
// RUN:   | sim-opt --sim-front-end=strategy=lts --sim-lower-to-cpu \
// RUN:   | FileCheck %s --check-prefix=ZERO

sim.simulation @rod range(100) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @U : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @F : f32 interp(#sim.flux) boundary(clamp) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.schedule [@Flux]
  sim.component @Flux writes(@F) num_steps {
  ^bb0(%j: index, %t: i64):
    %j64 = arith.index_cast %j : index to i64
    %c50 = arith.constant 50 : i64
    %stiff = arith.cmpi sge, %j64, %c50 : i64
    %c1 = arith.constant 1 : i32
    %c8 = arith.constant 8 : i32
    %n = arith.select %stiff, %c1, %c8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %ul = sim.read @U[%j] : f32
    %ur = sim.read @U[%jr] : f32
    %du = arith.subf %ur, %ul : f32
    sim.yield %du : f32
  }
  sim.component @Cells writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c8 = arith.constant 8 : i32
    sim.yield %c8 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %fw = sim.read @F[%il] : f32
    %fe = sim.read @F[%i] : f32
    %u0 = sim.read @U[%i] : f32
    %d = arith.subf %fe, %fw : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %u1 = math.fma %h, %d, %u0 : f32
    sim.yield %u1 : f32
  }
  sim.observe [@U]
}

// CHECK-LABEL: func.func @levels_Cells(
//                The cells' codes, then one atomic per block.
// CHECK:         } {simplan.lanes}
// CHECK:         memref.atomic_rmw maxs
//                The interfaces' codes: no atomic among the lanes.
// CHECK-NOT:     memref.atomic_rmw
// CHECK:         } {simplan.lanes}
//                The lanes that reach each block, one atomic.
// CHECK:         scf.for
// CHECK:           scf.for
// CHECK:             arith.maxsi
// CHECK:           memref.atomic_rmw maxs
//                A group at an end of the range: the boundary rule's readers.
// CHECK:         scf.if
// CHECK:           scf.for
// CHECK:             scf.for
// CHECK:               memref.atomic_rmw maxs

// A block whose interfaces reach another sub-step is due at the finest
// sub-step among its interfaces (each that of its coarsest reader, j and
// j + 1 here), not at that of the finest block its interfaces reach: the
// interfaces whose readers all lie in the block take its own, those at its
// two ends are folded over their readers (limit_levels_C, one lane per
// block).
// CHECK-LABEL: func.func @limit_levels_Cells(
// CHECK:         scf.if
// CHECK:         } else {
// CHECK:           scf.for
// CHECK:             scf.for %{{.*}} = %c-1 to %c1
// CHECK:               arith.maxsi
// CHECK:             arith.minsi
// CHECK:           scf.for
// CHECK:             scf.for %{{.*}} = %c-1 to %c1
// CHECK:               arith.maxsi
// CHECK:             arith.minsi
// CHECK:       func.func @local_flux_Flux(

// ZERO-LABEL:  func.func @levels_Cells(
// ZERO-COUNT-2: memref.atomic_rmw maxs
// ZERO-NOT:     memref.atomic_rmw
// ZERO:        func.func @limit_levels_Cells(

// Every lanes loop widens but the end groups' (their atomics).
// WIDE-NOT:   lanes stay scalar
// WIDE:       lanes stay scalar: an op it cannot widen: memref.atomic_rmw
// WIDE-NOT:   lanes stay scalar
