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

// -----

// Names PTX cannot spell. LLVM's NVPTX printer would abort on a space and
// print a leading digit or a lone `_` that ptxas rejects. Kernels and other
// external symbols keep their names (a host looks kernels up by them), so
// each is an error at the symbol; LLVM renames the other characters of
// private and internal symbols itself, but not a leading digit.
gpu.module @names {
  // expected-error @+1 {{the symbol name "k 1" is not a PTX identifier (letters, digits, '_' and '$', not starting with a digit), so no PTX can name it; rename the symbol}}
  llvm.func @"k 1"() attributes {gpu.kernel, nvvm.kernel} {
    llvm.return
  }
  // expected-error @+1 {{the symbol name "1k" is not a PTX identifier}}
  llvm.func @"1k"() attributes {gpu.kernel, nvvm.kernel} {
    llvm.return
  }
  // expected-error @+1 {{the symbol name "_" is not a PTX identifier}}
  llvm.mlir.global external @_(0 : i32) {addr_space = 1 : i32} : i32
  // expected-error @+1 {{the symbol name "2.x" is not a PTX identifier}}
  llvm.mlir.global private @"2.x"(0 : i32) {addr_space = 1 : i32} : i32
  // Valid, or made valid by LLVM: no error.
  llvm.func @k_$1() attributes {gpu.kernel, nvvm.kernel} {
    llvm.return
  }
  llvm.mlir.global private @"a b.c"(0 : i32) {addr_space = 1 : i32} : i32
  llvm.func internal @"helper.1"() {
    llvm.return
  }
}
