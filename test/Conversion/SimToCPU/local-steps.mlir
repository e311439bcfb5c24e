// The CPU kernels of local time steps (strategy lts): levels_C folds the
// lanes of each block before one atomic maximum per block and group (its
// lanes' phase has no atomic, so --sim-vectorize-lanes widens it);
// limit_levels_C decodes, limits (sweeps), codes and finds the runs in one
// pass of one lane (on the GPU a lane per block: below);
// local_step_C and local_parity_C walk the runs of blocks across the
// invocation's groups (scf.while) and run a run's lanes as one loop.
//
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-gpu | FileCheck %s --check-prefix=GPU
// RUN: sim-opt %s --sim-front-end=strategy=lts --sim-lower-to-cpu \
// RUN:   | sim-opt --sim-vectorize-lanes="width=8 report=true" -o /dev/null 2>&1 \
// RUN:   | FileCheck %s --check-prefix=WIDE --implicit-check-not="lanes stay scalar"

sim.simulation @rod range(100) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @U : f32 init {
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

// levels_C: the lanes store their codes (into an array that is not zeroed
// first: every active lane stores one); then per block the maximum of its
// lanes, a plain one where the block lies wholly in the group (no other
// group writes it, and no flux writer's codes join it), else an atomic.
// Where the group starts on a block boundary its whole blocks take a
// vector maximum each; the lanes of the rest (a block the range cuts
// short) are folded one by one.
// CHECK-LABEL: func.func @levels_Diffuse(
// CHECK:         %[[CODES:.*]] = memref.alloca(%{{.*}}) : memref<?xi64>
// CHECK-NOT:     memref.store {{.*}}, %[[CODES]]
// CHECK-NOT:     memref.atomic_rmw
// CHECK:         memref.store %{{[0-9]+}}, %[[CODES]]
// CHECK:         } {simplan.lanes}
// CHECK:         %[[WHOLE:.*]] = vector.load %[[CODES]][%{{.*}}] : memref<?xi64>, vector<32xi64>
// CHECK-NEXT:    %[[LARGEST:.*]] = vector.reduction <maxsi>, %[[WHOLE]] : vector<32xi64> into i64
// CHECK:         %[[BEFORE:.*]] = memref.load %arg1
// CHECK-NEXT:    %[[MAXED:.*]] = arith.maxsi %[[BEFORE]], %[[LARGEST]]
// CHECK-NEXT:    memref.store %[[MAXED]], %arg1
// CHECK-NOT:     memref.atomic_rmw
// CHECK:         scf.for
// CHECK:           %[[LANES:.*]] = scf.for
// CHECK:             arith.maxsi
// CHECK:           scf.if
// CHECK-NEXT:        %[[OLD:.*]] = memref.load %arg1
// CHECK-NEXT:        %[[MAX:.*]] = arith.maxsi %[[OLD]], %[[LANES]]
// CHECK-NEXT:        memref.store %[[MAX]], %arg1
// CHECK-NEXT:      } else {
// CHECK-NEXT:        memref.atomic_rmw maxs %[[LANES]], %arg1
// CHECK:       return

// limit_levels_C: on the CPU one lane (block 0's) takes every block in one
// pass: decode, the sweeps (one each way, as the rod does not wrap), the
// finest with the codes, the runs (from the last block back). @Diffuse's levels never change
// (invariant_levels): once its codes are kept and while m is the m of the
// last pass (block 0's entry of code half 0), the pass is not repeated and
// the finest sub-step kept in half 1 goes to the sub-step clock's Size.
// The group's lanes stop at the block count: a lane past it takes no block.
// CHECK-LABEL: func.func @limit_levels_Diffuse(
// CHECK-SAME:      %[[CLOCK:arg0]]: memref<?xi64>, %[[LEVELS:arg1]]: memref<?xi64>
// CHECK:           %[[M:.*]] = memref.load %[[CLOCK]][%c1] : memref<?xi64>
// CHECK:           %[[BLOCKS:.*]] = arith.addi %{{.*}}, %c0 : index
// CHECK:           %[[HIGH:.*]] = arith.minsi %{{.*}}, %[[BLOCKS]] : index
// CHECK:           scf.for %{{.*}} = %{{.*}} to %[[HIGH]] step %c1 {
// CHECK:               scf.for %{{.*}} = %arg{{[0-9]+}} to %[[BLOCKS]] step %{{[0-9]+}} {
// CHECK:                 scf.if
// CHECK:                   %[[KEPT:.*]] = arith.cmpi ne, %{{.*}}, %c0_i64 : i64
// CHECK:                   %[[LAST:.*]] = memref.load %[[LEVELS]][%{{.*}}] : memref<?xi64>
// CHECK:                   %[[SAME_M:.*]] = arith.cmpi eq, %[[LAST]], %[[M]] : i64
// CHECK:                   %[[REUSE:.*]] = arith.andi %[[KEPT]], %[[SAME_M]] : i1
// CHECK:                   scf.if %[[REUSE]] {
// CHECK-NEXT:                %[[FINEST:.*]] = memref.load %[[LEVELS]][%{{.*}}] : memref<?xi64>
// CHECK-NEXT:                memref.store %[[FINEST]], %[[CLOCK]][%{{.*}}] : memref<?xi64>
// CHECK-NEXT:              } else {
// CHECK:                   scf.for
// The rod does not wrap: one sweep forward, one backward, no fixpoint loop.
// CHECK-NOT:               scf.while
// CHECK:                   %[[FORWARD:.*]] = scf.for {{.*}} iter_args(%{{.*}} = %false) -> (i1)
// CHECK-NOT:               scf.while
// CHECK:                   scf.for {{.*}} iter_args(%{{.*}} = %[[FORWARD]]) -> (i1)
// CHECK-NOT:               scf.while
// CHECK:                   scf.for {{.*}} iter_args
// CHECK:                   memref.store {{.*}} : memref<?xi64>
// CHECK:                   scf.for
// CHECK:       return

// local_step_C: runs across groups, each run's lanes as one loop (those of
// a run next to another sub-step through the time levels), counted at once:
// no evaluation count per lane.
// Its groups' work differs within a launch (only the blocks due at the
// slot evaluate), recorded for the runtime's split over threads.
// CHECK-LABEL: func.func @local_step_Diffuse(
// CHECK-SAME:    simplan.uneven_groups
// CHECK-NOT:     memref.alloca
// CHECK:         scf.while
// CHECK:             } {simplan.lanes}
// CHECK:             memref.atomic_rmw addi
// CHECK-NOT:     memref.alloca
// CHECK:       return

// CHECK-LABEL: func.func @local_parity_Diffuse(
// CHECK-NOT:     simplan.uneven_groups
// CHECK:         scf.while
// CHECK:       return

// Every lanes loop of the lts kernels is widened.
// WIDE-COUNT-9: lanes run 8 at a time

// On the GPU the same limit and codes, a thread per block: thread k of the
// launch takes blocks k, k + range, ... (so one), in groups that start
// below the blocks; no runs of codes (only a CPU walks them).
// GPU-LABEL: gpu.func @limit_levels_Diffuse(
// GPU:         gpu.thread_id x
// GPU:         scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} {
// GPU:           scf.for %{{.*}} = %c1_i64 to %c4_i64 step %c1_i64 iter_args
// GPU:           memref.atomic_rmw mins
// GPU-NOT:       memref.atomic_rmw
// GPU:       gpu.return
