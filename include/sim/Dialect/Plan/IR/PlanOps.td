//===- PlanOps.td - simplan operations and attributes ------*- tablegen -*-===//
//
// A plan is a symbol table of buffers and parameters plus phases of kernel
// launches. It holds no computation: every number a kernel needs at run time
// (the range, dt, the parameters, the clock) is a launch argument.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_PLAN_IR_PLANOPS_TD
#define SIM_DIALECT_PLAN_IR_PLANOPS_TD

include "sim/Dialect/Plan/IR/PlanDialect.td"
include "mlir/IR/AttrTypeBase.td"
include "mlir/IR/BuiltinAttributeInterfaces.td"
include "mlir/IR/EnumAttr.td"
include "mlir/IR/OpBase.td"
include "mlir/IR/RegionKindInterface.td"
include "mlir/IR/SymbolInterfaces.td"

//===----------------------------------------------------------------------===//
// Enumerations and attributes
//===----------------------------------------------------------------------===//

def Plan_PhaseKind : I32Enum<"PhaseKind", "when a phase runs", [
    I32EnumCase<"init", 0>, I32EnumCase<"step", 1>, I32EnumCase<"finish", 2>,
    I32EnumCase<"exact", 3>, I32EnumCase<"total", 4>]> {
  let cppNamespace = "::mlir::simplan";
  let description = [{
    `init` runs once before the first big step; `step` is one big step and is
    repeated until the clock reaches the end of the run; `finish` runs once
    after the last big step of a run; `exact` evaluates the exact solution of
    the buffers that declare one, at a time given by the runtime; `total`
    writes the per-item values of every `simplan.total` at the current `T`
    (the runtime sums them).
  }];
}
def Plan_PhaseKindAttr : EnumAttr<Plan_Dialect, Plan_PhaseKind, "phase">;

def Plan_LaunchShape : I32Enum<"LaunchShape", "the grid of a launch", [
    I32EnumCase<"items", 0>, I32EnumCase<"single", 1>]> {
  let cppNamespace = "::mlir::simplan";
  let description = [{
    `items`: one thread per item, in groups of the run's group size; the grid
    is `ceil(range / group size)` groups (a runtime may launch fewer: kernels
    loop over the padded range with a grid stride). `single`: one group of
    one thread (the clock updates).
  }];
}
def Plan_LaunchShapeAttr : EnumAttr<Plan_Dialect, Plan_LaunchShape, "shape">;

def Plan_ArgKind : I32Enum<"ArgKind", "what a launch argument is", [
    I32EnumCase<"clock", 0>, I32EnumCase<"buffer", 1>,
    I32EnumCase<"snapshot", 2>, I32EnumCase<"exact", 3>,
    I32EnumCase<"param", 4>, I32EnumCase<"range", 5>, I32EnumCase<"dt", 6>,
    I32EnumCase<"time", 7>, I32EnumCase<"total", 8>,
    I32EnumCase<"first", 9>, I32EnumCase<"extent", 10>,
    I32EnumCase<"levels", 11>]> {
  let cppNamespace = "::mlir::simplan";
  let description = [{
    `clock`: the clock (`memref<?xi64>`, `clock_slots` entries). `buffer @B`:
    both halves of buffer B (`memref<?xT>`, `2 * range` elements; half `h`
    starts at element `h * range`). `snapshot @B`: B's snapshot (`range`
    elements). `exact @B`: the output of B's exact solution (`range`
    elements). `param @P`: the run-time value of parameter P (its type).
    `range`: the item count (`i64`). `dt`: the base time step (the plan's dt
    type). `time`: the time of an exact solution, in time units (`f64`).
    `total @T`: the per-item values of total T (`memref<?xf64>`, `range`
    elements). `max_steps` is no argument: it is compiled into the kernels.
    Distributed plans only: `first`, the first item of the rank's block
    (`i64`), and `extent`, the elements of one half of a buffer on the rank
    (its block's items plus twice the plan's halo, `i64`); every `range`
    above is then `extent`, and item `i` is element `i - first + halo`.
    `levels @C`: the sub-steps of the blocks of 32 items of a component
    that advances in `local_steps` and their neighbourhood codes
    (`memref<?xi64>`, `6 * ceil(range / 32)` elements: docs/Plan.md,
    "Levels"), which its kernels decide and read in every big step.
    The cases and their numbers are the bundle schema's `ArgKind`
    (runtime/schema/bundle.fbs).
  }];
}

def Plan_ArgAttr : AttrDef<Plan_Dialect, "Arg"> {
  let mnemonic = "arg";
  let summary = "one argument of a kernel launch";
  let description = [{
    Names what the runtime passes for one kernel argument, in order. A memref
    argument is passed as the five values of its descriptor (allocated
    pointer, aligned pointer, offset 0, size, stride 1); a scalar as itself.

    ```mlir
    [#simplan.arg<clock>, #simplan.arg<buffer @B0>, #simplan.arg<param @L>]
    ```
  }];
  let parameters = (ins EnumParameter<Plan_ArgKind>:$kind,
                        OptionalParameter<"::mlir::FlatSymbolRefAttr">:$name);
  let hasCustomAssemblyFormat = 1;
  let genVerifyDecl = 1;
}

/// The sim dialect's `#sim<advance ...>` (docs/Dialects/Sim.md, `Advance`),
/// which `--sim-plan-memory` records on a component. Wrapped here rather
/// than included with SimAttrs.td, whose enums the simplan generators would
/// emit again.
def Plan_AdvanceAttr : Attr<CPred<"::llvm::isa<::mlir::sim::AdvanceAttr>($_self)">,
    "how a component advances through a big step (`#sim<advance ...>`)"> {
  let storageType = "::mlir::sim::AdvanceAttr";
  let returnType = "::mlir::sim::Advance";
  let convertFromStorage = "$_self.getValue()";
  let constBuilderCall =
      "::mlir::sim::AdvanceAttr::get($_builder.getContext(), $0)";
}

//===----------------------------------------------------------------------===//
// Operations
//===----------------------------------------------------------------------===//

class Plan_Op<string mnemonic, list<Trait> traits = []>
    : Op<Plan_Dialect, mnemonic, traits>;

def Plan_PlanOp : Plan_Op<"plan", [
    Symbol, SymbolTable, IsolatedFromAbove, NoTerminator, SingleBlock,
    NoRegionArguments]> {
  let summary = "the host plan of one simulation and one strategy";
  let description = [{
    The buffers, parameters, components and phases of one lowered
    simulation. `kernels` names the `gpu.module` whose kernels the launches
    call. `range`, `dt` and the parameters' values are defaults: they are
    launch arguments, so a runtime may change them without recompiling.
    `max_steps` and `group_size` are the values the kernels were planned for
    (the clock holds a histogram of big-step sizes up to `max_steps`).
    `step_cap` is the largest big step the strategy takes (1 under `simple`,
    `max_steps` otherwise), as `--sim-plan-memory` recorded it; `advance`
    caps every big step with it. `clock_slots` is the number of `i64`
    entries of the clock; docs/Plan.md gives its layout (`T`, `m`, the
    parity, the end of the run, the pending estimate, the big steps taken,
    evaluation counters, sub-step clocks and the histogram, which starts at
    slot `histogram`). `distributed halo(H)` marks a plan for many
    processes (docs/Distributed.md): each rank holds a block of whole
    groups plus `H` ghost items on either side, and its kernels take the
    `first` and `extent` arguments.

    ```mlir
    simplan.plan @rod strategy("hip") kernels(@rod_kernels) range(1024)
        dt(1.0e-3 : f32) max_steps(4) step_cap(4) group_size(256)
        clock_slots(15) histogram(10) {
      simplan.param @k = 2.0 : f32
      simplan.buffer @Q : f32 stride(4)
      simplan.buffer @T : f32 stride(4) observed
      simplan.component @Heater writes [@Q] evaluations(8) advance whole_step
          estimates
      simplan.phase init { ... }
      simplan.phase step { ... }
      simplan.phase finish { ... }
    }
    ```
  }];
  let arguments = (ins SymbolNameAttr:$sym_name, StrAttr:$strategy,
                       FlatSymbolRefAttr:$kernels, I64Attr:$range,
                       TypedAttrInterface:$dt, I64Attr:$max_steps,
                       I64Attr:$step_cap, I64Attr:$group_size,
                       I64Attr:$clock_slots,
                       I64Attr:$histogram_slot,
                       OptionalAttr<I64Attr>:$distributed_halo);
  let regions = (region SizedRegion<1>:$body);
  let assemblyFormat = [{
    $sym_name `strategy` `(` $strategy `)` `kernels` `(` $kernels `)`
    `range` `(` $range `)` `dt` `(` $dt `)` `max_steps` `(` $max_steps `)`
    `step_cap` `(` $step_cap `)` `group_size` `(` $group_size `)`
    `clock_slots` `(` $clock_slots `)`
    `histogram` `(` $histogram_slot `)`
    (`distributed` `halo` `(` $distributed_halo^ `)`)? attr-dict-with-keyword
    $body
  }];
  let hasRegionVerifier = 1;
  let extraClassDeclaration = [{
    ::mlir::Block &getBlock() { return getBody().front(); }
  }];
}

def Plan_ParamOp : Plan_Op<"param", [Symbol, HasParent<"PlanOp">]> {
  let summary = "a scene parameter passed to kernels at run time";
  let description = [{
    A `sim.param` of the scene with its default value. Launches pass the
    run-time value (`#simplan.arg<param @P>`).

    ```mlir
    simplan.param @L = 256 : i32
    ```
  }];
  let arguments = (ins SymbolNameAttr:$sym_name, TypedAttrInterface:$value);
  let assemblyFormat = "$sym_name `=` $value attr-dict";
}

def Plan_BufferOp : Plan_Op<"buffer", [Symbol, HasParent<"PlanOp">]> {
  let summary = "a double-buffered state buffer to allocate";
  let description = [{
    A buffer of `range` elements, allocated as two halves (`2 * range`
    elements of `stride` bytes). Which half holds the state at `T` is the
    clock's parity. `snapshot`: also allocate a snapshot of `range` elements.
    `observed`: the buffer is an output of the scene. `exact`: the scene
    declares its exact solution (the `exact` phase computes it into a
    separate array of `range` elements).

    Distributed plans ([Distributed.md](../Distributed.md)): `halo` gives
    the items below and above an item that reads of the buffer reach, the
    ghost items that travel between ranks; `replicated` says that a gather
    reads the buffer, so every rank holds all `range` items of it, addressed
    as on one process, and an exchange of it is an all-gather of the ranks'
    blocks.

    ```mlir
    simplan.buffer @B0 : vector<4xf32> stride(16) snapshot observed
    simplan.buffer @T : f64 stride(8) halo [1, 1]
    simplan.buffer @X : vector<3xf64> stride(32) observed replicated
    ```
  }];
  let arguments = (ins SymbolNameAttr:$sym_name, TypeAttr:$element_type,
                       I64Attr:$stride, UnitAttr:$snapshot, UnitAttr:$observed,
                       UnitAttr:$exact, OptionalAttr<DenseI64ArrayAttr>:$halo,
                       UnitAttr:$replicated);
  let assemblyFormat = [{
    $sym_name `:` $element_type `stride` `(` $stride `)`
    (`snapshot` $snapshot^)? (`observed` $observed^)? (`exact` $exact^)?
    (`halo` $halo^)? (`replicated` $replicated^)? attr-dict
  }];
}

def Plan_ComponentOp : Plan_Op<"component", [Symbol, HasParent<"PlanOp">]> {
  let summary = "a component: what it writes, how it advances, its counters";
  let description = [{
    The buffers the component writes, and the clock slot to which each
    kernel that evaluates it adds the number of item evaluations it
    performed. `advance` and `estimates` are what `--sim-plan-memory`
    recorded on the component for the plan's strategy: how it advances
    through a big step (`whole_step`, `group_substeps` or `grid_substeps`,
    the sim dialect's `Advance`) and whether its `num_steps` decides the
    size of the big step (an `estimate_C` launch before `advance`). A
    `grid_substeps` component has a sub-step clock of four slots from
    `sub_clock` (docs/Plan.md, "The clock"); no other component has one.
    In a distributed plan a `local_steps` component records `level_reach`:
    how many items beyond a rank's block the level blocks lie whose codes
    the levels its kernels read depend on (the limit's reach, its windows,
    the ghost items), so that `reduce_max_levels` gathers the codes of
    those blocks only. A `local_steps` component whose levels cannot change
    (the sim dialect's `invariant_levels`) records `keeps_levels`: its
    kernels keep every block's code from the first big step longer than
    one base step on, so a distributed run gathers its codes for that big
    step only. Under `lts` the writer of a pair (`local_flux`) that
    estimates bounds the big step by its largest `num_steps`, not its
    smallest (docs/Model.md, "The big step"): it records
    `largest_estimate`, the first of three clock slots (the estimate being
    taken, negated, 0 when there is none; where its last one reached the
    step cap; the estimate kept), and, when its reader keeps its levels,
    `keeps_estimate`: its estimate cannot change either, so `advance` keeps
    the first one taken until the runtime zeroes the kept slot (a new run,
    new parameters), and a distributed run all-reduces it once.

    ```mlir
    simplan.component @C0 writes [@B0] evaluations(8) advance whole_step estimates
    simplan.component @C1 writes [@B1] evaluations(9) advance grid_substeps sub_clock(10)
    simplan.component @C2 writes [@B2] evaluations(11) advance local_steps sub_clock(12) level_reach(161)
    simplan.component @C3 writes [@B3] evaluations(13) advance local_steps sub_clock(14) level_reach(97) keeps_levels
    simplan.component @E writes [@F] evaluations(18) advance local_flux estimates largest_estimate(19) keeps_estimate
    ```
  }];
  let arguments = (ins SymbolNameAttr:$sym_name,
                       FlatSymbolRefArrayAttr:$writes, I64Attr:$evaluations,
                       Plan_AdvanceAttr:$advance, UnitAttr:$estimates,
                       OptionalAttr<I64Attr>:$sub_clock,
                       OptionalAttr<I64Attr>:$level_reach,
                       UnitAttr:$keeps_levels,
                       OptionalAttr<I64Attr>:$largest_estimate,
                       UnitAttr:$keeps_estimate);
  let assemblyFormat = [{
    $sym_name `writes` $writes `evaluations` `(` $evaluations `)`
    `advance` custom<EnumKeyword>($advance) (`estimates` $estimates^)?
    (`sub_clock` `(` $sub_clock^ `)`)?
    (`level_reach` `(` $level_reach^ `)`)?
    (`keeps_levels` $keeps_levels^)?
    (`largest_estimate` `(` $largest_estimate^ `)`)?
    (`keeps_estimate` $keeps_estimate^)? attr-dict
  }];
  let hasVerifier = 1;
}

def Plan_TotalOp : Plan_Op<"total", [Symbol, HasParent<"PlanOp">]> {
  let summary = "a total the scene observes, summed by the runtime";
  let description = [{
    A `sim.total` of the scene: the `total` phase writes its value at every
    item, as `f64`, into an array of `range` elements
    (`#simplan.arg<total @T>`); the runtime adds them in item order in
    double precision. `type` is the type the scene declared.

    ```mlir
    simplan.total @Energy : f64
    ```
  }];
  let arguments = (ins SymbolNameAttr:$sym_name, TypeAttr:$type);
  let assemblyFormat = "$sym_name `:` $type attr-dict";
}

def Plan_PhaseOp : Plan_Op<"phase", [HasParent<"PlanOp">, NoTerminator,
    SingleBlock, NoRegionArguments]> {
  let summary = "a sequence of launches that runs at one point of a run";
  let description = [{
    The launches of the phase in order; each one starts after the previous
    one finished (one CUDA stream, or a CUDA graph of the phase).

    ```mlir
    simplan.phase step {
      simplan.launch @k::@estimate_C0 items [...]
      simplan.launch @k::@advance single [...]
      simplan.launch @k::@step_C0 items [...]
    }
    ```
  }];
  let arguments = (ins Plan_PhaseKindAttr:$kind);
  let regions = (region SizedRegion<1>:$body);
  let assemblyFormat = "custom<EnumKeyword>($kind) attr-dict-with-keyword $body";
}

def Plan_RepeatOp : Plan_Op<"repeat", [NoTerminator, SingleBlock,
    NoRegionArguments, ParentOneOf<["PhaseOp", "RepeatOp"]>]> {
  let summary = "a fixed number of repetitions of some launches";
  let description = [{
    Runs the nested launches `count` times in order. The sub-steps of a
    component that needs a grid-wide barrier between sub-steps are such
    rounds: at most `max_steps` of them, each deciding its size on the
    device; rounds after the last sub-step do nothing.

    ```mlir
    simplan.repeat 3 {
      simplan.launch @k::@substep_estimate_C1 items [...]
      simplan.launch @k::@substep_advance_C1 single [...]
      simplan.launch @k::@substep_C1 items [...]
    }
    ```
  }];
  let arguments = (ins ConfinedAttr<I64Attr, [IntMinValue<1>]>:$count);
  let regions = (region SizedRegion<1>:$body);
  let assemblyFormat = "$count attr-dict-with-keyword $body";
}

def Plan_LaunchOp : Plan_Op<"launch", [
    ParentOneOf<["PhaseOp", "RepeatOp"]>,
    DeclareOpInterfaceMethods<SymbolUserOpInterface>]> {
  let summary = "a kernel launch";
  let description = [{
    Launches `kernel` (a `gpu.func` in the plan's `gpu.module`) with the
    given shape. `args` lists, in order, what the runtime passes for each
    kernel argument. `component` names the component whose buffers the
    launch writes, if any. `shared_per_thread` and `shared_fixed` give the dynamic
    shared memory in bytes: `shared_per_thread * group size + shared_fixed`
    (both 0 when the kernel needs none; static workgroup memory is part of
    the kernel). Where the kernel function is present, its
    `simplan.shared` record must say the same, and its `simplan.clock_slots`
    record must be the plan's `clock_slots`.

    ```mlir
    simplan.launch @k::@substep_C1 items
        [#simplan.arg<clock>, #simplan.arg<buffer @B0>, #simplan.arg<range>]
            for @C1 shared(16, 128)
    ```

    In a distributed plan (docs/Distributed.md) a launch also says what the
    ranks communicate around it: `reduce_min` lists clock slots that every
    rank replaces by their minimum over all ranks before the launch (the
    estimate of the next big step or sub-step, before the launch that
    consumes it); `exchange` lists buffers whose ghost items (both halves)
    travel after the launch, and `exchange_snapshots` buffers whose
    snapshot's ghost items do: the buffers the launch writes that some read
    reaches at other items (for a snapshot, a later component's read:
    `snapshot_ghosts` on the `sim.buffer`). `exchange_targets` lists buffers of which only
    the target half's ghost items travel (half `1 - parity`): those written
    by a component that advances by `whole_step` or `group_substeps`, whose
    launch writes the target half and leaves the source half, which every
    rank already holds, as it was (and those of a parity copy, which
    copies into the target half). `exchange_sub_step` lists buffers of a
    `grid_substeps` component (the launch's) of which only the half its
    sub-step wrote travels: half `1 - (parity xor (d mod 2))` with `d` the
    sub-steps done that the component's sub-step clock holds (its `Done`
    slot) when the launch ends. `exchange_local_step` lists buffers of a
    `local_steps` component (the launch's slot kernel's) of which only the
    ghost items of blocks that start a sub-step at the launch's slot travel,
    each in the half it wrote: with `q` the slot (the sub-step clock's
    `Begin` less `T` before the launch) and `s` a block's sub-step (the
    `Steps` section of the component's `levels`), the blocks with
    `q mod s = 0`, half `1 - (parity xor ((q / s) mod 2))`; the other
    blocks' items, and the other half, are as they travelled before.
    `exchange_local_flux` lists buffers of a flux pair's `local_flux`
    writer (the launch's slot kernel, which passes the `levels` of the
    pair's `local_steps` reader) of which only the target half's ghost
    items of blocks where the reader starts a sub-step at the slot travel:
    the blocks with `q mod s = 0`, `s` the sub-step of the reader's block
    (an interface is due only where its coarsest reader starts a sub-step,
    and an interface read by its own item has a reader in its block whose
    sub-step divides that one's).
    `reduce_max_levels` lists components that take
    local time steps whose blocks' sub-step codes of the big step (half
    `parity` of their `levels`, written by `levels_C`) every rank replaces,
    for the blocks within the component's `level_reach` items of its
    block, by their maximum over the ranks that hold items of them before
    the launch (one exchange with those ranks), so that every rank limits
    the levels it reads as one process would (`limit_levels_C`), and whose
    finest sub-step (`Size` of the sub-step clock, which `limit_levels_C`
    writes) every rank replaces by its minimum over all ranks after the
    launch (one all-reduce), so that every rank takes the same slots.

    ```mlir
    simplan.launch @k::@advance single [#simplan.arg<clock>] reduce_min [4]
    simplan.launch @k::@step_C0 items [...] for @C0 exchange_targets [@B0]
    simplan.launch @k::@limit_levels_C items [...] reduce_max_levels [@C]
    simplan.launch @k::@substep_C items [...] for @C exchange_sub_step [@U]
    simplan.launch @k::@local_step_C items [...] for @C exchange_local_step [@U]
    simplan.launch @k::@local_flux_E items [...] for @E exchange_local_flux [@F]
    ```
  }];
  let arguments = (ins SymbolRefAttr:$kernel, Plan_LaunchShapeAttr:$shape,
                       TypedArrayAttrBase<Plan_ArgAttr, "launch arguments">:$args,
                       OptionalAttr<FlatSymbolRefAttr>:$component,
                       DefaultValuedAttr<I64Attr, "0">:$shared_per_thread,
                       DefaultValuedAttr<I64Attr, "0">:$shared_fixed,
                       OptionalAttr<DenseI64ArrayAttr>:$reduce_min,
                       OptionalAttr<FlatSymbolRefArrayAttr>:$exchange,
                       OptionalAttr<FlatSymbolRefArrayAttr>:$exchange_snapshots,
                       OptionalAttr<FlatSymbolRefArrayAttr>:$reduce_max_levels,
                       OptionalAttr<FlatSymbolRefArrayAttr>:$exchange_targets,
                       OptionalAttr<FlatSymbolRefArrayAttr>:$exchange_sub_step,
                       OptionalAttr<FlatSymbolRefArrayAttr>:$exchange_local_step,
                       OptionalAttr<FlatSymbolRefArrayAttr>:$exchange_local_flux);
  let assemblyFormat = [{
    $kernel custom<EnumKeyword>($shape) $args (`for` $component^)?
    (`shared` `(` $shared_per_thread^ `,` $shared_fixed `)`)?
    (`reduce_min` $reduce_min^)? (`exchange` $exchange^)?
    (`exchange_snapshots` $exchange_snapshots^)?
    (`reduce_max_levels` $reduce_max_levels^)?
    (`exchange_targets` $exchange_targets^)?
    (`exchange_sub_step` $exchange_sub_step^)?
    (`exchange_local_step` $exchange_local_step^)?
    (`exchange_local_flux` $exchange_local_flux^)? attr-dict
  }];
  let extraClassDeclaration = [{
    ::mlir::LogicalResult
    verifyCommunication(PlanOp plan,
                        ::mlir::SymbolTableCollection &symbolTable);
  }];
}

#endif // SIM_DIALECT_PLAN_IR_PLANOPS_TD
