// Math functions that lower to libdevice calls (__nv_expf, __nv_sqrtf, ...),
// on scalars and on vector<4xf32> items (scalarized), and one that lowers to
// an LLVM intrinsic (math.fma).
module attributes {gpu.container_module} {
  gpu.module @math_kernels {
    gpu.func @decay(%x: memref<?xvector<4xf32>>, %rate: memref<?xf32>,
                    %n: index) kernel {
      %tid = gpu.thread_id x
      %bid = gpu.block_id x
      %bdim = gpu.block_dim x
      %first = arith.muli %bid, %bdim : index
      %i = arith.addi %first, %tid : index
      %in_range = arith.cmpi ult, %i, %n : index
      scf.if %in_range {
        %v = memref.load %x[%i] : memref<?xvector<4xf32>>
        %r = memref.load %rate[%i] : memref<?xf32>
        %neg = arith.negf %r : f32
        %e = math.exp %neg : f32
        %s = math.sqrt %e : f32
        %sv = vector.broadcast %s : f32 to vector<4xf32>
        %ev = math.exp %v : vector<4xf32>
        %rv = math.sqrt %ev : vector<4xf32>
        %w = math.fma %rv, %sv, %v : vector<4xf32>
        memref.store %w, %x[%i] : memref<?xvector<4xf32>>
      }
      gpu.return
    }
  }
}
