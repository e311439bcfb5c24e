//===- Passes.td - passes of the PTX back end --------------*- tablegen -*-===//
//
// Passes that run inside the GPU-to-PTX pipeline (--sim-gpu-to-ptx) on
// gpu.modules already lowered to the LLVM and NVVM dialects, just before
// upstream's gpu-module-to-binary turns them into PTX. They fix or check what
// the upstream lowering leaves behind; they do not lower anything themselves.
// docs/PTXPasses.md is generated from this file.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_TARGET_PTX_PASSES_TD
#define SIM_TARGET_PTX_PASSES_TD

include "mlir/Pass/PassBase.td"

def SimNVVMExternDynamicSharedMemory
    : Pass<"sim-nvvm-extern-dynamic-shared-memory", "::mlir::gpu::GPUModuleOp"> {
  let summary = "Declare dynamic shared memory as `.extern .shared` for PTX";
  let description = [{
    Upstream's `convert-gpu-to-nvvm` (MLIR 22) lowers
    `gpu.dynamic_shared_memory` to an *internal* zero-sized global in
    address space 3. The NVPTX back end then emits an ordinary static
    `.shared .align 16 .b8 __dynamic_shmem__0;` of one byte, which `ptxas`
    places among the kernel's static shared variables (workgroup
    attributions): element 1 of the dynamic array aliases whatever ptxas put
    after it, and ptxas warns of an out-of-bound access. CUDA's
    `extern __shared__` is an *external* declaration, which NVPTX emits as
    `.extern .shared .align 16 .b8 __dynamic_shmem__0[];` and the driver places
    after all static shared memory.

    This pass gives every internal, zero-sized, uninitialized global in
    shared memory (address space 3) external linkage, which makes it that
    declaration. Nothing else changes.

    ```mlir
    // before
    llvm.mlir.global internal @__dynamic_shmem__0() {addr_space = 3 : i32, alignment = 16 : i64} : !llvm.array<0 x i8>
    // after
    llvm.mlir.global external @__dynamic_shmem__0() {addr_space = 3 : i32, alignment = 16 : i64} : !llvm.array<0 x i8>
    ```
  }];
  let dependentDialects = ["::mlir::LLVM::LLVMDialect"];
}

def SimNVVMCheckTarget
    : Pass<"sim-nvvm-check-target", "::mlir::gpu::GPUModuleOp"> {
  let summary = "Check that a lowered gpu.module can be compiled to PTX";
  let description = [{
    Turns the ways `gpu-module-to-binary` would fail late, obscurely or not
    at all into errors at the construct's location:

    - an operation left outside the LLVM and NVVM dialects (a construct the
      pipeline cannot lower, e.g. `math.ipowi`): error at the operation,
      instead of a missing-translation error on the whole module;
    - an `#nvvm.target` whose chip or features LLVM's NVPTX back end does not
      know (LLVM would only warn on stderr and emit PTX for another chip);
    - a call to a libdevice function (`__nv_expf` for `math.exp`, ...) when
      the libdevice file named by `libdevice` does not exist: upstream would
      leave the call unresolved and the PTX would fail to load;
    - a function or global whose name is not a PTX identifier (letters,
      digits, `_` and `$`, not starting with a digit), such as a kernel
      `@"scale by 2"`: LLVM's NVPTX printer would abort the process
      ("Symbol name with unsupported characters") or print PTX that ptxas
      rejects. LLVM renames private and internal symbols itself (other
      characters become `_$_`), so only their leading digit is an error.
      The kernels of a lowered scene always have such names
      (`--sim-lower-to-gpu`).

    ```
    sim-opt k.mlir --pass-pipeline='builtin.module(gpu.module(sim-nvvm-check-target{libdevice=/usr/local/cuda/nvvm/libdevice/libdevice.10.bc}))'
    ```
  }];
  let options = [
    Option<"libdevice", "libdevice", "std::string", /*default=*/"\"\"",
           "The libdevice bitcode file that gpu-module-to-binary will link; "
           "empty: none">,
  ];
}

#endif // SIM_TARGET_PTX_PASSES_TD
