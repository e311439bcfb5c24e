// RUN: sim-opt %s --split-input-file --pass-pipeline='builtin.module(gpu.module(sim-nvvm-set-data-layout))' | FileCheck %s
// RUN: sim-translate --gpu-to-ptx %s --split-input-file -o - | FileCheck %s --check-prefix=PTX

// A gpu.module gets NVPTX's data layout, so that the translation to LLVM IR
// aligns an i64 access to 8 bytes: one 64-bit load and store. With LLVM's
// default layout (i64 aligned to 4) the NVPTX back end split each into two
// 32-bit accesses.

// CHECK-LABEL: gpu.module @kernels
// CHECK-SAME: llvm.data_layout = "e-{{.*}}i64:64{{.*}}"
// PTX-LABEL: .entry copy_slot(
// PTX-NOT: ld.global.b32
// PTX: ld.global.b64
// PTX-NOT: st.global.b32
// PTX: st.global.b64
module attributes {gpu.container_module} {
  gpu.module @kernels {
    gpu.func @copy_slot(%clock: memref<?xi64>) kernel {
      %c0 = arith.constant 0 : index
      %c1 = arith.constant 1 : index
      %v = memref.load %clock[%c0] : memref<?xi64>
      memref.store %v, %clock[%c1] : memref<?xi64>
      gpu.return
    }
  }
}

// -----

// A module that has a data layout keeps it.

// CHECK-LABEL: gpu.module @own_layout
// CHECK-SAME: llvm.data_layout = "e-i64:64"
module attributes {gpu.container_module} {
  gpu.module @own_layout attributes {llvm.data_layout = "e-i64:64"} {
  }
}
