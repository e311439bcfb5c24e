// Every error sim-translate --gpu-to-ptx reports for input a user can write,
// and the options that select the target. Each case is a file of its own,
// since the options apply to a whole run.
//
// RUN: split-file %s %t
// RUN: sim-translate --gpu-to-ptx %t/no-gpu-module.mlir --verify-diagnostics
// RUN: sim-translate --gpu-to-ptx %t/no-lowering.mlir --verify-diagnostics
// RUN: sim-translate --gpu-to-ptx %t/no-libdevice.mlir --verify-diagnostics \
// RUN:   --sim-cuda-path=%t/no-cuda
// RUN: sim-translate --gpu-to-ptx %t/unknown-chip.mlir --verify-diagnostics \
// RUN:   --sim-chip=sm_999
// RUN: sim-translate --gpu-to-ptx %t/empty-chip.mlir --verify-diagnostics \
// RUN:   --sim-chip=
// RUN: sim-translate --gpu-to-ptx %t/compute-chip.mlir --verify-diagnostics \
// RUN:   --sim-chip=compute_90
// RUN: sim-translate --gpu-to-ptx %t/unroll-zero.mlir --verify-diagnostics \
// RUN:   --sim-gpu-unroll=0
// RUN: sim-translate --gpu-to-ptx %t/unknown-feature.mlir \
// RUN:   --verify-diagnostics --sim-features=+ptx99
// RUN: sim-translate --gpu-to-ptx %t/unsigned-feature.mlir \
// RUN:   --verify-diagnostics --sim-features=ptx80
// RUN: sim-translate --gpu-to-ptx %t/old-chip.mlir --verify-diagnostics \
// RUN:   --sim-chip=sm_60
// RUN: sim-translate --gpu-to-ptx %t/old-ptx.mlir --verify-diagnostics \
// RUN:   --sim-features=+ptx60
// RUN: sim-translate --gpu-to-ptx %t/wide-reduce.mlir --verify-diagnostics \
// RUN:   --sim-chip=sm_75
// RUN: not sim-translate --gpu-to-ptx %t/opt-level.mlir --sim-opt-level=4 \
// RUN:   -o /dev/null 2>&1 | FileCheck %s --check-prefix=OPT-LEVEL
// OPT-LEVEL: sim-translate: for the --sim-opt-level option: '4' is not an optimization level (0 to 3)
// RUN: sim-translate --gpu-to-ptx %t/kernel-name.mlir --verify-diagnostics
//
// Diagnostics are one line and a caret; the failing op is printed only when
// asked for.
// RUN: not sim-translate --gpu-to-ptx %t/unknown-chip.mlir --sim-chip=sm_999 \
// RUN:   -o /dev/null 2>&1 | FileCheck %s --check-prefix=QUIET
// RUN: not sim-translate --gpu-to-ptx %t/unknown-chip.mlir --sim-chip=sm_999 \
// RUN:   --mlir-print-op-on-diagnostic -o /dev/null 2>&1 \
// RUN:   | FileCheck %s --check-prefix=OP
// QUIET: unknown-chip.mlir:3:3: error: unknown NVIDIA GPU 'sm_999'
// QUIET-NOT: see current operation
// OP: unknown-chip.mlir:3:3: error: unknown NVIDIA GPU 'sm_999'
// OP: note: see current operation

//--- no-gpu-module.mlir
// expected-error @+1 {{there is no gpu.module to compile to PTX}}
module {
  func.func @host() {
    return
  }
}

//--- no-lowering.mlir
module attributes {gpu.container_module} {
  gpu.module @kernels {
    gpu.func @narrow(%a: memref<?xi32>) kernel {
      %c0 = arith.constant 0 : index
      %x = memref.load %a[%c0] : memref<?xi32>
      %f = arith.sitofp %x : i32 to f32
      // expected-error @+1 {{'arith.truncf' op was not lowered to the LLVM and NVVM dialects; the PTX pipeline has no lowering for it}}
      %h = arith.truncf %f : f32 to f8E4M3FN
      // expected-error @+1 {{'arith.extf' op was not lowered to the LLVM and NVVM dialects}}
      %g = arith.extf %h : f8E4M3FN to f32
      %y = arith.fptosi %g : f32 to i32
      memref.store %y, %a[%c0] : memref<?xi32>
      gpu.return
    }
  }
}

//--- no-libdevice.mlir
module attributes {gpu.container_module} {
  gpu.module @kernels {
    gpu.func @decay(%a: memref<?xf32>) kernel {
      %c0 = arith.constant 0 : index
      %x = memref.load %a[%c0] : memref<?xf32>
      // expected-error @+1 {{this operation needs the libdevice function '__nv_expf', but there is no libdevice at '}}
      %y = math.exp %x : f32
      // expected-error @+1 {{needs the libdevice function '__nv_logf'}}
      %z = math.log %y : f32
      // expected-error @+1 {{no-cuda/nvvm/libdevice/libdevice.10.bc'; give the CUDA toolkit's root with the pipeline option cuda-path (sim-translate's --sim-cuda-path) or with $CUDA_HOME}}
      %f = math.fma %z, %z, %z : f32
      // Arithmetic needs no libdevice: no error.
      %w = arith.mulf %f, %f : f32
      memref.store %w, %a[%c0] : memref<?xf32>
      gpu.return
    }
  }
}

//--- unknown-chip.mlir
module attributes {gpu.container_module} {
  // expected-error @+1 {{unknown NVIDIA GPU 'sm_999': LLVM's NVPTX back end knows chips such as sm_80, sm_90, sm_90a and sm_100}}
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- empty-chip.mlir
// An empty chip crashed upstream's verifier of #nvvm.target; it is checked
// before the target is attached.
module attributes {gpu.container_module} {
  // expected-error @+1 {{unknown NVIDIA GPU '': LLVM's NVPTX back end knows chips such as sm_80, sm_90, sm_90a and sm_100}}
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- compute-chip.mlir
// A virtual architecture is no chip (upstream said "Minimum NVVM target SM
// version is sm_20").
module attributes {gpu.container_module} {
  // expected-error @+1 {{unknown NVIDIA GPU 'compute_90': LLVM's NVPTX back end knows chips such as sm_80, sm_90, sm_90a and sm_100}}
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- unroll-zero.mlir
// --sim-gpu-unroll=0 was taken as 1, though its help says 1 to 32.
module attributes {gpu.container_module} {
  // expected-error @+1 {{sim-gpu-unroll-loops: the factor must be from 1 to 32, not 0}}
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- unknown-feature.mlir
module attributes {gpu.container_module} {
  // expected-error @+1 {{unknown PTX feature '+ptx99': LLVM's NVPTX back end knows PTX ISA versions such as +ptx78, +ptx80 and +ptx86}}
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- unsigned-feature.mlir
module attributes {gpu.container_module} {
  // expected-error @+1 {{the PTX feature 'ptx80' must start with '+' or '-' (e.g. '+ptx80')}}
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- old-chip.mlir
// Before sm_70 there is no shfl.sync, which the kernels' warp reductions
// need; LLVM aborted the process selecting it.
module attributes {gpu.container_module} {
  // expected-error @+1 {{sim's GPU kernels need sm_70 or later (warp shuffles, shfl.sync), not sm_60}}
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- old-ptx.mlir
// A PTX ISA older than the chip's: LLVM aborted the process.
module attributes {gpu.container_module} {
  // expected-error @+1 {{PTX ISA 6.0 (the features '+ptx60') is older than sm_90 needs: give +ptx78 or later, or no PTX version (the chip's oldest PTX ISA is the default)}}
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- wide-reduce.mlir
// sm_75 has no redux.sync: warp reductions become 32-bit shuffles, which
// cannot carry an i64 (the kernels reduce i32 values only).
module attributes {gpu.container_module} {
  gpu.module @kernels {
    gpu.func @min(%a: memref<?xi64>) kernel {
      %c0 = arith.constant 0 : index
      %x = memref.load %a[%c0] : memref<?xi64>
      // expected-error @+1 {{'gpu.subgroup_reduce' op cannot become warp shuffles of at most 32 bits for a chip without redux.sync (before sm_80); compile for sm_80 or later}}
      %m = gpu.subgroup_reduce minsi %x uniform : (i64) -> i64
      memref.store %m, %a[%c0] : memref<?xi64>
      gpu.return
    }
  }
}

//--- opt-level.mlir
// A level LLVM does not have is refused on the command line (upstream's
// serializer refused it with "Invalid optimization level: 4.").
module attributes {gpu.container_module} {
  gpu.module @kernels {
    gpu.func @empty() kernel {
      gpu.return
    }
  }
}

//--- kernel-name.mlir
// A kernel's name is its PTX .entry, which PTX must be able to spell.
module attributes {gpu.container_module} {
  gpu.module @"my kernels" {
    // expected-error @+1 {{the symbol name "scale by 2" is not a PTX identifier (letters, digits, '_' and '$', not starting with a digit), so no PTX can name it; rename the symbol}}
    gpu.func @"scale by 2"(%a: memref<?xf32>) kernel {
      gpu.return
    }
  }
}
