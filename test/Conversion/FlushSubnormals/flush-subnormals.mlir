// RUN: sim-opt %s --sim-flush-subnormals --split-input-file | FileCheck %s

// Every function with a body flushes subnormals, results and operands, f32
// and every other type alike.
// CHECK-LABEL: llvm.func @kernel
// CHECK-SAME: denormal_fp_math = "preserve-sign"
// CHECK-SAME: denormal_fp_math_f32 = "preserve-sign"
llvm.func @kernel(%a: f32, %b: f32) -> f32 {
  %r = llvm.fmul %a, %b : f32
  llvm.return %r : f32
}

// -----

// A declaration (libm, libdevice) is not ours to mark.
// CHECK-LABEL: llvm.func @tanhf
// CHECK-NOT: denormal_fp_math
// CHECK-LABEL: llvm.func @caller
// CHECK-SAME: denormal_fp_math = "preserve-sign"
llvm.func @tanhf(f32) -> f32
llvm.func @caller(%a: f32) -> f32 {
  %r = llvm.call @tanhf(%a) : (f32) -> f32
  llvm.return %r : f32
}

// -----

// Functions nested in a gpu.module too.
// CHECK-LABEL: gpu.module @kernels
// CHECK: llvm.func @scale
// CHECK-SAME: denormal_fp_math_f32 = "preserve-sign"
module attributes {gpu.container_module} {
  gpu.module @kernels {
    llvm.func @scale(%a: f32) -> f32 {
      llvm.return %a : f32
    }
  }
}
