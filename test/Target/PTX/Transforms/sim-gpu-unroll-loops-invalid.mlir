// A factor outside 1 to 32: each copy of a load loop's body is tens of
// instructions, and 1000 copies did not finish compiling.
// RUN: sim-opt %s --split-input-file --verify-diagnostics --pass-pipeline='builtin.module(gpu.module(sim-gpu-unroll-loops{factor=1000}))'
// RUN: sim-opt %s --split-input-file --verify-diagnostics --pass-pipeline='builtin.module(gpu.module(sim-gpu-unroll-loops{factor=0}))'
// On the file's top module, which has no location of its own ("file:0:0"),
// the error is at its first operation.
// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-gpu-unroll-loops=factor=0

// expected-error-re @+1 {{sim-gpu-unroll-loops: the factor must be from 1 to 32, not {{(1000|0)}}}}
gpu.module @kernels {
  func.func @empty() {
    return
  }
}
