// A plan for many processes under lts (--sim-front-end="strategy=lts
// distributed=true"): every rank limits the levels of the blocks within its
// level reach from the maximum of the ranks' codes there (reduce_max_levels
// on limit_levels_C),
// the ghost items of the local_steps component's buffers travel after
// every slot launch (those of the blocks that started a sub-step at the
// slot, in the half each wrote) and after local_parity_C (the target
// half), a read through the time levels of another item finds it in the
// rank's block or its ghost items (item - first + halo, clamped into the
// rank's storage), and the slot kernel's last invocation counts the
// rank's items (extent - 2 * halo) on both targets, which therefore take
// the same arguments.
//
// RUN: sim-opt %s --sim-front-end="strategy=lts distributed=true" --sim-lower-to-cpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end="strategy=lts distributed=true" --sim-lower-to-gpu | FileCheck %s --check-prefix=GPU

sim.simulation @rod range(100) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 interp(#sim.linear) boundary(clamp) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Rod writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c50 = arith.constant 50 : index
    %c1 = arith.constant 1 : i32
    %c4 = arith.constant 4 : i32
    %stiff = arith.cmpi ult, %i, %c50 : index
    %n = arith.select %stiff, %c1, %c4 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %left = sim.read @U[%l] : f32
    %right = sim.read @U[%r] : f32
    %u = sim.read @U[%i] : f32
    %s = arith.addf %left, %right : f32
    %v = arith.addf %s, %u : f32
    sim.yield %v : f32
  }
  sim.observe [@U]
}

// The slot kernel's last invocation: the items of its groups (first to end
// times the group size, up to the rank's extent less 2 ghost items) into
// the sub-step clock's count slot; the one that completes the rank's items
// moves the clock to the next slot.
// CHECK-LABEL: func.func @local_step_Rod(
// CHECK-SAME:    %[[CLOCK:[a-z0-9]+]]: memref<?xi64>, %{{.*}}: memref<?xf32>, %{{.*}}: memref<?xi64>, %{{.*}}: i64, %{{.*}}: i64, %{{.*}}: i64, %[[FIRSTG:[a-z0-9]+]]: i64, %[[ENDG:[a-z0-9]+]]: i64, %[[SIZE:[a-z0-9]+]]: i64)
// CHECK:         %[[ITEMS:.*]] = arith.subi %{{.*}}, %c2 : index
// CHECK:         %[[TOTAL:.*]] = arith.index_cast %[[ITEMS]] : index to i64
// CHECK:         %[[ENDI:.*]] = arith.muli %[[ENDG]], %[[SIZE]] : i64
// CHECK:         %[[CLIP:.*]] = arith.minsi %[[ENDI]], %[[TOTAL]] : i64
// CHECK:         %[[FIRSTI:.*]] = arith.muli %[[FIRSTG]], %[[SIZE]] : i64
// CHECK:         %[[MINE:.*]] = arith.subi %[[CLIP]], %[[FIRSTI]] : i64
// CHECK:         %[[BEFORE:.*]] = memref.atomic_rmw addi %[[MINE]], %[[CLOCK]][%c11]
// CHECK:         %[[AFTER:.*]] = arith.addi %[[BEFORE]], %[[MINE]] : i64
// CHECK:         arith.cmpi eq, %[[AFTER]], %[[TOTAL]] : i64

// The plan: the all-reduce of the levels before limit_levels_Rod (which
// every rank runs over the blocks within its level reach, spread over
// the lanes of its block), the exchange of @U after
// every slot launch (the blocks the slot started, exchange_local_step) and
// after the parity copy (its target half).
// Its codes come from the blocks within 161 items of a rank's block: the
// ghost items (1), the window's radius (1 block) and the limit's reach
// (2 neighbour steps of 1 block for max_steps 4), a block more on each
// side: 1 + 32 * (2 + 1 + 2). Its num_steps reads the item only, so its
// kernels keep the codes (keeps_levels), which the ranks then gather for
// one big step.
// CHECK-LABEL: simplan.plan
// CHECK:       simplan.component @Rod writes [@U] evaluations({{[0-9]+}}) advance local_steps sub_clock({{[0-9]+}}) level_reach(161) keeps_levels{{$}}
// CHECK:       simplan.launch @rod_kernels::@levels_Rod items [#simplan.arg<clock>, #simplan.arg<levels @Rod>, #simplan.arg<range>, #simplan.arg<first>]{{$}}
// CHECK-NEXT:  simplan.launch @rod_kernels::@limit_levels_Rod items [#simplan.arg<clock>, #simplan.arg<levels @Rod>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] reduce_max_levels [@Rod]
// CHECK-NEXT:  simplan.repeat 4 {
// CHECK-NEXT:    simplan.launch @rod_kernels::@local_step_Rod items [#simplan.arg<clock>, #simplan.arg<buffer @U>, #simplan.arg<levels @Rod>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] for @Rod exchange_local_step [@U]
// CHECK-NEXT:  }
// CHECK-NEXT:  simplan.launch @rod_kernels::@local_parity_Rod items [{{.*}}] for @Rod exchange_targets [@U]

// On the GPU a thread group counts its items of the rank's block (the
// block's items from its base, at most the group size), so the kernels of
// both targets take the same arguments.
// GPU-LABEL: gpu.func @local_step_Rod(
// GPU:         gpu.barrier
// GPU:         %[[SIZE:.*]] = arith.index_cast %block_dim_x : index to i64
// GPU:         %[[GROUP:.*]] = arith.index_cast %block_id_x : index to i64
// GPU:         %[[BASE:.*]] = arith.muli %[[GROUP]], %[[SIZE]] : i64
// GPU:         %[[ITEMS:.*]] = arith.subi %{{.*}}, %c2 : index
// GPU:         %[[TOTAL:.*]] = arith.index_cast %[[ITEMS]] : index to i64
// GPU:         %[[LEFT:.*]] = arith.subi %[[TOTAL]], %[[BASE]] : i64
// GPU:         %[[MINE:.*]] = arith.minsi %[[SIZE]], %[[LEFT]] : i64
// GPU:         memref.atomic_rmw addi %[[MINE]]
// GPU-LABEL: simplan.plan
// GPU:         simplan.launch @rod_kernels::@limit_levels_Rod items [#simplan.arg<clock>, #simplan.arg<levels @Rod>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] reduce_max_levels [@Rod]
// GPU-NEXT:    simplan.repeat
// GPU:         simplan.launch @rod_kernels::@local_step_Rod items [#simplan.arg<clock>, #simplan.arg<buffer @U>, #simplan.arg<levels @Rod>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] for @Rod exchange_local_step [@U]
