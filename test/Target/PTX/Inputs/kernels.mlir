// Kernels with the constructs the lowering of sim.simulation emits, written
// by hand: a grid-stride loop over vector<4xf32> items, the minimum of the
// step counts over a thread group (warp reduction, then atomic minimum and
// add on workgroup attributions between barriers, then global atomics),
// and a shared-memory cache in dynamic shared memory next to a workgroup
// attribution. No math function, so no libdevice is needed.
module attributes {gpu.container_module} {
  gpu.module @scene_kernels {
    // Advances every item: dst[i] = src[i] * dt + dst[i], for i in a
    // grid-stride loop.
    gpu.func @advance(%src: memref<?xvector<4xf32>>,
                      %dst: memref<?xvector<4xf32>>, %n: index, %dt: f32)
        kernel {
      %tid = gpu.thread_id x
      %bid = gpu.block_id x
      %bdim = gpu.block_dim x
      %gdim = gpu.grid_dim x
      %first = arith.muli %bid, %bdim : index
      %start = arith.addi %first, %tid : index
      %stride = arith.muli %bdim, %gdim : index
      %dtv = vector.broadcast %dt : f32 to vector<4xf32>
      scf.for %i = %start to %n step %stride {
        %x = memref.load %src[%i] : memref<?xvector<4xf32>>
        %y = memref.load %dst[%i] : memref<?xvector<4xf32>>
        %z = vector.fma %x, %dtv, %y : vector<4xf32>
        memref.store %z, %dst[%i] : memref<?xvector<4xf32>>
      }
      gpu.return
    }

    // The minimum of steps[i] over the group (padding threads contribute
    // INT_MAX, since every lane must take part in the reduction), then over
    // the grid into min[0]; count[0] counts the warps that took part.
    gpu.func @min_steps(%steps: memref<?xi32>, %min: memref<?xi64>,
                        %count: memref<?xi64>, %n: index)
        workgroup(%group_min: memref<1xi32, #gpu.address_space<workgroup>>,
                  %group_warps: memref<1xi32, #gpu.address_space<workgroup>>)
        kernel {
      %c0 = arith.constant 0 : index
      %c0_i32 = arith.constant 0 : i32
      %c1_i32 = arith.constant 1 : i32
      %int_max = arith.constant 2147483647 : i32
      %tid = gpu.thread_id x
      %bid = gpu.block_id x
      %bdim = gpu.block_dim x
      %lane = gpu.lane_id
      %first = arith.muli %bid, %bdim : index
      %i = arith.addi %first, %tid : index
      %in_range = arith.cmpi ult, %i, %n : index
      %own = scf.if %in_range -> i32 {
        %s = memref.load %steps[%i] : memref<?xi32>
        scf.yield %s : i32
      } else {
        scf.yield %int_max : i32
      }
      %is_first = arith.cmpi eq, %tid, %c0 : index
      scf.if %is_first {
        memref.store %int_max, %group_min[%c0]
            : memref<1xi32, #gpu.address_space<workgroup>>
        memref.store %c0_i32, %group_warps[%c0]
            : memref<1xi32, #gpu.address_space<workgroup>>
      }
      gpu.barrier
      %warp_min = gpu.subgroup_reduce minsi %own uniform : (i32) -> i32
      %is_lane0 = arith.cmpi eq, %lane, %c0 : index
      scf.if %is_lane0 {
        %old_min = memref.atomic_rmw mins %warp_min, %group_min[%c0]
            : (i32, memref<1xi32, #gpu.address_space<workgroup>>) -> i32
        %old_warps = memref.atomic_rmw addi %c1_i32, %group_warps[%c0]
            : (i32, memref<1xi32, #gpu.address_space<workgroup>>) -> i32
      }
      gpu.barrier
      scf.if %is_first {
        %m = memref.load %group_min[%c0]
            : memref<1xi32, #gpu.address_space<workgroup>>
        %m64 = arith.extsi %m : i32 to i64
        %old_min = memref.atomic_rmw mins %m64, %min[%c0]
            : (i64, memref<?xi64>) -> i64
        %w = memref.load %group_warps[%c0]
            : memref<1xi32, #gpu.address_space<workgroup>>
        %w64 = arith.extsi %w : i32 to i64
        %old_count = memref.atomic_rmw addi %w64, %count[%c0]
            : (i64, memref<?xi64>) -> i64
      }
      gpu.return
    }

    // Caches src[first - 1 .. first + group] in dynamic shared memory and
    // averages each item with its neighbours from the cache; the group's
    // item count goes through a workgroup attribution.
    gpu.func @smooth(%src: memref<?xf32>, %dst: memref<?xf32>, %n: index)
        workgroup(%items: memref<1xindex, #gpu.address_space<workgroup>>)
        kernel {
      %c0 = arith.constant 0 : index
      %c1 = arith.constant 1 : index
      %c2 = arith.constant 2 : index
      %third = arith.constant 0.333333343 : f32
      %tid = gpu.thread_id x
      %bid = gpu.block_id x
      %bdim = gpu.block_dim x
      %first = arith.muli %bid, %bdim : index
      %i = arith.addi %first, %tid : index
      %width = arith.addi %bdim, %c2 : index
      %bytes = gpu.dynamic_shared_memory
          : memref<?xi8, #gpu.address_space<workgroup>>
      %cache = memref.view %bytes[%c0][%width]
          : memref<?xi8, #gpu.address_space<workgroup>>
            to memref<?xf32, #gpu.address_space<workgroup>>
      %is_first = arith.cmpi eq, %tid, %c0 : index
      scf.if %is_first {
        memref.store %bdim, %items[%c0]
            : memref<1xindex, #gpu.address_space<workgroup>>
      }
      // Thread t loads item first + t - 1 (clamped) into cache[t], and the
      // last two threads the two items after the group.
      scf.for %k = %tid to %width step %bdim {
        %j = arith.addi %first, %k : index
        %jm = arith.maxsi %j, %c1 : index
        %jp = arith.subi %jm, %c1 : index
        %nm = arith.subi %n, %c1 : index
        %jc = arith.minsi %jp, %nm : index
        %v = memref.load %src[%jc] : memref<?xf32>
        memref.store %v, %cache[%k]
            : memref<?xf32, #gpu.address_space<workgroup>>
      }
      gpu.barrier
      %count = memref.load %items[%c0]
          : memref<1xindex, #gpu.address_space<workgroup>>
      %in_group = arith.cmpi ult, %tid, %count : index
      %in_range = arith.cmpi ult, %i, %n : index
      %active = arith.andi %in_group, %in_range : i1
      scf.if %active {
        %r = arith.addi %tid, %c2 : index
        %a = memref.load %cache[%tid]
            : memref<?xf32, #gpu.address_space<workgroup>>
        %b = memref.load %cache[%r]
            : memref<?xf32, #gpu.address_space<workgroup>>
        %m = arith.addi %tid, %c1 : index
        %c = memref.load %cache[%m]
            : memref<?xf32, #gpu.address_space<workgroup>>
        %ab = arith.addf %a, %b : f32
        %abc = arith.addf %ab, %c : f32
        %avg = arith.mulf %abc, %third : f32
        memref.store %avg, %dst[%i] : memref<?xf32>
      }
      gpu.return
    }
  }
}
