// The CPU kernels of local time steps for a component whose levels depend
// on the state (num_steps reads @U, so no invariant_levels), in big steps
// of up to max_steps(6), not a power of two (docs/Model.md, "Levels").
//
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu | FileCheck %s

sim.simulation @front range(100) dt(1.0e-2 : f32) max_steps(6) {
  sim.buffer @U : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @React writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %u = sim.read @U[%i] : f32
    %half = arith.constant 5.0e-1 : f32
    %stiff = arith.cmpf ogt, %u, %half : f32
    %c1 = arith.constant 1 : i32
    %c8 = arith.constant 8 : i32
    %n = arith.select %stiff, %c1, %c8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %ul = sim.read @U[%il] : f32
    %u0 = sim.read @U[%i] : f32
    %ur = sim.read @U[%ir] : f32
    %s = arith.addf %ul, %ur : f32
    %two = arith.constant 2.0 : f32
    %d = arith.mulf %two, %u0 : f32
    %lap = arith.subf %s, %d : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %u1 = math.fma %h, %lap, %u0 : f32
    sim.yield %u1 : f32
  }
  sim.observe [@U]
}

// advance restarts the sub-step clock of @React (slots 9 to 14: Begin, Size,
// Done, Estimate, Unit, UnitRequest) but leaves its Estimate slot, where
// limit_levels_C keeps the key of the levels it last limited, and the
// unit slots, which limit_levels_C and local_parity_C keep.
// CHECK-LABEL: func.func @advance(
// CHECK:         memref.store %{{.*}}, %arg0[%c9]
// CHECK-NEXT:    memref.store %c0_i64, %arg0[%c10]
// CHECK-NEXT:    memref.store %c0_i64, %arg0[%c11]
// CHECK-NOT:     memref.store
// CHECK:       return

// levels_C: each item's num_steps, capped at max_steps and at least 1, less
// 2^31 - 1, joins the unit request, the minimum over the lanes, which goes
// into the UnitRequest slot (14) by an atomic minimum.
// CHECK-LABEL: func.func @levels_React(
// CHECK:         %[[REQUEST:.*]] = memref.alloca(%{{.*}}) : memref<?xi32>
// CHECK:         arith.minsi %{{.*}}, %c6_i32 : i32
// CHECK-NEXT:    arith.maxsi %{{.*}}, %c1_i32 : i32
// CHECK-NEXT:    arith.subi %{{.*}}, %c2147483647_i32 : i32
// CHECK:         %[[FOLD:.*]] = scf.for {{.*}} iter_args(%{{.*}} = %c2147483647_i32) -> (i32)
// CHECK:         %[[WIDE:.*]] = arith.extsi %[[FOLD]] : i32 to i64
// CHECK-NEXT:    memref.atomic_rmw mins %[[WIDE]], %arg0[%c14]
// CHECK:       return

// limit_levels_C: the unit u is the request plus 2^31 - 1, at most m and at
// least 1; the whole big step counts as the smallest power of two not below
// ceil(m / u). One pass over the blocks compares each code (half `parity`)
// plus 1 with the one kept in section Cached (7), clears the code half of
// the next big step and takes the finest sub-step kept in section Steps;
// where every code and the key u * (max_steps + 1) + m (the Estimate slot)
// are those of the last limit, that finest goes to the sub-step clock's
// Size and nothing is limited; else the levels are limited again, and the
// codes plus 1 and the key kept. The unit goes to the Unit slot (13).
// CHECK-LABEL: func.func @limit_levels_React(
// CHECK-SAME:      %[[CLOCK:arg0]]: memref<?xi64>, %[[LEVELS:arg1]]: memref<?xi64>
// CHECK:         %[[M:.*]] = memref.load %[[CLOCK]][%c1]
// CHECK:         %[[REQ:.*]] = memref.load %[[CLOCK]][%c14]
// CHECK-NEXT:    %[[ASKED:.*]] = arith.addi %[[REQ]], %c2147483647_i64
// CHECK-NEXT:    %[[CAPPED:.*]] = arith.minsi %[[ASKED]], %[[M]]
// CHECK-NEXT:    %[[UNIT:.*]] = arith.maxsi %[[CAPPED]], %c1_i64
// CHECK-NEXT:    %[[UM1:.*]] = arith.subi %[[UNIT]], %c1_i64
// CHECK-NEXT:    %[[UP:.*]] = arith.addi %[[M]], %[[UM1]]
// CHECK-NEXT:    %[[UNITS:.*]] = arith.divui %[[UP]], %[[UNIT]]
// CHECK-NEXT:    %[[ONE:.*]] = arith.maxsi %[[UNITS]], %c1_i64
// CHECK:         %[[TWICE:.*]] = arith.addi %[[ONE]], %[[ONE]]
// CHECK:         memref.store %[[UNIT]], %[[CLOCK]][%c13]
// CHECK:         %[[CACHED:.*]] = arith.muli %c7_i64
// CHECK:         %[[PASS:.*]]:2 = scf.for {{.*}} iter_args(%{{.*}} = %true, %{{.*}} = %{{.*}}) -> (i1, i64)
// CHECK:           %[[CODE:.*]] = memref.load %[[LEVELS]]
// CHECK:           %[[PLUS:.*]] = arith.addi %[[CODE]], %c1_i64
// CHECK:           %[[KEPTAT:.*]] = arith.addi %[[CACHED]]
// CHECK:           %[[KEPT:.*]] = memref.load %[[LEVELS]]
// CHECK:           arith.cmpi eq, %[[PLUS]], %[[KEPT]]
// CHECK:           memref.store %c0_i64, %[[LEVELS]]
// CHECK:           arith.minsi
// CHECK:         %[[SCALED:.*]] = arith.muli %[[UNIT]], %c7_i64
// CHECK-NEXT:    %[[KEY:.*]] = arith.addi %[[SCALED]], %[[M]]
// CHECK-NEXT:    %[[LAST:.*]] = memref.load %[[CLOCK]][%c12]
// CHECK-NEXT:    %[[SAMEM:.*]] = arith.cmpi eq, %[[LAST]], %[[KEY]]
// CHECK:         %[[REUSE:.*]] = arith.andi %[[PASS]]#0, %[[SAMEM]]
// CHECK:         scf.if %[[REUSE]] {
// CHECK-NEXT:      memref.store %[[PASS]]#1, %[[CLOCK]][%c10]
// CHECK-NEXT:    } else {
// CHECK:             arith.divui %{{.*}}, %[[UNIT]] : i64
// CHECK:             %[[KEEPAT:.*]] = arith.addi %[[CACHED]], %{{[0-9]+}} : i64
// CHECK-NEXT:        %[[KEEPINDEX:.*]] = arith.index_cast %[[KEEPAT]] : i64 to index
// CHECK-NEXT:        memref.store %{{[0-9]+}}, %[[LEVELS]][%[[KEEPINDEX]]]
// CHECK-NEXT:      }
// CHECK-NEXT:      memref.store %[[KEY]], %[[CLOCK]][%c12]
// CHECK:       return

// local_step_C: the slot is its offset into the big step over the unit (the
// Unit slot, 13); a sub-step from it evaluates over min(s u, m - offset)
// base steps, so that a block's last sub-step ends with the big step, and
// the clock moves on by the finest sub-step times the unit.
// CHECK-LABEL: func.func @local_step_React(
// CHECK:         %[[SIZE:.*]] = memref.load %arg0[%c1]
// CHECK:         %[[OFFSET:.*]] = arith.subi %{{.*}}, %{{.*}} : i64
// CHECK-NEXT:    %[[STORED:.*]] = memref.load %arg0[%c13]
// CHECK-NEXT:    %[[UNIT:.*]] = arith.maxsi %[[STORED]], %c1_i64
// CHECK-NEXT:    %[[SLOT:.*]] = arith.divui %[[OFFSET]], %[[UNIT]]
// CHECK:         %[[STEPS:.*]] = arith.muli %{{.*}}, %[[UNIT]] : i64
// CHECK-NEXT:    %[[LEFT:.*]] = arith.subi %[[SIZE]], %[[OFFSET]] : i64
// CHECK-NEXT:    %[[LENGTH:.*]] = arith.minsi %[[STEPS]], %[[LEFT]] : i64
// CHECK-NEXT:    arith.trunci %[[LENGTH]] : i64 to i32
// CHECK:         %[[FINEST:.*]] = memref.load %arg0[%c10]
// CHECK-NEXT:    %[[STRIDE:.*]] = arith.muli %[[FINEST]], %[[UNIT]]
// CHECK:       return

// local_parity_C: the parity of ceil(M / s), M the big step in units; the
// last invocation clears the unit request for the next big step.
// CHECK-LABEL: func.func @local_parity_React(
// CHECK:         %[[PSTORED:.*]] = memref.load %arg0[%c13]
// CHECK-NEXT:    %[[PUNIT:.*]] = arith.maxsi %[[PSTORED]], %c1_i64
// CHECK:         arith.divui %{{.*}}, %[[PUNIT]]
// CHECK:         memref.store %c0_i64, %arg0[%c14]
// CHECK:       return
