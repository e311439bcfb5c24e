//===- Passes.td - sim conversion passes -------------------*- tablegen -*-===//
//
// The conversions out of the sim dialect (CIRCT's layout: one Passes.td for
// all conversions). docs/Passes.md is generated from this file too.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_CONVERSION_PASSES_TD
#define SIM_CONVERSION_PASSES_TD

include "mlir/Pass/PassBase.td"

def SimLowerToGPU : Pass<"sim-lower-to-gpu", "::mlir::ModuleOp"> {
  let summary = "Lower simulations to GPU kernels and a host plan";
  let description = [{
    Turns every `sim.simulation` that went through the front end
    (`--sim-front-end{strategy=...}`) into a `gpu.module @<name>_kernels` of
    kernels and a `simplan.plan @<name>` that says how to run them
    (docs/Plan.md), and erases the simulation. It reads the decisions the
    front end recorded (strategy, schedule, step bounds, sub-stepping,
    parity, snapshots, caches) and derives none of them again. It checks
    that they agree: each component's `advance` and `estimates` with what
    the strategy, `bounded_by` and its verdict give, an `in_kernel` verdict
    with reads of its own buffers at its own item only, a `local_window`
    with the reads of a `local_steps` component, and the copy each load
    reads with the schedule; a disagreement (a hand edit, or one pass rerun
    after a change) is an error at the record.

    - `simple` and `traditional`: one kernel per component that evaluates
      every item once with `n = m` (`traditional` first runs an estimate
      kernel per component with `num_steps`).
    - `hip`: estimate kernels for the components in `bounded_by`; an
      `in_kernel` component with `num_steps` runs Algorithm 2 in one kernel:
      own state in registers, sub-steps of the group-wide minimum of
      `num_steps` (`gpu.subgroup_reduce minsi ... uniform`, then
      `memref.atomic_rmw mins` on workgroup memory), the target written once;
      when `m = 1` it skips `num_steps` and the reduction. A `grid_sync`
      component with `num_steps` runs `max_steps` rounds of launches
      (estimate, decide, sub-step) with a grid-wide sub-step decided on the
      device, a snapshot before and a parity copy after.
    - `hip-cache`: as `hip`, and each recorded cache is filled with the
      interpolated values of the group's window once per sub-step, between
      barriers; reads inside the window come from it, others from global
      memory.

    The size of every big step is decided on the device: estimate kernels
    reduce into a device-resident clock, a one-thread kernel turns the
    minimum into `m`, and every kernel reads `T` and `m` from the clock and
    does nothing once the run has reached its end. `range`, `dt`,
    `max_steps` and every `sim.param` are kernel arguments.

    Kernels are named `<kind>_<symbol>` (`init_B`, `evaluate_C`, ...; the
    table in docs/Plan.md). A kernel name is a PTX `.entry` and, as
    `sim_cpu_<kernel>`, a C function, so symbols that are not identifiers
    are escaped: letters and digits stay, an `_` stays before a letter, a
    digit or the end, and every other byte becomes `__` and two lowercase
    hex digits (`@"B 4"` gives `init_B__204`, `@"a__b"` gives
    `init_a__5f_b`). An escaped symbol longer than 128 characters is cut
    and ends in `_` and a 64-bit hash of the symbol, and a name that another
    kernel of the module already has gets the first free suffix `_1`,
    `_2`, ... The plan names kernels by these names and everything else by
    its symbol.

    ```
    sim-opt scene.mlir --sim-front-end=strategy=hip --sim-lower-to-gpu
    ```
  }];
  let options = [
    Option<"groupSize", "group-size", "int64_t", "256",
           "Threads per group the plan is made for (a multiple of 32)">,
  ];
  // vector: the interpolation of a vector-typed buffer broadcasts its
  // fraction, also where the scene itself uses no vector op.
  let dependentDialects = [
    "::mlir::arith::ArithDialect", "::mlir::gpu::GPUDialect",
    "::mlir::memref::MemRefDialect", "::mlir::NVVM::NVVMDialect",
    "::mlir::scf::SCFDialect", "::mlir::simplan::PlanDialect",
    "::mlir::vector::VectorDialect"
  ];
}

def SimLowerToCPU : Pass<"sim-lower-to-cpu", "::mlir::ModuleOp"> {
  let summary = "Lower simulations to CPU kernels with the GPU kernels' semantics";
  let description = [{
    The CPU counterpart of `--sim-lower-to-gpu`: the same kernels (the same
    algorithms, names and arguments, and the same `simplan.plan`), as
    `func.func`s in a nested `builtin.module @<name>_kernels`. Each kernel
    takes the plan's arguments followed by the first group, the end group
    and the group size (`i64`), and runs those groups: a group phase by
    phase (a loop over its lanes between what are barriers on a GPU), with
    the same group-wide sub-step as on a GPU, so results do not depend on the
    backend. Shared-memory caches are not emulated (a cached value equals the
    value read through global memory). Clock updates are atomic, so disjoint
    ranges of groups of one launch may run on different threads.

    ```
    sim-opt scene.mlir --sim-front-end=strategy=hip --sim-lower-to-cpu
    ```
  }];
  let options = [
    Option<"groupSize", "group-size", "int64_t", "256",
           "Items per group the plan is made for">,
    Option<"levelsPerLane", "levels-per-lane", "bool", "false",
           "lts: limit each block's sub-step in a lane of its own, as the "
           "GPU kernels do, instead of in one pass by one lane "
           "(the same results; for testing the GPU's algorithm "
           "on the CPU)">,
  ];
  let dependentDialects = [
    "::mlir::arith::ArithDialect", "::mlir::func::FuncDialect",
    "::mlir::memref::MemRefDialect", "::mlir::scf::SCFDialect",
    "::mlir::simplan::PlanDialect", "::mlir::vector::VectorDialect"
  ];
}

def SimLowerToReference : Pass<"sim-lower-to-reference", "::mlir::ModuleOp"> {
  let summary = "Lower scheduled simulations to per-item body functions for "
                "the reference executor";
  let description = [{
    The compiler's part of the reference executor (docs/Reference.md), the
    oracle every backend is checked against. It starts from the *scheduled*
    IR (after `--sim-prune`, `--sim-schedule` and `--sim-substep-legality`,
    before `--sim-plan-memory`) and replaces every `sim.simulation` with a
    `builtin.module @<name>_reference` that holds one `func.func` per body,
    `sim_ref_init_<b>`, `sim_ref_exact_<b>`, `sim_ref_num_steps_<c>` and
    `sim_ref_evaluate_<c>`, and the reference model as its
    `sim.reference_model` dictionary: the model's parameters and buffers by
    scene name, its components in schedule order (sub-stepping verdict,
    whether they have `num_steps`, the model buffers they write and read,
    and how they take a big step under every strategy) and its totals with
    the buffers they read. A view read `sim.read @B[%j]` becomes
    a call through the context's `read` callback and a `sim.get_param` a
    call through its `param` callback: which value a read sees (its local
    time, interpolation, boundary rule) is decided by the executor, not
    here, and no code of the kernel lowerings is involved.

    ```
    sim-opt scene.mlir --sim-reference-pipeline
    ```
  }];
  let dependentDialects = [
    "::mlir::arith::ArithDialect", "::mlir::func::FuncDialect",
    "::mlir::LLVM::LLVMDialect"
  ];
}

def SimVectorizeLanes : Pass<"sim-vectorize-lanes"> {
  let summary = "Run the lanes of a CPU kernel's group in SIMD registers";
  let description = [{
    A CPU kernel runs a group phase by phase, each phase a loop over the
    group's lanes (`scf.for` marked `simplan.lanes`). The lanes of a phase
    are independent, as the threads of a GPU block between two barriers
    are, so this pass runs `width` lanes at once (SPMD on SIMD, as ISPC
    does): every value that differs between lanes becomes a vector of
    `width` lanes (a `vector<N x T>` value of one lane becomes `N` vectors,
    one per element, so lane `l` of every vector is item `l` of the chunk);
    values equal for all lanes stay scalars. Branches on a lane-dependent
    condition run under a mask and are skipped when no lane takes them;
    loads of consecutive items become one wide load, other loads gathers,
    stores masked scatters. A read through a boundary rule (clamp, zero or
    wrap of `item + offset`, shifted by a uniform value) is consecutive
    wherever the rule changes nothing: one wide load when the chunk's first
    and last items lie inside, decided by two scalar compares, and the
    gathers at the range's ends; under a branch's mask a consecutive access
    is wide when every lane runs. A load at an item divided by at least the
    lanes (a block's level) is one scalar load and a broadcast when every
    lane reads the same element, two when they read two, gathers else;
    under a mask only a chunk with a lane that does not run first moves
    that lane's index to an active lane's. A loaded `vector<N x T>` (N a power of two)
    stays interleaved as memory holds it while elementwise ops use it (a
    uniform operand is spread to match), and is de-interleaved by shuffles
    only where something needs its elements apart: an interpolation of two
    halves costs one de-interleaving, not two, and a value loaded, computed
    and stored needs none. Where an elementwise op's elements are needed
    and its operands' elements are at hand or need one de-interleaving
    between them, they are computed element by element from those instead
    (the same operations: rows of a vec4 product built from the same two
    loads take the loads apart once, not each row). Such a value also
    stays interleaved through a
    branch on a lane-independent condition whose sides both have it so (a
    read from one of two halves, chosen by the clock) and from one
    iteration of a loop to the next (a window's sum: de-interleaved once
    after the loop, not each load in every iteration), where the loop's
    body computes it by elementwise ops alone; a branch or loop where that
    holds only for some of its values is widened again with the others in
    parts. With `chains-apart`, a loop body made of pure operations only (a
    scene's rounds of a matrix product) is ordered chain by chain: the
    widened elements of a vec4 are computed apart, and computed one element
    after another they fit in AVX2's 16 registers where all at once they do
    not. The lanes left
    over when the group size is not a multiple of `width` run in the
    original loop. Each lane computes exactly the operations of the scalar
    loop in the same order (fused multiply-adds, libm calls per element,
    ordered reductions), so the results are bit for bit those of the
    scalar code. A loop with an operation the pass cannot widen (a
    `scf.while`, a call, an atomic, a store of different lanes to one
    element, a memref it cannot address) is left as it is.

    x86 has no SIMD integer division: a widened one is a `div` per lane.
    So a select on a lane-independent condition whose operand costs an
    integer division (a `num_steps` keyed by `i / @group` or `i` as a
    parameter says) becomes a branch that computes only the chosen operand,
    and a division by a constant that cannot trap (not 0, not -1 when
    signed) keeps its divisor in lanes a branch does not take (others
    divide by one there), so that LLVM multiplies by its reciprocal. A
    division or remainder by any other divisor runs in f64 lanes where
    that is exact: for |x| < 2^53 and 0 < |d| < 2^53 the quotient
    truncated from the correctly rounded x / d is the integer quotient (a
    quotient that is not an integer lies at least 1 / |d| from the nearest
    one, further than the rounding error). 32-bit operands always qualify;
    64-bit and `index` ones (the wrap of a window read) where every lane of
    the chunk is within 2^51 of zero (they convert through the bits of
    1.5 * 2^52, which needs no AVX-512; with `wide-int-conversions`, within
    2^53, by the target's conversions), else the chunk divides as before. A
    64-bit remainder by a constant below 2^16 that is not a power of two
    is computed from 32-bit remainders of the two halves, which x86 has
    in vector form where it has no vector high half of a 64-bit product.
    A division or remainder of a consecutive dividend (the item plus a
    uniform value: a 2-D grid's row and column, a ring's neighbour) by a
    divisor every lane shares takes one scalar division of the chunk's
    first lane where the divisor is at least the lanes and no lane wraps or
    (signed) is below zero: the chunk then crosses at most one multiple of
    the divisor, which a compare per lane finds; elsewhere it divides as
    above (a constant divisor too, unless it is a power of two or 32-bit).
    A remainder and a division of the same operands share that branch.

    ```
    sim-opt kernels.mlir --sim-vectorize-lanes=width=16
    ```
  }];
  let options = [
    Option<"width", "width", "int64_t", "16",
           "Lanes per SIMD chunk (a power of two from 2 to 64)">,
    Option<"report", "report", "bool", "false",
           "A remark at every lane loop: widened, or why it stays scalar">,
    Option<"wideIntConversions", "wide-int-conversions", "bool", "false",
           "The target converts vectors of 64-bit integers to and from f64 "
           "(x86-64-v4, AVX-512DQ): 64-bit divisions in f64 lanes use "
           "them, for lanes within 2^53 of zero">,
    Option<"chainsApart", "chains-apart", "bool", "false",
           "Order a loop body of pure ops chain by chain (each widened "
           "element's ops together), for a target with few vector "
           "registers (x86-64-v3: 16)">,
  ];
  let statistics = [
    Statistic<"numWidened", "widened-loops", "Lane loops run in SIMD chunks">,
    Statistic<"numScalar", "scalar-loops",
              "Lane loops left scalar (an op the pass cannot widen)">,
  ];
  let dependentDialects = [
    "::mlir::arith::ArithDialect", "::mlir::LLVM::LLVMDialect",
    "::mlir::math::MathDialect", "::mlir::memref::MemRefDialect",
    "::mlir::scf::SCFDialect", "::mlir::vector::VectorDialect"
  ];
}

def SimExpandIntegerPowers : Pass<"sim-expand-integer-powers"> {
  let summary = "Expand math.ipowi into multiplications (every backend)";
  let description = [{
    No upstream conversion lowers `math.ipowi` to the LLVM or NVVM
    dialects, libm or libdevice. This pass writes it out in `arith` ops:
    exponentiation by squaring over every bit of the exponent, unrolled and
    selected per bit, so the result is straight-line code (the CPU lanes
    widen it; the GPU takes no branch). Multiplications wrap as
    `arith.muli` does. A negative exponent `p` gives `1 / base^-p` in
    integers: 1 for base 1, `(-1)^p` for base -1 and 0 for every other base
    (0 also for base 0, which C would divide by zero). The CPU kernels, the
    reference functions (lib/Target/CPU/CPUKernels.cpp) and the GPU kernels
    (lib/Pipelines/GPUToPTX.cpp) all run it, so they agree bit for bit.

    ```
    sim-opt kernels.mlir --sim-expand-integer-powers
    ```
  }];
  let dependentDialects = ["::mlir::arith::ArithDialect"];
}

def SimLowerVectorOps : Pass<"sim-lower-vector-ops"> {
  let summary = "Lower high-level vector ops (contract, outerproduct, "
                "multi_reduction, transpose, step, shape_cast, scan, n-D "
                "broadcasts, masks) to 1-D vector ops (every backend)";
  let description = [{
    A component body may use `vector.contract` (for example a dot
    product), `vector.outerproduct`, `vector.multi_reduction`,
    `vector.transpose`, `vector.step`, `vector.shape_cast`, `vector.scan`,
    broadcasts of
    vectors to n-D vectors and masks (`vector.create_mask`,
    `vector.constant_mask`). The LLVM and NVVM conversions lower only 1-D
    vector ops (extract, insert, reduction, fma, shuffle), so these ops
    compiled for no backend. This pass applies upstream's progressive
    lowering patterns (contractions as multiplications and reductions,
    outer products as `vector.fma`, multi-reductions as `vector.reduction`,
    transposes element by element, steps as constants, scans slice by slice
    in order, shape casts and
    strided slices as shuffles, n-D broadcasts row by row, masks as
    comparisons with a step), and a `math.fpowi` of vectors as one scalar
    `fpowi` per element (LLVM's `powi` takes one integer exponent).
    The CPU kernels, the reference functions (lib/Target/CPU/CPUKernels.cpp)
    and the GPU kernels (lib/Pipelines/GPUToPTX.cpp) all run it, so they
    compute the same operations; a module without such an op is left
    untouched.

    ```
    sim-opt kernels.mlir --sim-lower-vector-ops
    ```
  }];
  // (math ops are made only where a math.fpowi already is.)
  let dependentDialects = ["::mlir::arith::ArithDialect",
                           "::mlir::vector::VectorDialect"];
}

def SimExpandTanh : Pass<"sim-expand-tanh"> {
  let summary = "Expand f32 math.tanh into glibc's tanhf algorithm in "
                "arithmetic (CPU kernels)";
  let description = [{
    On the CPU an f32 `math.tanh` is a call of libm's `tanhf` per element,
    about 33 cycles each, and every live SIMD register is spilled around
    it. glibc's `tanhf` (Debian 12's 2.36 and earlier releases) is
    fdlibm's: `expm1f` plus a few operations, all plain f32 arithmetic and
    bit manipulation. This pass writes that algorithm out in `arith` ops,
    every path computed and the right one selected per element, so that
    the vectorised lanes compute it in SIMD instructions and every element
    gets the bits glibc's `tanhf` returns. Where two paths divide by the
    same value, the numerator is selected before one division, and the
    `1/x +- 1` glibc returns for infinities and NaN becomes the value those
    give (+-1 from the path for large |x|; `x + x`, the NaN itself): two
    divisions per element, the slowest SIMD operation in it. The reference
    executor and the
    hand-written CPU baseline, which call glibc, still agree bit for bit
    (checked on all 2^32 inputs, `utils/check-tanh.sh`). f64 `tanh` and
    other math ops stay libm calls. The CPU kernels run it
    (lib/Target/CPU/CPUKernels.cpp); the GPU keeps libdevice's `tanhf`.

    ```
    sim-opt kernels.mlir --sim-expand-tanh
    ```
  }];
  let dependentDialects = ["::mlir::arith::ArithDialect"];
}

def SimFusedMultiplyAdd : Pass<"sim-fused-multiply-add"> {
  let summary = "Lower vector.fma to llvm.intr.fma, fused on every target";
  let description = [{
    `vector.fma` is a fused multiply-add: one rounding. Upstream's
    `convert-vector-to-llvm` lowers it to `llvm.intr.fmuladd`, which LLVM may
    fuse or not as the target finds faster: NVPTX fuses it (`fma.rn`), but
    generic x86-64 has no FMA instruction and computes a multiply and an add,
    so the CPU backend and the reference functions rounded twice where the
    GPU rounded once. This pass rewrites every `vector.fma` (any rank) to
    `llvm.intr.fma`, whose result is the correctly rounded `a * b + c` on
    every target (one instruction where the CPU has FMA, libm's `fma` where
    it does not). `math.fma` needs no pass: `convert-math-to-llvm` already
    lowers it to `llvm.intr.fma`, and the GPU's libdevice `__nv_fmaf` is
    `fma.rn`. Every backend runs this pass before its conversion to LLVM
    (lib/Target/CPU/CPUKernels.cpp, lib/Pipelines/GPUToPTX.cpp), so the
    backends agree bit for bit on scenes that use `vector.fma`
    (docs/Reference.md).

    ```
    sim-opt kernels.mlir --sim-fused-multiply-add
    ```
  }];
  let dependentDialects = ["::mlir::LLVM::LLVMDialect"];
}

def SimFlushSubnormals : Pass<"sim-flush-subnormals"> {
  let summary = "Mark every LLVM function as flushing subnormals to zero";
  let description = [{
    The code generation half of `sim-translate --sim-ftz`: sets
    `denormal_fp_math` and `denormal_fp_math_f32` to `"preserve-sign"` on
    every `llvm.func` with a body, so that LLVM folds and simplifies as if
    subnormal inputs and results were zero (of the same sign). On NVPTX the
    f32 operations then become their `.ftz` forms (`add.rn.ftz.f32`, ...);
    PTX has no such form for f64. On the CPU no instruction encodes it: the
    runtime sets the FTZ and DAZ bits of MXCSR on every thread that runs the
    kernels or the reference functions (docs/Runtime.md), which flushes f32
    and f64 alike.

    ```
    sim-opt kernels-in-llvm.mlir --sim-flush-subnormals
    ```
  }];
  let dependentDialects = ["::mlir::LLVM::LLVMDialect"];
}

#endif // SIM_CONVERSION_PASSES_TD
