// RUN: sim-opt %s --split-input-file --verify-diagnostics \
// RUN:   --pass-pipeline='builtin.module(gpu.module(sim-nvvm-check-target{libdevice=%t.missing.bc}))' \
// RUN:   | FileCheck %s

// A module that is all LLVM and NVVM, for a chip and features LLVM knows and
// without libdevice calls, passes unchanged.
// CHECK-LABEL: gpu.module @kernels [#nvvm.target<O = 3, chip = "sm_90a", features = "+ptx80,-ptx86">]
// CHECK: llvm.func @k()
gpu.module @kernels [#nvvm.target<O = 3, chip = "sm_90a", features = "+ptx80,-ptx86">] {
  llvm.func @k() attributes {gpu.kernel, nvvm.kernel} {
    %0 = nvvm.read.ptx.sreg.tid.x : i32
    llvm.return
  }
}

// -----

gpu.module @no_target {
  // Declared but never called: no error.
  llvm.func @__nv_expf(f32) -> f32
  llvm.func @k(%x: f32) -> f32 {
    // expected-error @+1 {{this operation needs the libdevice function '__nv_sqrtf', but there is no libdevice at}}
    %0 = llvm.call @__nv_sqrtf(%x) : (f32) -> f32
    %1 = llvm.call @__nv_sqrtf(%0) : (f32) -> f32
    llvm.return %1 : f32
  }
  llvm.func @__nv_sqrtf(f32) -> f32
}

// -----

// expected-error @+1 {{unknown NVIDIA GPU 'sm_91': LLVM's NVPTX back end knows chips such as sm_80, sm_90, sm_90a and sm_100}}
gpu.module @bad_chip [#nvvm.target<chip = "sm_91">] {
}

// -----

// expected-error @+1 {{unknown PTX feature '+avx2': LLVM's NVPTX back end knows PTX ISA versions such as +ptx78, +ptx80 and +ptx86}}
gpu.module @bad_feature [#nvvm.target<chip = "sm_90", features = "+ptx80,+avx2">] {
}

// -----

gpu.module @not_lowered {
  llvm.func @k(%x: i32) -> i32 {
    // expected-error @+1 {{'arith.addi' op was not lowered to the LLVM and NVVM dialects; the PTX pipeline has no lowering for it}}
    %0 = arith.addi %x, %x : i32
    // One error per kind of operation.
    %1 = arith.addi %0, %x : i32
    llvm.return %1 : i32
  }
}
