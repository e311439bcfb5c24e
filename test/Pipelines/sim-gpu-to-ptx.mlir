// The GPU back end as a pass pipeline: every gpu.module becomes a gpu.binary
// holding PTX for the chosen target; everything outside the gpu.modules is
// left alone.
//
// RUN: sim-opt %s --sim-gpu-to-ptx | FileCheck %s
// RUN: sim-opt %s --sim-gpu-to-ptx="chip=sm_80 features=+ptx80 opt-level=1" \
// RUN:   | FileCheck %s --check-prefix=OPTIONS
//
// The passes, in order (upstream's, plus the two sim-nvvm ones):
// RUN: sim-opt %s --sim-gpu-to-ptx --dump-pass-pipeline -o /dev/null 2>&1 \
// RUN:   | FileCheck %s --check-prefix=PIPELINE

// CHECK-LABEL: module attributes {gpu.container_module}
// CHECK:       gpu.binary @kernels [#gpu.object<#nvvm.target<O = 3, chip = "sm_90">, properties = {{.*}}, assembly = "
// CHECK-SAME:    .version 7.8\0A.target sm_90\0A
// CHECK-SAME:    .visible .entry scale(
// CHECK-NOT:   gpu.module
// CHECK:       func.func @host(%{{.*}}: memref<?xf32>)
// CHECK:         scf.for

// OPTIONS: gpu.binary @kernels [#gpu.object<#nvvm.target<O = 1, chip = "sm_80", features = "+ptx80">
// OPTIONS-SAME: .version 8.0\0A.target sm_80\0A

// PIPELINE:      builtin.module(
// PIPELINE-NEXT:   gpu.module(
// PIPELINE-NEXT:     sim-nvvm-check-target{attaching=true chip=sm_90 libdevice=}
// PIPELINE-NEXT:   ),
// PIPELINE-NEXT:   nvvm-attach-target{O=3 chip=sm_90 {{.*}}features= {{.*}}}
// PIPELINE-NEXT:   gpu.module(
// PIPELINE-NEXT:     sim-fused-multiply-add
// PIPELINE-NEXT:     sim-expand-integer-powers
// PIPELINE-NEXT:     sim-lower-vector-ops
// PIPELINE-NEXT:     convert-scf-to-cf
// PIPELINE-NEXT:     expand-strided-metadata
// PIPELINE-NEXT:     convert-gpu-to-nvvm{{{.*}} has-redux=true {{.*}}use-bare-ptr-memref-call-conv=false}
// PIPELINE-NEXT:     convert-nvvm-to-llvm
// PIPELINE-NEXT:     convert-math-to-llvm
// PIPELINE-NEXT:     reconcile-unrealized-casts
// PIPELINE-NEXT:     sim-nvvm-extern-dynamic-shared-memory
// PIPELINE-NEXT:     sim-nvvm-set-data-layout
// PIPELINE-NEXT:     sim-nvvm-check-target{attaching=false chip= libdevice={{.*}}/nvvm/libdevice/libdevice.10.bc}
// PIPELINE-NEXT:   ),
// PIPELINE-NEXT:   gpu-module-to-binary{format=isa {{.*}}}
// PIPELINE-NEXT: )

module attributes {gpu.container_module} {
  gpu.module @kernels {
    gpu.func @scale(%x: memref<?xf32>, %n: index, %a: f32) kernel {
      %tid = gpu.thread_id x
      %bid = gpu.block_id x
      %bdim = gpu.block_dim x
      %first = arith.muli %bid, %bdim : index
      %i = arith.addi %first, %tid : index
      %in_range = arith.cmpi ult, %i, %n : index
      scf.if %in_range {
        %v = memref.load %x[%i] : memref<?xf32>
        %w = arith.mulf %v, %a : f32
        memref.store %w, %x[%i] : memref<?xf32>
      }
      gpu.return
    }
  }

  // Host code stays as it is (the pipeline lowers no host code).
  func.func @host(%x: memref<?xf32>) {
    %c0 = arith.constant 0 : index
    %c1 = arith.constant 1 : index
    %n = memref.dim %x, %c0 : memref<?xf32>
    scf.for %i = %c0 to %n step %c1 {
      %v = memref.load %x[%i] : memref<?xf32>
      memref.store %v, %x[%i] : memref<?xf32>
    }
    return
  }
}
