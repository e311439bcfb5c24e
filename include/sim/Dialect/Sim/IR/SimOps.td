//===- SimOps.td - sim dialect operations ------------------*- tablegen -*-===//
//
// The operations of a simulation: the simulation itself, its parameters,
// buffers, components, schedule and observed outputs, and the operations that
// may appear inside component and buffer bodies.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_IR_SIMOPS_TD
#define SIM_DIALECT_SIM_IR_SIMOPS_TD

include "sim/Dialect/Sim/IR/SimDialect.td"
include "sim/Dialect/Sim/IR/SimAttrs.td"
include "sim/Dialect/Sim/IR/SimInterfaces.td"
include "mlir/IR/OpAsmInterface.td"
include "mlir/IR/OpBase.td"
include "mlir/IR/RegionKindInterface.td"
include "mlir/IR/SymbolInterfaces.td"
include "mlir/Interfaces/ControlFlowInterfaces.td"
include "mlir/Interfaces/SideEffectInterfaces.td"

class Sim_Op<string mnemonic, list<Trait> traits = []>
    : Op<Sim_Dialect, mnemonic, traits>;

/// The simulation state (all buffers). View reads and explicit loads read it;
/// declaring the effect lets CSE merge identical reads but never move them
/// across anything that writes state.
def Sim_StateResource : Resource<"::mlir::sim::StateResource">;

/// The shared-memory caches of interpolated values (hip-cache): a fill writes
/// them, cache loads read them.
def Sim_CacheResource : Resource<"::mlir::sim::CacheResource">;

def Sim_TimeStepAttr : AnyAttrOf<[F32Attr, F64Attr]>;

//===----------------------------------------------------------------------===//
// SimulationOp
//===----------------------------------------------------------------------===//

def Sim_SimulationOp : Sim_Op<"simulation", [
    Symbol, SymbolTable, IsolatedFromAbove, NoTerminator, SingleBlock,
    NoRegionArguments, RegionKindInterface, HasOnlyGraphRegion]> {
  let summary = "a component-based simulation over a range of items";
  let description = [{
    A simulation advances the state of `range` items in base steps of `dt`
    time units. Big steps take at most `max_steps` base steps. The body is a
    graph region (order does not matter) of `sim.param`, `sim.buffer`,
    `sim.component`, `sim.total`, at most one `sim.schedule` and at most one
    `sim.observe`.

    ```mlir
    sim.simulation @gravity_like range(65536) dt(1.0e-3 : f32) max_steps(3) {
      sim.param @L = 8 : i32
      sim.buffer @B0 : vector<4xf32> interp(#sim.linear) init { ... }
      sim.component @C0 writes(@B0) num_steps { ... } evaluate { ... }
      sim.observe [@B0]
    }
    ```

    Simulations are ops of the top-level module, where the passes and
    `sim-translate` look for them: the verifier rejects one in a nested
    module. Lowering `@name` adds a top-level module `@name_kernels`
    (`--sim-lower-to-gpu`, `--sim-lower-to-cpu`) or `@name_reference`
    (`--sim-lower-to-reference`), so no other symbol may have that name.

    `range`, `dt` and `max_steps` can be overridden without editing the file:
    `sim-opt --sim-set-params="values=range=16384,max_steps=2"`.

    Bodies compute defined values, so the verifier rejects, at the operation,
    what makes a poison value: `ub.poison`, the poison index `-1` (it is not
    the last element) or a constant index out of range in `vector.extract`
    and `vector.insert`, and `-1` in a `vector.shuffle` mask.

    `strategy` is recorded by `--sim-plan-memory`: the memory plan and the
    explicit reads that `--sim-insert-interpolation` produces are for that
    strategy. So is `step_cap`, the largest big step the strategy takes (1
    under `simple`, `max_steps` otherwise), which the lowering and the
    runtime read.

    `distributed_halo` is recorded by `--sim-plan-halos` for a scene
    compiled for many processes (docs/Distributed.md): the most items any
    read reaches below or above its item, the ghost items each rank keeps on
    either side of its block. The lowering then addresses a rank's block
    and takes reads of other items from the ghosts.
  }];

  let arguments = (ins SymbolNameAttr:$sym_name, I64Attr:$range,
                       Sim_TimeStepAttr:$dt, I32Attr:$max_steps,
                       OptionalAttr<Sim_StrategyAttr>:$strategy,
                       OptionalAttr<I32Attr>:$step_cap,
                       OptionalAttr<I64Attr>:$distributed_halo);
  let regions = (region SizedRegion<1>:$body);
  let assemblyFormat = [{
    $sym_name `range` `(` $range `)` `dt` `(` $dt `)`
    `max_steps` `(` custom<MaxSteps>($max_steps) `)`
    attr-dict-with-keyword $body
  }];
  let hasVerifier = 1;
  let hasRegionVerifier = 1;

  let extraClassDeclaration = [{
    /// The largest item range (2^40: byte offsets of every buffer fit in
    /// 64 bits, and the runtime takes no more) and the largest max_steps
    /// (the clock counts big steps of every size up to it).
    static constexpr int64_t kMaxRange = int64_t(1) << 40;
    static constexpr int64_t kMaxMaxSteps = int64_t(1) << 20;
    /// The scalar float type of the base time step (f32 or f64).
    ::mlir::FloatType getTimeStepType() {
      return ::llvm::cast<::mlir::FloatType>(
          ::llvm::cast<::mlir::TypedAttr>(getDt()).getType());
    }
    /// The base time step as a double.
    double getTimeStep() {
      return ::llvm::cast<::mlir::FloatAttr>(getDt()).getValueAsDouble();
    }
    auto getBuffers() { return getBody().front().getOps<BufferOp>(); }
    auto getComponents() { return getBody().front().getOps<ComponentOp>(); }
    auto getParams() { return getBody().front().getOps<ParamOp>(); }
    auto getTotals() { return getBody().front().getOps<TotalOp>(); }
    /// The schedule, or null when the user gave none and no pass made one.
    ScheduleOp getScheduleOp();
    /// The observed outputs, or null.
    ObserveOp getObserveOp();
    BufferOp lookupBuffer(::mlir::FlatSymbolRefAttr name) {
      return ::llvm::dyn_cast_or_null<BufferOp>(lookupSymbol(name));
    }
    ComponentOp lookupComponent(::mlir::FlatSymbolRefAttr name) {
      return ::llvm::dyn_cast_or_null<ComponentOp>(lookupSymbol(name));
    }
    ::mlir::Operation *lookupSymbol(::mlir::FlatSymbolRefAttr name) {
      return ::mlir::SymbolTable::lookupSymbolIn(*this, name.getAttr());
    }
    /// The component that writes `buffer` (verified IR has exactly one), or
    /// null when no component writes it. Every writer lookup goes through
    /// these two.
    ComponentOp getWriter(BufferOp buffer);
    ComponentOp getWriter(::mlir::FlatSymbolRefAttr buffer);
    /// Checks that no symbol beside each of `simulations` has the name
    /// `<sym_name><suffix>` that the lowering `pass` (its argument, without
    /// `--`) gives the module it puts that simulation's `what` in
    /// ("kernels"), with an error at each such symbol. A lowering calls it
    /// before it creates any module, so that every clash is reported.
    static ::llvm::LogicalResult checkLoweredNamesAreFree(
        ::llvm::ArrayRef<SimulationOp> simulations, ::llvm::StringRef suffix,
        ::llvm::StringRef what, ::llvm::StringRef pass);
    /// The index of `component` in the order recorded on `sim.schedule`, or
    /// std::nullopt when there is no schedule or it does not list the
    /// component (a prefix given by the user).
    std::optional<unsigned> getSchedulePosition(ComponentOp component);
    /// Every component in the order a complete `sim.schedule` gives (what
    /// --sim-schedule records), or std::nullopt without one (no schedule,
    /// or only a prefix given by the user).
    std::optional<::llvm::SmallVector<ComponentOp>> getScheduledOrder();
    /// The first `sim.load` or `sim.big_step` in a component body, or null.
    /// A simulation that has one is past `--sim-insert-interpolation`: its
    /// schedule, verdicts and memory plan are fixed.
    ::mlir::Operation *findExplicitAccess();
    /// Fails with an error naming `passArgument` (empty: a lowering) when a
    /// buffer is still `constant`: every stage after
    /// `--sim-inline-constants` relies on every buffer having a writer.
    ::mlir::LogicalResult checkConstantsInlined(::llvm::StringRef passArgument);
    /// True for `range`, `dt` and `max_steps`: the simulation's own
    /// parameters, which `sim.get_param` reads like a `sim.param` and which
    /// no `sim.param` may be named.
    static bool isBuiltinParamName(::llvm::StringRef name) {
      return name == "range" || name == "dt" || name == "max_steps";
    }
    /// The type `sim.get_param` reads a builtin parameter with: `range` is
    /// i64, `dt` the time step type, `max_steps` i32; null for other names.
    ::mlir::Type getBuiltinParamType(::llvm::StringRef name);
  }];
}

//===----------------------------------------------------------------------===//
// ParamOp / GetParamOp
//===----------------------------------------------------------------------===//

def Sim_ParamOp : Sim_Op<"param", [Symbol, HasParent<"SimulationOp">]> {
  let summary = "a named scene parameter with a default value";
  let description = [{
    A scalar parameter of the scene (an integer or float), read in bodies with
    `sim.get_param`. Tools override the default without editing the file:
    `sim-opt --sim-set-params="L=64"`.

    ```mlir
    sim.param @L = 256 : i32
    sim.param @stiffness = 2.5e+01 : f32
    ```
  }];
  let arguments = (ins SymbolNameAttr:$sym_name, TypedAttrInterface:$value);
  let assemblyFormat = "$sym_name `=` $value attr-dict";
  let hasVerifier = 1;
}

def Sim_GetParamOp : Sim_Op<"get_param", [Pure,
    DeclareOpInterfaceMethods<SymbolUserOpInterface>]> {
  let summary = "reads a scene parameter or the simulation's range, dt or max_steps";
  let description = [{
    Returns the current value of a `sim.param` of the enclosing simulation,
    or of one of the simulation's own parameters: `@range : i64` (the
    number of items), `@dt : <dt type>` (the base time step, `f32` or `f64`
    as declared by `dt(...)`) and `@max_steps : i32`. The result type must be
    the parameter's type. Every body (`init`, `exact`, `num_steps`,
    `evaluate`) may read every parameter.

    Parameters are run-time values: a lowering passes them to the kernels,
    so one compiled scene runs with any values `--sim-set-params` or the
    runtime gives them. The compiler never reads a parameter's default to
    decide anything (an item index computed from one is a gather).

    ```mlir
    %L = sim.get_param @L : i32
    %dt = sim.get_param @dt : f32
    %range = sim.get_param @range : i64
    %max = sim.get_param @max_steps : i32
    ```
  }];
  let arguments = (ins FlatSymbolRefAttr:$param);
  let results = (outs AnyType:$result);
  let assemblyFormat = "$param attr-dict `:` type($result)";
  let hasVerifier = 1;
  let extraClassDeclaration = [{
    /// True when this reads `range`, `dt` or `max_steps` of the simulation
    /// rather than a `sim.param`.
    bool isBuiltin();
  }];
}

//===----------------------------------------------------------------------===//
// BufferOp
//===----------------------------------------------------------------------===//

def Sim_BufferOp : Sim_Op<"buffer", [
    Symbol, IsolatedFromAbove, HasParent<"SimulationOp">,
    DeclareOpInterfaceMethods<OpAsmOpInterface, ["getAsmBlockArgumentNames"]>,
    DeclareOpInterfaceMethods<SymbolUserOpInterface>]> {
  let summary = "a double-buffered state buffer with one element per item";
  let description = [{
    A buffer holds one element per item of the simulation's range: a scalar
    `f32` or `f64`, or a vector of up to 16 of them. It is double-buffered
    (source = value at `T`, target = value at `T + m`) and written by exactly
    one component, unless it is `constant`.

    - `interp(...)`: how a later component reconstructs the buffer at an
      intermediate time (default `#sim.linear`), or `interp(none)` when its
      value means nothing between the ends of a big step (see `#sim.none`).
    - `boundary(...)`: what reads outside `[0, range)` return (default
      `clamp`).
    - `constant`: no component writes the buffer; its `init` gives its
      value at every time (a material field, a mass, a rest length). It
      takes neither `interp(...)` nor `exact`, and `sim.observe` cannot
      name it. `--sim-inline-constants`, the first pass of the front end,
      replaces every read of it with its init at the item read (after the
      boundary rule), so no backend stores, copies or interpolates it.
    - `init`: the initial state of item `%i` at time 0. Reads in it see the
      initial state of other buffers.
    - `exact` (optional): the exact solution at item `%i` and time `%t`
      (`f64`, in time units), used to report the error of a run. Reads in it
      see initial states.
    - `snapshot` (set by `--sim-plan-memory`): the plan keeps a copy of the
      value at `T` for later interpolating readers.
    - `halo` (set by `--sim-plan-halos`, distributed scenes only): the
      items below and above an item that reads of the buffer reach, as
      `array<i64: below, above>`; the ghost items that travel between ranks.
    - `replicated` (set by `--sim-plan-halos`, distributed scenes only): a
      gather reads the buffer, so every rank holds all of it and the blocks
      its writer computes are all-gathered after each write.
    - `snapshot_ghosts` (set by `--sim-plan-halos`, distributed scenes
      only, on a buffer with a `snapshot`): a later component reads other
      items of the buffer between `T` and `T + m` (a window or a gather),
      so the snapshot's ghost items (all of it when `replicated`) travel
      after the snapshot is taken. Without it only the writer reads other
      items, of its own halves, and the snapshot stays on its rank.

    ```mlir
    sim.buffer @X : f64 interp(#sim.hermite<@V>) boundary(wrap) init {
    ^bb0(%i: index):
      %c = arith.constant 1.0 : f64
      sim.yield %c : f64
    } exact {
    ^bb0(%i: index, %t: f64):
      %x = math.cos %t : f64
      sim.yield %x : f64
    }
    ```
  }];

  let arguments = (ins SymbolNameAttr:$sym_name, TypeAttr:$element_type,
                       OptionalAttr<Sim_InterpolationAttrInterface>:$interp,
                       DefaultValuedAttr<Sim_BoundaryAttr,
                                         "::mlir::sim::Boundary::clamp">:$boundary,
                       UnitAttr:$constant, UnitAttr:$snapshot,
                       OptionalAttr<DenseI64ArrayAttr>:$halo,
                       UnitAttr:$replicated, UnitAttr:$snapshot_ghosts);
  let regions = (region SizedRegion<1>:$init, MaxSizedRegion<1>:$exact);
  let assemblyFormat = [{
    $sym_name `:` $element_type ``
    custom<BufferClauses>($interp, $boundary, $constant)
    attr-dict-with-keyword custom<BufferBodies>($init, $exact)
  }];
  let hasVerifier = 1;

  let extraClassDeclaration = [{
    /// The interpolation function, `#sim.linear` when none is given.
    InterpolationAttrInterface getInterpolation();
    /// The element's scalar float type (f32 or f64).
    ::mlir::FloatType getScalarType();
    /// Bytes of one element.
    int64_t getElementBytes();

    /// The item argument `%i` of the init body.
    ::mlir::BlockArgument getInitItem() {
      return getInit().front().getArgument(0);
    }
    /// The item argument `%i` of the exact body (requires an exact body).
    ::mlir::BlockArgument getExactItem() {
      return getExact().front().getArgument(0);
    }
    /// The time argument `%t: f64` (time units) of the exact body.
    ::mlir::BlockArgument getExactTime() {
      return getExact().front().getArgument(1);
    }
  }];
}

//===----------------------------------------------------------------------===//
// TotalOp
//===----------------------------------------------------------------------===//

def Sim_TotalOp : Sim_Op<"total", [
    Symbol, IsolatedFromAbove, HasParent<"SimulationOp">,
    DeclareOpInterfaceMethods<OpAsmOpInterface, ["getAsmBlockArgumentNames"]>]> {
  let summary = "a total the scene observes: a sum over all items";
  let description = [{
    A total (energy, momentum, mass) is the sum over all items `%i` of the
    range of the value its body yields for `%i`: one `f32` or `f64` scalar
    (the declared type). Reads in the body see every buffer at the current
    time `T` (the state a runtime reads after a run), not initial states as
    in `init` and `exact` bodies, and not an interpolation. A runtime adds
    the per-item values in item order in double precision.

    A total is an output like an observed buffer: `--sim-prune` keeps
    everything its body reads. It is not a component: the schedule, the
    dependency graph and the memory plan ignore it, and
    `--sim-insert-interpolation` turns its reads into loads of the
    `source` copy (the half the clock's parity selects).

    ```mlir
    sim.total @Energy : f64 {
    ^bb0(%i: index):
      %v = sim.read @V[%i] : f64
      %half = arith.constant 0.5 : f64
      %v2 = arith.mulf %v, %v : f64
      %e = arith.mulf %half, %v2 : f64
      sim.yield %e : f64
    }
    ```
  }];

  let arguments = (ins SymbolNameAttr:$sym_name, TypeAttr:$value_type);
  let regions = (region SizedRegion<1>:$body);
  let assemblyFormat = [{
    $sym_name `:` $value_type attr-dict-with-keyword $body
  }];
  let hasVerifier = 1;

  let extraClassDeclaration = [{
    /// The item argument `%i` of the body.
    ::mlir::BlockArgument getItem() { return getBody().front().getArgument(0); }
  }];
}

//===----------------------------------------------------------------------===//
// ComponentOp
//===----------------------------------------------------------------------===//

def Sim_ComponentOp : Sim_Op<"component", [
    Symbol, IsolatedFromAbove, HasParent<"SimulationOp">,
    DeclareOpInterfaceMethods<OpAsmOpInterface, ["getAsmBlockArgumentNames"]>,
    DeclareOpInterfaceMethods<SymbolUserOpInterface>]> {
  let summary = "a component that advances the buffers it writes";
  let description = [{
    A component advances every buffer in `writes` (one or more: an integrator
    updates position and velocity together) from local time `t` to `t + n`
    base steps.

    - `num_steps` (optional) has arguments `(%i: index, %t: i64)` and yields
      an `i32`: how many base steps item `%i` could take from local time `%t`
      (values below 1 count as 1). Without it the component never limits a
      step.
    - `evaluate` has arguments `(%i: index, %t: i64, %n: i32, %dt: <dt type>)`
      and yields the new value of each written buffer, in `writes` order,
      after `%n` base steps of `%dt` from local time `%t`.

    Both bodies (like buffer bodies) may read the simulation's `range`, `dt`
    and `max_steps` with `sim.get_param`. C++ code reaches the arguments by
    name: `getNumStepsItem()`, `getNumStepsTime()`, `getEvaluateItem()`,
    `getEvaluateTime()`, `getEvaluateSteps()`, `getEvaluateTimeStep()`.

    Both bodies read state only through `sim.read`. The analyses record
    their verdicts as attributes: `sub_stepping` and, for a `grid_sync`
    component that may take local time steps, `local_window = array<i64: lo,
    hi>`, the offsets at which it reads its own buffers (through the
    fluxes of a flux pair too), with `local_reads = array<i64: lo0, hi0,
    lo1, hi1, ...>` the windows of those reads where they leave gaps of
    more than two blocks (a stencil on a flattened grid: the kernels then test only
    the blocks the reads reach), and, for the flux writer of a flux pair,
    `flux_window = array<i64: lo, hi>`, the offsets at which its reader
    reads its `#sim.flux` buffers, with `local_window` the offsets at which
    it reads the reader's state (`--sim-substep-legality`);
    `advance` (how the component advances through a big step), `estimates`
    (its `num_steps` decides the size of the big step), `invariant_levels`
    (under `lts`, on a `local_steps` component whose `num_steps`, and its
    flux writer's, read neither `%t` nor a buffer: its blocks' levels are
    computed once per run and kept), `invariant_estimate` (on a
    `grid_substeps` component whose `num_steps` reads neither `%t` nor a
    buffer: the grid-wide minimum of its first round holds for every round
    of the big step, so later rounds do not estimate), `parity` and, under
    `hip-cache`, `caches` (a `#sim.cache<@B, lo, hi>` for each buffer whose
    interpolated values in the window `i+lo..i+hi` the component caches in
    shared memory), all by `--sim-plan-memory` for its strategy.

    ```mlir
    sim.component @Integrate writes(@X, @V) num_steps {
    ^bb0(%i: index, %t: i64):
      %c2 = arith.constant 2 : i32
      sim.yield %c2 : i32
    } evaluate {
    ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
      %x = sim.read @X[%i] : f64
      %v = sim.read @V[%i] : f64
      ...
      sim.yield %x1, %v1 : f64, f64
    }
    ```
  }];

  let arguments = (ins SymbolNameAttr:$sym_name,
                       FlatSymbolRefArrayAttr:$writes,
                       OptionalAttr<Sim_SubSteppingAttr>:$sub_stepping,
                       OptionalAttr<DenseI64ArrayAttr>:$local_window,
                       OptionalAttr<DenseI64ArrayAttr>:$local_reads,
                       OptionalAttr<DenseI64ArrayAttr>:$flux_window,
                       OptionalAttr<Sim_AdvanceAttr>:$advance,
                       UnitAttr:$estimates,
                       UnitAttr:$invariant_levels,
                       UnitAttr:$invariant_estimate,
                       OptionalAttr<Sim_ParityAttr>:$parity,
                       OptionalAttr<TypedArrayAttrBase<Sim_CacheAttr,
                           "array of #sim.cache">>:$caches);
  let regions = (region MaxSizedRegion<1>:$num_steps, SizedRegion<1>:$evaluate);
  let assemblyFormat = [{
    $sym_name `writes` `` custom<SymbolList>($writes) attr-dict-with-keyword
    custom<ComponentBodies>($num_steps, $evaluate)
  }];
  let hasVerifier = 1;

  let extraClassDeclaration = [{
    /// True when the component has a `num_steps` body.
    bool hasNumSteps() { return !getNumSteps().empty(); }
    /// True when `buffer` is one of the buffers this component writes.
    bool writesBuffer(::mlir::FlatSymbolRefAttr buffer);

    // The arguments of the bodies by name; code never indexes them. The
    // num_steps accessors require hasNumSteps().

    /// The item argument `%i: index` of num_steps.
    ::mlir::BlockArgument getNumStepsItem() {
      return getNumSteps().front().getArgument(0);
    }
    /// The local time argument `%t: i64` (base steps) of num_steps.
    ::mlir::BlockArgument getNumStepsTime() {
      return getNumSteps().front().getArgument(1);
    }
    /// The item argument `%i: index` of evaluate.
    ::mlir::BlockArgument getEvaluateItem() {
      return getEvaluate().front().getArgument(0);
    }
    /// The local time argument `%t: i64` (base steps) of evaluate: the start
    /// of the sub-step.
    ::mlir::BlockArgument getEvaluateTime() {
      return getEvaluate().front().getArgument(1);
    }
    /// The sub-step length argument `%n: i32` (base steps) of evaluate.
    ::mlir::BlockArgument getEvaluateSteps() {
      return getEvaluate().front().getArgument(2);
    }
    /// The base time step argument `%dt` (the simulation's dt type) of
    /// evaluate.
    ::mlir::BlockArgument getEvaluateTimeStep() {
      return getEvaluate().front().getArgument(3);
    }
  }];
}

//===----------------------------------------------------------------------===//
// ScheduleOp / ObserveOp
//===----------------------------------------------------------------------===//

def Sim_ScheduleOp : Sim_Op<"schedule", [HasParent<"SimulationOp">,
    DeclareOpInterfaceMethods<SymbolUserOpInterface>]> {
  let summary = "the order of components within one step";
  let description = [{
    The components in the order one step runs them; the back edge runs from
    the last to the first. A user may give a full order or a prefix (at least
    the component that starts a step, which decides where the dependency
    cycle is cut). `--sim-schedule` validates it against the dependency graph,
    completes a prefix, and records in `bounded_by` the components whose
    `num_steps` bound the `hip` big step (those that read through the back
    edge and have a `num_steps` body; without one a component never bounds a
    step). Without `bounded_by` only `max_steps` bounds the step.

    ```mlir
    sim.schedule [@C0]
    // after --sim-schedule:
    sim.schedule [@C0, @C1, @C2, @C3, @C4] bounded_by [@C0]
    ```
  }];
  let arguments = (ins FlatSymbolRefArrayAttr:$order,
                       OptionalAttr<FlatSymbolRefArrayAttr>:$bounded_by);
  let assemblyFormat = "$order (`bounded_by` $bounded_by^)? attr-dict";
}

def Sim_ObserveOp : Sim_Op<"observe", [HasParent<"SimulationOp">,
    DeclareOpInterfaceMethods<SymbolUserOpInterface>]> {
  let summary = "the buffers that are the outputs of the simulation";
  let description = [{
    The observed buffers are what the scene is for: `--sim-prune` removes
    every component and buffer they do not depend on.

    ```mlir
    sim.observe [@B2]
    ```
  }];
  let arguments = (ins FlatSymbolRefArrayAttr:$buffers);
  let assemblyFormat = "$buffers attr-dict";
}

//===----------------------------------------------------------------------===//
// Body operations
//===----------------------------------------------------------------------===//

def Sim_YieldOp : Sim_Op<"yield", [Pure, Terminator, ReturnLike,
    ParentOneOf<["BufferOp", "ComponentOp", "FillCacheOp", "TotalOp"]>]> {
  let summary = "returns the values of a buffer, component, fill or total body";
  let description = [{
    Terminates `init`, `exact`, `num_steps`, `evaluate` and total bodies.

    ```mlir
    sim.yield %x, %v : f64, f64
    ```
  }];
  let arguments = (ins Variadic<AnyType>:$values);
  let assemblyFormat = "($values^ `:` type($values))? attr-dict";
}

def Sim_ReadOp : Sim_Op<"read", [
    DeclareOpInterfaceMethods<SymbolUserOpInterface>,
    MemoryEffects<[MemRead<Sim_StateResource>]>]> {
  let summary = "a view read: a buffer at an item, at the reader's local time";
  let description = [{
    Reads buffer `@B` at item `%j` "at my current local time": in `evaluate`
    at the end `t + n` of the sub-step for buffers advanced earlier in the
    step, at `T` for buffers read through the back edge, and the own current
    state for buffers the component writes; in `num_steps` everything at `t`;
    in `init` and `exact` bodies the initial state; in a `sim.total` body the
    state at `T`. The index may be any
    value; the analyses classify it (own item, window `%i + c`, gather).
    Items outside the range follow the buffer's boundary rule.

    `--sim-schedule` records the read's role (`own`, `interpolate`,
    `back_edge`) after the index.

    ```mlir
    %v = sim.read @B0[%j] : vector<4xf32>
    %w = sim.read @B0[%j] interpolate : vector<4xf32>
    ```
  }];
  let arguments = (ins FlatSymbolRefAttr:$buffer, Index:$index,
                       OptionalAttr<Sim_ReadRoleAttr>:$role);
  let results = (outs AnyType:$result);
  let assemblyFormat = [{
    $buffer `[` $index `]` `` custom<OptionalReadRole>($role) attr-dict
    `:` type($result)
  }];
  let hasVerifier = 1;
}

def Sim_LoadOp : Sim_Op<"load", [
    DeclareOpInterfaceMethods<SymbolUserOpInterface>,
    MemoryEffects<[MemRead<Sim_StateResource>]>]> {
  let summary = "an explicit read of one copy of a buffer";
  let description = [{
    Produced by `--sim-insert-interpolation` from view reads: reads item `%j`
    of one specific copy of a buffer (`source`, `snapshot`, `target`, the
    component's `local` state, or under `hip-cache` the interpolated value a
    `sim.fill_cache` of the body describes). Nothing about time is left to derive: a
    lowering turns it into an address computation and a load.

    ```mlir
    %a = sim.load snapshot @B0[%j] : vector<4xf32>
    %b = sim.load target @B0[%j] : vector<4xf32>
    %c = sim.load cache @B0[%k] in_window : vector<4xf32>
    ```

    `in_window` (cache loads only) records that the dependency analysis
    proved the index to be the body's item plus an offset inside the fill's
    window (`%i - 1`, a loop over the window, an index clamped around the
    item): the group's cache always holds it, so a lowering loads the cache
    without a check or a fallback. Without it the lowering checks the index
    against the cache at run time. `--sim-insert-interpolation` sets it, and
    the lowerings reject a load whose index the analysis does not place in
    the window.
  }];
  let arguments = (ins FlatSymbolRefAttr:$buffer, Index:$index,
                       Sim_VersionAttr:$version, UnitAttr:$in_window);
  let results = (outs AnyType:$result);
  let assemblyFormat = [{
    custom<LoadVersion>($version) $buffer `[` $index `]`
    (`in_window` $in_window^)? attr-dict `:` type($result)
  }];
  let hasVerifier = 1;
}

def Sim_FillCacheOp : Sim_Op<"fill_cache", [
    SingleBlock, DeclareOpInterfaceMethods<SymbolUserOpInterface>,
    MemoryEffects<[MemWrite<Sim_CacheResource>]>]> {
  let summary = "the interpolated values of one buffer that a group caches";
  let description = [{
    Produced by `--sim-insert-interpolation` under `hip-cache`, at the start
    of an `evaluate` body, for each cache the memory plan records
    (`#sim.cache<@B, min, max>` in the component's `caches`). The region
    computes the value of `@B` at item `%k`, interpolated at the sub-step's
    local time (from the body's time values). Once per sub-step a GPU group
    fills its shared memory with the region's values at the items from its
    first item plus `min` to its last item plus `max`, then serves
    `sim.load cache @B[%j]` from it; a read outside those items, and a
    backend without caches, computes the region at `%j` instead. So caching
    never changes a result.

    ```mlir
    sim.fill_cache @B0 window(-4, 4) {
    ^bb0(%k: index):
      %a = sim.load source @B0[%k] : vector<4xf32>
      %b = sim.load target @B0[%k] : vector<4xf32>
      ...
      sim.yield %v : vector<4xf32>
    }
    ...
    %v = sim.load cache @B0[%j] : vector<4xf32>
    ```
  }];
  let arguments = (ins FlatSymbolRefAttr:$buffer, I64Attr:$min_offset,
                       I64Attr:$max_offset);
  let regions = (region SizedRegion<1>:$body);
  let assemblyFormat = [{
    $buffer `window` `(` $min_offset `,` $max_offset `)` attr-dict-with-keyword
    $body
  }];
  let hasRegionVerifier = 1;
}

def Sim_BigStepOp : Sim_Op<"big_step", [Pure]> {
  let summary = "the current big step: its start T and its size m";
  let description = [{
    Inside a component body: the start `T` of the current big step and its
    size `m`, both in base steps. Produced by `--sim-insert-interpolation` to
    compute interpolation fractions; the strategy that executes the body
    defines the values (`simple`: `m = 1`).

    ```mlir
    %T, %m = sim.big_step : i64, i64
    ```
  }];
  let results = (outs I64:$begin, I64:$size);
  let assemblyFormat = "attr-dict `:` type($begin) `,` type($size)";
  let hasVerifier = 1;
}

#endif // SIM_DIALECT_SIM_IR_SIMOPS_TD
