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

// The flux writer's estimate bounds the big step by its largest num_steps
// (docs/Model.md, "The big step"): capped at max_steps, negated, combined
// into its own slot (16) by minima, groups stopping once the slot holds
// the cap (their hint in 17); taken only while advance has kept none (18),
// since its reader keeps its levels (keeps_estimate).
// CHECK-LABEL: func.func @estimate_Flux(
// CHECK:         %[[KEPT:.*]] = memref.load %arg0[%c18]
// CHECK:         arith.cmpi eq, %[[KEPT]], %c0_i64
// CHECK:         memref.atomic_rmw addi %c0_i64, %arg0[%c17]
// CHECK:         arith.cmpi sgt, %{{.*}}, %c-8_i64
// CHECK:         %[[CAPPED:.*]] = arith.minsi %{{.*}}, %c8_i32 : i32
// CHECK-NEXT:    arith.subi %c0_i32, %[[CAPPED]] : i32
// CHECK:         memref.atomic_rmw mins %{{.*}}, %arg0[%c16]
// advance: the big step at most the largest estimate, the one taken or the
// one kept (the cap when neither), which it keeps; the slot of the one
// taken starts the next at 0.
// CHECK-LABEL: func.func @advance(
// CHECK:         %[[TAKEN:.*]] = memref.load %arg0[%c16]
// CHECK-NEXT:    %[[OLD:.*]] = memref.load %arg0[%c18]
// CHECK-NEXT:    %[[NEGATED:.*]] = arith.minsi %[[TAKEN]], %[[OLD]]
// CHECK-NEXT:    memref.store %[[NEGATED]], %arg0[%c18]
// CHECK-NEXT:    %[[ANY:.*]] = arith.cmpi slt, %[[NEGATED]], %c0_i64
// CHECK-NEXT:    %[[LARGEST:.*]] = arith.subi %c0_i64, %[[NEGATED]]
// CHECK-NEXT:    %[[BOUND:.*]] = arith.select %[[ANY]], %[[LARGEST]], %c8_i64
// CHECK-NEXT:    arith.minsi %c8_i64, %[[BOUND]]
// CHECK-NEXT:    memref.store %c0_i64, %arg0[%c16]
// CHECK-LABEL: func.func @levels_Cells(
//                The cells' codes, then one atomic per block: a vector
//                maximum for each whole block of a group that starts on a
//                block boundary (an atomic, as the interfaces' codes join
//                them), the lanes one by one for the rest.
// CHECK:         } {simplan.lanes}
// CHECK:         %[[WHOLE:.*]] = vector.load %{{alloca[_0-9]*}}[%{{.*}}] : memref<?xi64>, vector<32xi64>
// CHECK-NEXT:    %[[LARGEST:.*]] = vector.reduction <maxsi>, %[[WHOLE]] : vector<32xi64> into i64
// CHECK:         memref.atomic_rmw maxs %[[LARGEST]]
// CHECK:         scf.for
// CHECK:           memref.atomic_rmw maxs
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

// Under zero: the cells' whole blocks and the rest, the interfaces, and no
// phase for the readers outside the range; then the unit request (the
// sub-step clock's UnitRequest, 15).
// ZERO-LABEL:  func.func @levels_Cells(
// ZERO-COUNT-3: memref.atomic_rmw maxs
// ZERO:         memref.atomic_rmw mins %{{.*}}, %arg0[%c15]
// ZERO-NOT:     memref.atomic_rmw
// ZERO:        func.func @limit_levels_Cells(

// Every lanes loop widens but the end groups' (their atomics).
// WIDE-NOT:   lanes stay scalar
// WIDE:       lanes stay scalar: an op it cannot widen: memref.atomic_rmw
// WIDE-NOT:   lanes stay scalar

// CHECK-LABEL: simplan.plan
// CHECK:         simplan.component @Flux writes [@F] evaluations(8) advance local_flux estimates largest_estimate(16) keeps_estimate
// CHECK-NEXT:    simplan.component @Cells writes [@U] evaluations(9) advance local_steps sub_clock(10) keeps_levels
