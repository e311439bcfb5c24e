//===- Passes.td - sim dialect passes ----------------------*- tablegen -*-===//
//
// The passes of the sim compiler's front end. docs/Passes.md is generated
// from this file; the pipeline they form is described in docs/Pipeline.md.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_TRANSFORMS_PASSES_TD
#define SIM_DIALECT_SIM_TRANSFORMS_PASSES_TD

include "mlir/Pass/PassBase.td"

def SimSetParams : Pass<"sim-set-params", "::mlir::sim::SimulationOp"> {
  let summary = "Override scene parameters without editing the scene";
  let description = [{
    Sets `sim.param` defaults and the simulation's `range`, `dt` and
    `max_steps` from a list of `name=value` pairs (the last of repeated names
    wins; blanks around names, `=` and commas are not part of them, and an
    empty entry is an error). Integers are decimal or `0x` hexadecimal with
    an optional `-`, as MLIR literals; floats are converted in the
    parameter's own type. Unknown names, values that do not parse, values
    that do not fit the parameter's type (no silent truncation, overflow or
    underflow), a `range` or `max_steps` below 1 and a `dt` that is not
    positive and finite are errors, and so is a simulation the front end has
    planned already (its plan was decided from the old values).

    ```
    sim-opt scene.mlir --sim-set-params="values=range=16384,L=64"
    ```
  }];
  let options = [
    ListOption<"values", "values", "std::string",
               "name=value pairs; names are range, dt, max_steps or a "
               "sim.param of the scene">,
  ];
}

def SimPrintDependencyGraph : Pass<"sim-print-dependency-graph"> {
  let summary = "Print the component/buffer dependency graph (text or DOT)";
  let description = [{
    Prints, for every simulation, its components and buffers, the reads of
    every body with their access pattern (`i`, a window `i-4..i+4`, or
    `gather`), and the read edges between components. When the schedule can
    be determined (see `--sim-schedule`), edges carry their role
    (`interpolate`, `back_edge`) and the step bounds are listed. The IR is
    not changed; the graph goes to standard output.

    With `format=dot` the graph is Graphviz DOT: components are boxes,
    buffers ellipses, back-edge reads dashed purple (as in the paper's
    Fig. 5):

    ```
    sim-opt scene.mlir --sim-print-dependency-graph=format=dot -o /dev/null \
      | dot -Tsvg -o graph.svg
    ```
  }];
  let options = [
    Option<"format", "format", "::mlir::sim::GraphFormat",
           "::mlir::sim::GraphFormat::text", "Output format",
           [{::llvm::cl::values(
               clEnumValN(::mlir::sim::GraphFormat::text, "text",
                          "a readable listing"),
               clEnumValN(::mlir::sim::GraphFormat::dot, "dot",
                          "Graphviz DOT"))}]>,
  ];
}

def SimSchedule : Pass<"sim-schedule", "::mlir::sim::SimulationOp"> {
  let summary = "Order the components of a step and classify every read";
  let description = [{
    Computes the per-step order by a topological sort of the in-step
    dependencies (a component depends on the writers of the buffers it
    reads), with the back edge from the last component to the first.

    The first component of `sim.schedule` starts a step: its reads of other
    components' buffers cross the back edge and see values at `T`. Every
    other dependency must point forward in the step. A user may give a whole
    order (it is validated, not trusted) or a prefix (it is completed). When
    the dependencies have a cycle and no first component is named, when they
    leave more than one possible order, or when they form a cycle inside one
    step, this is an error that names the cycle or the candidates.

    The result is recorded on the IR: `sim.schedule` holds the full order and,
    in `bounded_by`, the components whose `num_steps` bound the `hip` big step
    (those that read through the back edge and have a `num_steps` body,
    Fig. 6; `traditional` is bounded by every component with a `num_steps`
    body). Every `sim.read` in a
    component gets its role: `own`, `interpolate` (a buffer already advanced
    in this step) or `back_edge`.

    ```mlir
    sim.schedule [@C0]
    // becomes
    sim.schedule [@C0, @C1, @C2, @C3, @C4] bounded_by [@C0]
    ```
  }];
}

def SimSubstepLegality
    : Pass<"sim-substep-legality", "::mlir::sim::SimulationOp"> {
  let summary = "Prove, per component, that sub-steps can run inside one kernel";
  let description = [{
    A component's sub-steps run inside one kernel (Algorithm 2), synchronised
    only within a thread group. That is race-free only when the component
    reads the buffers it writes at its own item: then each thread owns its
    item's state between sub-steps. A read of a written buffer at another item
    (a window or a gather) could see a neighbour mid-way through its
    sub-steps, so such a component falls back to a grid-wide barrier between
    sub-steps with a sub-step size that is uniform over the range.

    Records `sub_stepping = #sim<sub_stepping in_kernel>` or `grid_sync` on
    every component and emits a remark that says why for every `grid_sync`
    verdict.

    For `lts` (docs/Model.md, "Local time stepping") it records
    `local_window` on a `grid_sync` component whose reads of its own buffers
    at other items are windows of interpolable buffers, and recognises
    pairs: a flux pair (the first component writes `#sim.flux` buffers that
    one component reads through windows) and an item pair (the first
    component bounds the big step and writes values from that component's
    state that it reads at its own items, such as forces and an integrator,
    or, keeping state of its own, at its neighbours, as the two fields of a
    staggered scheme do). It records
    `flux_window` on the pair's writer and widens its reader's
    `local_window`; a remark on the writer says that the two form a pair, or
    which rule fails and what to change.

    With `remarks=false` the verdicts are recorded the same, and only the
    remarks that hold under every strategy are emitted (a flux buffer whose
    clamp boundary breaks conservation): the front end of `simple` and
    `traditional`, which take no sub-steps, and the reference lowering of a
    bundle, whose strategies' front ends explain their own verdicts, run it
    so.
  }];
  let options = [
    Option<"remarks", "remarks", "bool", /*default=*/"true",
           "Explain every grid_sync verdict and pair in a remark">,
    Option<"pairRemarks", "pair-remarks", "bool", /*default=*/"true",
           "With remarks: also explain the flux and item pairs (which only "
           "the lts strategy forms), and why a pair's shape forms none">,
  ];
}

def SimInlineConstants
    : Pass<"sim-inline-constants", "::mlir::sim::SimulationOp"> {
  let summary = "Compute constant buffers where they are read";
  let description = [{
    A `constant` buffer has no writer: its `init` body gives its value at
    every time (a conductivity field, a mass per particle, a rest length).
    This pass replaces every `sim.read` of one, in any body, with a copy of
    its `init` body at the item read, after the buffer's boundary rule
    (`clamp` reads the nearest item, `wrap` the item modulo `range`, `zero`
    gives a zero element outside the range), and removes the buffer. Reads
    inside the copied body see initial states, as in `init`: a read of any
    buffer there becomes that buffer's `init` at its item too (init bodies
    read each other without a cycle, which the verifier checks, so this
    ends). "Model only what a scene needs": no backend stores, copies,
    exchanges or interpolates a constant buffer, and every backend and the
    reference executor compute the same operations from the same IR. It
    is the front end's first pass; every later stage refuses a simulation
    that still has a constant buffer.

    A read costs the init body's operations instead of a load: an init
    that is expensive and read at many items per evaluation (a window of
    a transcendental field) can be cheaper as a buffer that a component
    without `num_steps` writes once per big step.

    ```mlir
    sim.buffer @K : f64 constant boundary(zero) init {
    ^bb0(%i: index):
      ...
    }
    // In a component: %k = sim.read @K[%j] : f64 becomes the init at
    // clamp(j), selected against zero where j is outside [0, range).
    ```
  }];
  let dependentDialects = ["::mlir::arith::ArithDialect"];
}

def SimPrune : Pass<"sim-prune", "::mlir::sim::SimulationOp"> {
  let summary = "Remove what no observed output depends on";
  let description = [{
    "Model only what a scene needs": starting from the buffers in
    `sim.observe` and the buffers `sim.total` bodies read, keeps the writer of every needed buffer and, transitively
    (across the back edge too), every buffer that the writer reads to compute
    a needed buffer or its step size, the derivative buffers of needed
    buffers' interpolations, and the buffers that needed init and exact
    bodies read. Removes every other component and buffer, and drops a
    written buffer (its `writes` entry and its yielded value, then the dead
    code) from a component that is kept for another buffer. Emits a remark
    per removal. A simulation without `sim.observe` is an error.

    In `evaluate`, a read counts when a needed yielded value depends on it,
    or an operation that stays whatever uses its results (a `memref.store`,
    an op of unknown effects) does. Any other read is dead code: a read
    whose value nothing uses, or uses only for something that is removed.
    It does not keep its buffer, and when the buffer is removed the read is
    removed too, with the body's other dead code and a remark at the read,
    so no read is left naming a buffer that is gone. Reads in `num_steps`,
    `init`, `exact` and `sim.total` bodies all count, used or not.

    ```mlir
    // @C's unused read of @Aux does not keep @Aux (or its writer, @W):
    // both go, and so does the read.
    sim.component @C writes(@X) evaluate {
    ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
      %x = sim.read @X[%i] : f32
      %unused = sim.read @Aux[%i] : f32
      sim.yield %x : f32
    }
    sim.observe [@X]
    ```
  }];
  let dependentDialects = [];
}

def SimDefineEdgeCases
    : Pass<"sim-define-edge-cases", "::mlir::sim::SimulationOp"> {
  let summary = "Give the integer divisions, shifts, float-to-integer "
                "conversions and loops of a scene's bodies one result for "
                "every operand";
  let description = [{
    LLVM leaves some `arith` and `scf` ops undefined for some operands: an
    integer division by 0 or of the smallest integer by -1 (x86 traps),
    a shift by the bit width or more and a float-to-integer conversion of
    NaN or of a value out of the type's range (poison, which SIMD lanes
    and scalar code resolve differently), and an `scf.for` whose step is
    not positive (it never ends). In every body of the simulation this pass
    gives each case the result docs/Model.md ("Other rules") defines, so
    that no operand stops a run and every backend computes the same bits:

    | op | operands | result |
    | --- | --- | --- |
    | `divsi`, `divui`, `ceildivsi`, `ceildivui`, `floordivsi` | divisor 0 | 0 |
    | `remsi`, `remui` | divisor 0 | the dividend (`x = (x / d) * d + x % d` holds) |
    | signed divisions | divisor -1 | the negated dividend, wrapping (`x % -1` is 0) |
    | `shli`, `shrui` | shift of the width or more | 0 |
    | `shrsi` | shift of the width or more | the sign (0 or -1) |
    | `fptosi`, `fptoui` | NaN | 0 |
    | `fptosi`, `fptoui` | beyond the integer type's range | its nearest end (saturated, as PTX's `cvt.rzi`) |
    | `scf.for` | step 0 or negative (0 when unsigned) | no iteration |

    An op whose constant operand rules its case out is left as it is (a
    division by a constant other than 0 and -1 keeps its multiplication by
    the reciprocal). A loop with a constant step that is not positive is
    an error at the loop. Shifts of `index` values are left to the target,
    whose width they depend on. The front end and the reference pipeline
    run this pass, so every backend and the reference executor agree.

    ```
    sim-opt scene.mlir --pass-pipeline='builtin.module(sim.simulation(sim-define-edge-cases))'
    ```
  }];
  let dependentDialects = ["::mlir::arith::ArithDialect"];
}

def SimPlanHalos : Pass<"sim-plan-halos", "::mlir::sim::SimulationOp"> {
  let summary = "Record the ghost items a distributed run exchanges";
  let description = [{
    For a scene compiled for many processes (`sim-translate
    --sim-distributed`, docs/Distributed.md): every rank holds a block of
    the range, and a read of another item must find it in the rank's ghost
    items. From the recorded read windows of the `num_steps`, `evaluate`
    and total bodies, records on every buffer read at other items
    `halo = array<i64: below, above>` (the largest offsets below and above
    the read item; an interpolated read reaches the buffers its
    interpolation reads, a Hermite derivative too, and so does a read
    through the time levels of a `local_steps` component under `lts`, by
    the component or the writer of its pair), and on the simulation
    `distributed_halo`, the largest of them. Reads in `init` and `exact`
    bodies need no ghosts: the kernels recompute initial states.

    A gather (an index that is neither the item plus a bounded offset nor
    one clamped around the item, docs/Model.md) can reach any item: the
    buffer it reads (and, for an interpolated read, the buffers of its
    interpolation) is recorded `replicated` instead, with a remark at the
    read (which, for an index wrapped around by hand, `(%i + c) mod n`,
    names the window `boundary(wrap)` gives instead). Every rank then holds all of it, and the blocks its
    writer computes are all-gathered after each write.
  }];
  let dependentDialects = [];
}

def SimPlanMemory : Pass<"sim-plan-memory", "::mlir::sim::SimulationOp"> {
  let summary = "Plan snapshots and parity copies for a strategy";
  let description = [{
    Decides, for the chosen strategy, which buffers need a snapshot (a copy of
    their value at `T`) and which components need a parity copy after their
    sub-steps (Algorithm 2, lines 41-44; Fig. 4), and records the plan:
    `strategy` on the simulation, `snapshot` on buffers, `parity` on
    components.

    Only what a scene needs is planned. Under `simple` and `traditional`
    every component evaluates once per big step from the source half into the
    target half, so nothing is snapshotted or copied. Under `hip`, an
    `in_kernel` component keeps its own state in registers between sub-steps
    and writes the target once, so its source half still holds the value at
    `T` for later interpolating readers: no snapshot and no parity copy. A
    component without `num_steps` takes the whole big step in one
    evaluation, so it needs neither. Only a `grid_sync` component with
    `num_steps` ping-pongs through memory: it gets `copy_if_even`, and its
    buffers get a snapshot when a later component interpolates them (or
    needs them as an interpolation's auxiliary buffer).
    Under `hip-cache`, `caches` records a `#sim.cache<@B, lo, hi>` for each
    buffer a component interpolates through a window: neighbouring threads
    of a group share those values. `lo` and `hi` are the lowest and highest
    offset over all of the component's interpolated window reads of the
    buffer (own-item reads count as offset 0, gathers not at all). A cache
    is planned only where it can be hit: the range has at least 2 items,
    the window has more than one offset (`hi > lo`), its halo fits the
    thread group (`hi - lo < group-size`) and, with the component's caches
    before it, its `(group-size + hi - lo)` elements fit the 227 KiB of
    shared memory the largest GPUs give a group (otherwise a remark says
    that its reads interpolate from global memory, as under `hip`; the
    runtime checks the device's own limit when a session is made).

    Under `hip` and `hip-cache` an `interpolate` read (in `evaluate` or
    `num_steps`) of a buffer declared `interp(none)` is an error: it would
    need the buffer at an intermediate time of the big step.

    Needs the roles of `--sim-schedule` and the verdicts of
    `--sim-substep-legality`.
  }];
  let options = [
    Option<"strategy", "strategy", "::mlir::sim::Strategy",
           "::mlir::sim::Strategy::hip", "The strategy to plan for",
           "::mlir::sim::getStrategyOptionValues()">,
    Option<"groupSize", "group-size", "int64_t", "256",
           "Threads per group: hip-cache plans a cache only for a window "
           "whose halo is smaller">,
  ];
}

def SimInsertInterpolation
    : Pass<"sim-insert-interpolation", "::mlir::sim::SimulationOp"> {
  let summary = "Turn view reads into explicit loads and interpolations";
  let description = [{
    Replaces every `sim.read` in a component body by explicit `sim.load`s of
    specific buffer copies and, for reads of buffers already advanced in the
    step, the arithmetic of the buffer's interpolation function (Eq. (2)),
    for the strategy the memory plan recorded:

    - `own` reads load the component's `local` state;
    - `back_edge` reads load the `source` half (the value at `T`);
    - `interpolate` reads under `hip`/`hip-cache` load the value at `T`
      (`snapshot` if the plan keeps one, else `source`) and at `T + m`
      (`target`), plus the auxiliary buffers the interpolation needs, and
      interpolate at the reader's local time: fraction `(t + n - T) / m` in
      `evaluate`, `(t - T) / m` in `num_steps`, with `T` and `m` from
      `sim.big_step`. At the ends of the big step (fraction 0 or 1, as at
      every read of a big step of one base step) the read is the copy
      itself (`scf.if` on the local time), exactly, as the reference
      executor returns it; the arithmetic runs only in between. The length
      of the big step in time units (`m * dt`,
      for derivatives) reads `dt` with `sim.get_param @dt`: it is a
      run-time value, not a constant of the scene. Under `simple` and `traditional` they load `target` in
      `evaluate` (the fraction is always 1) and `source` in `num_steps`
      (estimates are taken at `T`).

    The result needs no further analysis to lower: every load names the copy
    it reads. Interpolation functions build their own arithmetic through
    `InterpolationAttrInterface`, so adding one does not touch this pass.
    Reads in init and exact bodies (initial states) are left as they are.
    Reads in `sim.total` bodies load the `source` copy (the state at `T`
    after a run), under every strategy.
  }];
  let dependentDialects = ["::mlir::arith::ArithDialect",
                           "::mlir::scf::SCFDialect",
                           "::mlir::vector::VectorDialect"];
}

def SimReportMemory : Pass<"sim-report-memory"> {
  let summary = "Report the bytes of the memory plan against the naive plan";
  let description = [{
    Prints, for every simulation with a memory plan, the bytes of each
    buffer's halves and snapshot, the shared memory of the `hip-cache`
    caches per thread group, and the total against the naive plan that
    triple-buffers every buffer (source, target and a snapshot of each), so
    that "model only what a scene needs" is a number. The IR is not changed.
    With `format=json` the same numbers are printed as JSON for benchmark
    scripts. Counts are exact 64-bit integers: a plan that needs more than
    2^63 - 1 bytes (a range near 2^63) is an error that names the quantity,
    never a wrapped number.

    Caches follow the paper's design (Section 4.1): for every
    `#sim.cache<@B, lo, hi>` a component has, one interpolated element per
    thread of a group plus the window's halo: `(group-size + hi - lo)`
    elements of `@B`.
  }];
  let options = [
    Option<"format", "format", "::mlir::sim::ReportFormat",
           "::mlir::sim::ReportFormat::text", "Output format",
           [{::llvm::cl::values(
               clEnumValN(::mlir::sim::ReportFormat::text, "text",
                          "a table"),
               clEnumValN(::mlir::sim::ReportFormat::json, "json",
                          "JSON"))}]>,
    Option<"groupSize", "group-size", "int64_t", "256",
           "Threads per group, for the size of hip-cache caches">,
  ];
}

#endif // SIM_DIALECT_SIM_TRANSFORMS_PASSES_TD
