// hip-cache on the GPU: the group fills a shared-memory cache of the window
// once per sub-step (every lane takes slots, the block size apart), waits,
// and reads the window from it. Which reads are inside the window the
// front end records (in_window on the cache load, from the dependency
// analysis): the window loop's, and a read clamped around the item,
// whatever it clamps. Any other read (here a gather) checks, with a
// fallback to the interpolation from global memory outside the cache. The
// launch asks for the dynamic shared memory: 4 bytes per thread plus the
// halo of 2 items.
//
// RUN: sim-opt %s --sim-front-end=strategy=hip-cache --sim-lower-to-gpu | FileCheck %s
// RUN: sim-opt %s --sim-front-end=strategy=hip-cache --sim-lower-to-cpu | FileCheck %s --check-prefix=CPU

sim.simulation @smooth range(10) dt(1.0e-1 : f32) max_steps(4) {
  sim.param @lead = 3 : i32
  sim.buffer @U : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f32
    sim.yield %x : f32
  }
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @Drive writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = sim.get_param @lead : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %s = sim.read @S[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %d = arith.mulf %h, %s : f32
    %next = arith.addf %u, %d : f32
    sim.yield %next : f32
  }
  sim.component @Smooth writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -1 : index
    %hi = arith.constant 2 : index
    %one = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %sum = scf.for %k = %lo to %hi step %one iter_args(%acc = %zero) -> (f32) {
      %j = arith.addi %i, %k : index
      %u = sim.read @U[%j] : f32
      %next = arith.addf %acc, %u : f32
      scf.yield %next : f32
    }
    %s = sim.read @S[%i] : f32
    %lead = sim.get_param @lead : i32
    %lead_index = arith.index_cast %lead : i32 to index
    %far = arith.addi %i, %lead_index : index
    %below = arith.subi %i, %one : index
    %above = arith.addi %i, %one : index
    %low = arith.maxsi %far, %below : index
    %partner = arith.minsi %low, %above : index
    %u_partner = sim.read @U[%partner] : f32
    %u_far = sim.read @U[%far] : f32
    %sum_partner = arith.addf %sum, %u_partner : f32
    %sum_far = arith.addf %sum_partner, %u_far : f32
    %avg = arith.addf %sum_far, %s : f32
    sim.yield %avg : f32
  }
  sim.schedule [@Drive]
  sim.observe [@S]
}

// The kernel records the shared memory its launches ask for.
// CHECK-LABEL: gpu.func @substep_Smooth(
// CHECK-SAME:      %{{[^:]*}}: memref<?xi64>, %[[U:[^:]*]]: memref<?xf32>
// CHECK-SAME:      kernel attributes {simplan.clock_slots = 15 : i64, simplan.shared = array<i64: 4, 8>}
// CHECK:         %[[SHARED:.*]] = gpu.dynamic_shared_memory : memref<?xi8, #gpu.address_space<workgroup>>
// CHECK:         %[[CACHE:.*]] = memref.view %[[SHARED]][%c0][%{{.*}}] : memref<?xi8, #gpu.address_space<workgroup>> to memref<?xf32, #gpu.address_space<workgroup>>
// CHECK:         scf.while
//                  The sub-step, then (after the m = 1 barrier) the fill.
// CHECK:           gpu.subgroup_reduce minsi
// CHECK:           gpu.barrier
// CHECK:           scf.if %{{.*}} {
// CHECK-NEXT:        gpu.barrier
// CHECK-NEXT:      }
// CHECK:           %[[TID:.*]] = gpu.thread_id x
// CHECK:           %[[BDIM:.*]] = gpu.block_dim x
// CHECK:           scf.for %[[SLOT:.*]] = %[[TID]] to %{{.*}} step %[[BDIM]] {
// CHECK:             memref.load %[[U]]
// CHECK:             memref.load %[[U]]
// CHECK:             memref.store %{{.*}}, %[[CACHE]][%[[SLOT]]]
// CHECK:           }
// CHECK-NEXT:      gpu.barrier
//                  Reads of the item plus an offset in the window always hit
//                  the cache: no check, no fallback.
// CHECK:           scf.for
// CHECK:             %[[J:.*]] = arith.addi %{{.*}}, %{{.*}} : index
// CHECK-NEXT:        %[[OFFSET:.*]] = arith.subi %[[J]], %{{.*}} : index
// CHECK-NEXT:        memref.load %[[CACHE]][%[[OFFSET]]]
// CHECK-NOT:         scf.if
// CHECK:           }
//                  So does a read clamped around the item (in_window).
// CHECK:           %[[PARTNER:.*]] = arith.minsi %{{.*}}, %{{.*}} : index
// CHECK-NEXT:      %[[PARTNER_OFFSET:.*]] = arith.subi %[[PARTNER]], %{{.*}} : index
// CHECK-NEXT:      memref.load %[[CACHE]][%[[PARTNER_OFFSET]]]
//                  The gather checks.
// CHECK:           %[[FAR_OFFSET:.*]] = arith.subi
// CHECK-NEXT:      %[[INSIDE:.*]] = arith.cmpi ult, %[[FAR_OFFSET]]
// CHECK-NEXT:      scf.if %[[INSIDE]] -> (f32) {
// CHECK-NEXT:        %[[HIT:.*]] = memref.load %[[CACHE]][%[[FAR_OFFSET]]]
// CHECK-NEXT:        scf.yield %[[HIT]]
// CHECK-NEXT:      } else {
// CHECK:             memref.load %[[U]]
// CHECK:             memref.load %[[U]]
// CHECK-LABEL: simplan.plan @smooth strategy("hip-cache")
// CHECK:         simplan.launch @smooth_kernels::@substep_Smooth items [{{.*}}] for @Smooth shared(4, 8)

// The CPU keeps the cache on the stack of the call (the group size plus the
// halo of 2 items): a loop of lanes fills it (once for a big step of 1, once
// per sub-step otherwise) and the window reads load it. The plan is the
// same (the CPU runtime ignores the shared bytes).
// CPU-LABEL: func.func @substep_Smooth(
// CPU-SAME:      attributes {simplan.clock_slots = 15 : i64, simplan.group_arguments = 3 : i64, simplan.shared = array<i64: 4, 8>}
// CPU-NOT:     memref.view
// CPU:         %[[COUNT:.*]] = arith.addi %{{.*}}, %c2 : index
// CPU:         %[[CACHE:.*]] = memref.alloca(%[[COUNT]]) : memref<?xf32>
// CPU:         scf.for %[[SLOT:.*]] = %c0 to %{{.*}} step %c1 {
// CPU:           memref.store %{{.*}}, %[[CACHE]][%[[SLOT]]] : memref<?xf32>
// CPU:         } {simplan.lanes}
// CPU:         memref.load %[[CACHE]][%{{.*}}] : memref<?xf32>
// CPU:         scf.while
// CPU:         scf.for %[[SLOT2:.*]] = %c0 to %{{.*}} step %c1 {
// CPU:           memref.store %{{.*}}, %[[CACHE]][%[[SLOT2]]] : memref<?xf32>
// CPU:         } {simplan.lanes}
// CPU-LABEL: simplan.plan @smooth strategy("hip-cache")
// CPU:         simplan.launch @smooth_kernels::@substep_Smooth items [{{.*}}] for @Smooth shared(4, 8)
