//===- Passes.td - passes of the PTX back end --------------*- tablegen -*-===//
//
// Passes that run inside the GPU-to-PTX pipeline (--sim-gpu-to-ptx) on
// gpu.modules. Two shape the kernels' loops before upstream lowers them
// (sim-gpu-narrow-loop-counters, sim-gpu-unroll-loops), one rewrites warp
// reductions into shuffles for chips before sm_80
// (sim-gpu-lower-subgroup-reduce); the others run on gpu.modules already
// lowered to the LLVM and NVVM dialects, just before upstream's
// gpu-module-to-binary turns them into PTX, and fix or check what the
// upstream lowering leaves behind.
// docs/PTXPasses.md is generated from this file.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_TARGET_PTX_PASSES_TD
#define SIM_TARGET_PTX_PASSES_TD

include "mlir/Pass/PassBase.td"

def SimGPUNarrowLoopCounters
    : Pass<"sim-gpu-narrow-loop-counters"> {
  let summary = "Count `scf.for` loops in 32 bits where their bounds allow";
  let description = [{
    `index` is 64 bits wide in the kernels, so a loop over `index` counts
    with 64-bit adds and compares, which a GPU executes as two 32-bit
    instructions each. A scene's loops are usually bounded by 32-bit
    values (`arith.index_cast` of an `i32` parameter, a constant), and nvcc
    counts such a loop of a hand-written kernel in 32 bits.

    This pass gives an `scf.for` whose trip count is not a constant (LLVM
    unrolls the others completely, so no counter is left) an `i32`
    induction variable when every value of its lower bound, upper bound and
    step provably fits: each is a
    constant or an `arith.index_cast` (`arith.index_castui`) of an integer
    of at most 32 (31) bits, the step is at least 1, and the largest upper
    bound plus the largest step minus one is still a 32-bit value, so that
    no increment of the counter can wrap. Uses of the induction variable
    get it as `index` again through an `arith.index_cast`, so nothing else
    changes and results are the same bit for bit. Loops that compare
    unsigned, and loops whose bounds are not known to fit (a range, a
    buffer's size), keep `index`. The pass runs on any operation; the GPU
    pipeline runs it on every `gpu.module`.

    ```mlir
    // before
    %n = arith.index_cast %rounds : i32 to index
    %r = scf.for %k = %c0 to %n step %c1 iter_args(%x = %x0) -> (f32) {...}
    // after
    %r = scf.for %k = %c0_i32 to %rounds step %c1_i32 iter_args(%x = %x0) -> (f32) : i32 {...}
    ```
  }];
  let dependentDialects = ["::mlir::arith::ArithDialect"];
}

def SimGPUUnrollLoops
    : Pass<"sim-gpu-unroll-loops"> {
  let summary = "Unroll the innermost `scf.for` loops of unknown trip count";
  let description = [{
    LLVM's NVPTX back end unrolls a loop whose trip count is not known at
    compile time only when its body is small; the load loop of a scene
    (say 64 fused multiply-adds per round) is not, so every round pays the
    loop's counter, compare and branch, where nvcc unrolls the same loop of
    a hand-written kernel by 2. This pass unrolls every innermost `scf.for`
    with a constant step whose trip count is not a constant (LLVM unrolls
    those itself) by `factor`: a main loop that runs `factor` copies of the
    body per iteration over the largest multiple of `factor` iterations,
    then the original loop for the rest. The copies run in the original
    order, so results are the same bit for bit. The trip count is computed
    in 64 bits, so a 32-bit counter (sim-gpu-narrow-loop-counters) cannot
    wrap.

    The pass runs on any operation. `sim-translate --sim-gpu-unroll=N`
    (default 1: off) adds it to the GPU pipeline, on every `gpu.module`; `utils/gpu-check.sh` stage `unroll` measures it against the
    default on a GPU.

    ```mlir
    // before
    %r = scf.for %k = %c0 to %n step %c1 iter_args(%x = %x0) -> (f32) : i32 {
      %y = "body"(%x) ...
    }
    // after (factor 2): the body twice per iteration, then the remainder
    %main = scf.for %k = %c0 to %n_even step %c2 iter_args(%x = %x0) -> (f32) : i32 {...}
    %r = scf.for %k = %n_even to %n step %c1 iter_args(%x = %main) -> (f32) : i32 {...}
    ```
  }];
  let options = [
    Option<"factor", "factor", "unsigned", /*default=*/"2",
           "Copies of the body per iteration of the main loop, 1 to 32 "
           "(1: none)">,
  ];
  let dependentDialects = ["::mlir::arith::ArithDialect",
                           "::mlir::scf::SCFDialect"];
}

def SimGPULowerSubgroupReduce
    : Pass<"sim-gpu-lower-subgroup-reduce"> {
  let summary = "Warp reductions as shuffles, for chips before sm_80";
  let description = [{
    The kernels combine the lanes of a warp with `gpu.subgroup_reduce`
    (the minimum of `num_steps` over a group, the sum of its evaluation
    counts), which `convert-gpu-to-nvvm` lowers to `redux.sync`: an
    instruction of sm_80 and later. For an older chip (sm_70 Volta, sm_75
    Turing) it refuses the operation, so no kernel compiled. The GPU
    pipeline runs this pass on every `gpu.module` when the chip has no
    `redux.sync`: it rewrites each reduction into a butterfly of five
    `gpu.shuffle xor` over the 32 lanes of a warp (`shfl.sync`, every
    chip) with upstream's patterns. The kernels reduce `i32` values only,
    minima and sums, which give the same result in any order; a reduction
    of a value wider than 32 bits is an error that names the chip rule.

    ```mlir
    // before
    %m = gpu.subgroup_reduce minsi %x uniform : (i32) -> i32
    // after: five rounds of
    %s, %valid = gpu.shuffle xor %acc, %c1_i32, %c32_i32 : i32
    %acc1 = arith.minsi %acc, %s : i32
    ```
  }];
  let dependentDialects = ["::mlir::arith::ArithDialect",
                           "::mlir::gpu::GPUDialect"];
}

def SimNVVMSetDataLayout
    : Pass<"sim-nvvm-set-data-layout", "::mlir::gpu::GPUModuleOp"> {
  let summary = "Give a gpu.module NVPTX's data layout before it is "
                "translated to LLVM IR";
  let description = [{
    Upstream's `gpu-module-to-binary` (MLIR 22) translates a gpu.module to
    LLVM IR and only then sets the NVPTX target's data layout on the LLVM
    module. An `llvm.load` or `llvm.store` without an `alignment` takes its
    alignment during the translation, from the data layout the module has
    then: LLVM's default, where an `i64` is aligned to 4 bytes. The NVPTX
    back end then splits every such access into two 32-bit ones
    (`ld.global.b32` twice and a shift and an or), which doubles the memory
    instructions of the kernels' clock and level codes and, for a slot
    another thread updates with a 64-bit atomic, could read the two halves
    of different values.

    This pass sets `llvm.data_layout` on the gpu.module to the data layout
    of its triple (`nvptx64-nvidia-cuda`, from LLVM's TargetParser), which
    the translation gives the LLVM module first, so `i64` accesses keep
    their natural 8-byte alignment (`ld.global.b64`). A module that already
    has a data layout keeps it.

    ```mlir
    // after
    gpu.module @kernels attributes {llvm.data_layout = "e-p6:32:32-i64:64-i128:128-i256:256-v16:16-v32:32-n16:32:64"} [...]
    ```
  }];
}

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
      pipeline cannot lower, e.g. an `arith.truncf` to an 8-bit float): error at the operation,
      instead of a missing-translation error on the whole module;
    - an `#nvvm.target` whose chip or features LLVM's NVPTX back end does not
      know (LLVM would only warn on stderr and emit PTX for another chip);
    - a chip before sm_70, which has no `shfl.sync` for the kernels' warp
      reductions, and a PTX ISA feature older than the chip needs
      (`+ptx60` for sm_90): LLVM would abort the process;
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

    With `attaching` (the sim pipelines run it so before
    `nvvm-attach-target`), it checks only `chip`, the chip about to be
    attached: upstream's verifier of the target attribute crashes on an
    empty chip and names other unknown ones by the oldest SM version it
    takes.

    ```
    sim-opt k.mlir --pass-pipeline='builtin.module(gpu.module(sim-nvvm-check-target{libdevice=/usr/local/cuda/nvvm/libdevice/libdevice.10.bc}))'
    ```
  }];
  let options = [
    Option<"libdevice", "libdevice", "std::string", /*default=*/"\"\"",
           "The libdevice bitcode file that gpu-module-to-binary will link; "
           "empty: none">,
    Option<"attaching", "attaching", "bool", /*default=*/"false",
           "Before nvvm-attach-target: check only `chip`, the chip it will "
           "attach">,
    Option<"chip", "chip", "std::string", /*default=*/"\"\"",
           "With `attaching`: the chip nvvm-attach-target will attach">,
  ];
}

#endif // SIM_TARGET_PTX_PASSES_TD
