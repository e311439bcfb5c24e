//===- SimAttrs.td - sim dialect attributes and enums ------*- tablegen -*-===//
//
// Interpolation functions (implementations of InterpolationAttrInterface) and
// the enumerations that the analyses and plans record on the IR.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_IR_SIMATTRS_TD
#define SIM_DIALECT_SIM_IR_SIMATTRS_TD

include "sim/Dialect/Sim/IR/SimDialect.td"
include "sim/Dialect/Sim/IR/SimInterfaces.td"
include "mlir/IR/AttrTypeBase.td"
include "mlir/IR/BuiltinAttributeInterfaces.td"
include "mlir/IR/EnumAttr.td"

//===----------------------------------------------------------------------===//
// Enumerations
//===----------------------------------------------------------------------===//

def Sim_Boundary : I32Enum<"Boundary", "rule for reads outside the item range", [
    I32EnumCase<"clamp", 0>, I32EnumCase<"wrap", 1>, I32EnumCase<"zero", 2>]> {
  let cppNamespace = "::mlir::sim";
  let description = [{
    What a read of item `j` outside `[0, range)` returns: `clamp` reads the
    nearest valid item, `wrap` reads item `j mod range` (periodic), `zero`
    returns a zero element. Every backend implements the same rule.
  }];
}
def Sim_BoundaryAttr : EnumAttr<Sim_Dialect, Sim_Boundary, "boundary">;

def Sim_ReadRole : I32Enum<"ReadRole", "role of a view read in the schedule", [
    I32EnumCase<"own", 0>, I32EnumCase<"interpolate", 1>,
    I32EnumCase<"back_edge", 2>]> {
  let cppNamespace = "::mlir::sim";
  let description = [{
    Recorded by `--sim-schedule` on every `sim.read` inside a component:
    `own` reads a buffer the component writes (its current sub-step state),
    `interpolate` reads a buffer already advanced in this big step (its value
    at the reader's local time lies between the value at `T` and at `T + m`),
    `back_edge` reads a buffer that is advanced later in the step, so only its
    value at `T` exists.
  }];
}
def Sim_ReadRoleAttr : EnumAttr<Sim_Dialect, Sim_ReadRole, "read_role">;

def Sim_SubStepping : I32Enum<"SubStepping",
    "how a component's sub-steps are synchronised", [
    I32EnumCase<"in_kernel", 0>, I32EnumCase<"grid_sync", 1>]> {
  let cppNamespace = "::mlir::sim";
  let description = [{
    Recorded by `--sim-substep-legality`. `in_kernel`: all sub-steps of an
    item run inside one kernel, synchronised only within a thread group
    (Algorithm 2); this is race-free because the component reads the buffers
    it writes only at its own item. `grid_sync`: the component reads a buffer
    it writes at another item, so every sub-step needs a grid-wide barrier
    (one launch per sub-step or a cooperative grid sync) and a sub-step size
    that is uniform over the whole range.
  }];
}
def Sim_SubSteppingAttr : EnumAttr<Sim_Dialect, Sim_SubStepping, "sub_stepping">;

def Sim_Parity : I32Enum<"Parity",
    "whether a component needs a parity copy after its sub-steps", [
    I32EnumCase<"none", 0>, I32EnumCase<"copy_if_even", 1>]> {
  let cppNamespace = "::mlir::sim";
  let description = [{
    Recorded by `--sim-plan-memory`. `none`: the component writes its target
    half once per big step, so no parity copy is needed; its source half still
    holds the value at `T` afterwards. That holds for every component under
    `simple` and `traditional` (one evaluation per big step), for
    `in_kernel` components under `hip`, which keep their own state in
    registers between sub-steps, and for components without `num_steps`,
    which take the whole big step in one evaluation. `copy_if_even`: the
    sub-steps of a `grid_sync` component with `num_steps` ping-pong between
    the halves through memory under `hip`, so after an even number of them
    the result sits in the wrong half and must be copied to the target
    (Algorithm 2, lines 41-44).
  }];
}
def Sim_ParityAttr : EnumAttr<Sim_Dialect, Sim_Parity, "parity">;

def Sim_Advance : I32Enum<"Advance",
    "how a component advances through a big step", [
    I32EnumCase<"whole_step", 0>, I32EnumCase<"group_substeps", 1>,
    I32EnumCase<"grid_substeps", 2>, I32EnumCase<"local_steps", 3>,
    I32EnumCase<"local_flux", 4>]> {
  let cppNamespace = "::mlir::sim";
  let description = [{
    Recorded by `--sim-plan-memory` on every component for the strategy it
    plans, and read by every later stage (the lowering, the plan, the
    bundle, the runtime); the reference lowering records it for every
    strategy. `whole_step`: one evaluation per item with `n = m`, from the
    state at `T` into the target half (every component under `simple` and
    `traditional`; under `hip` a component without `num_steps`, or one whose
    `num_steps` bounds the big step, since its minimum at `T` is at least
    `m`). `group_substeps`: sub-steps of the minimum `num_steps` of a thread
    group inside one kernel, the own state in registers (an `in_kernel`
    component with `num_steps` under `hip`). `grid_substeps`: sub-steps of
    the minimum over the whole range, one launch each, ping-ponging between
    the halves (a `grid_sync` component with `num_steps` under `hip`).
    `local_steps`: every thread group advances at its own power-of-two
    sub-step, chosen per big step from its items' `num_steps` and limited to
    twice its neighbours'; reads of its own buffers at other items are
    answered from the two time levels each item keeps (a `grid_sync`
    component with `num_steps` and a recorded `local_window` under `lts`;
    docs/Model.md, "Local time stepping"). `local_flux`: the flux writer of
    a flux pair under `lts` (a component with a recorded `flux_window`): it
    runs inside the slots of the `local_steps` component that reads its
    `#sim.flux` buffers, evaluating every interface at the slots where the
    coarsest block that reads it starts a sub-step (docs/Model.md,
    "Conservation").
  }];
}
def Sim_AdvanceAttr : EnumAttr<Sim_Dialect, Sim_Advance, "advance">;

def Sim_Version : I32Enum<"Version",
    "which copy of a buffer an explicit load reads", [
    I32EnumCase<"source", 0>, I32EnumCase<"snapshot", 1>,
    I32EnumCase<"target", 2>, I32EnumCase<"local", 3>,
    I32EnumCase<"cache", 4>]> {
  let cppNamespace = "::mlir::sim";
  let description = [{
    `source`: the half that holds the value at the start `T` of the big step;
    `snapshot`: the copy of the value at `T` taken before the writer ran (only
    for buffers the memory plan snapshots); `target`: the half that holds the
    value at `T + m` once the writer ran; `local`: the reading component's own
    state at its current local time; `cache`: the interpolated value at the
    reader's local time that the body's `sim.fill_cache` of the buffer
    describes (a GPU serves it from the group's shared-memory cache inside
    the cached window, and computes it like the fill outside it).
  }];
}
def Sim_VersionAttr : EnumAttr<Sim_Dialect, Sim_Version, "version">;

def Sim_Strategy : I32Enum<"Strategy", "how big steps are chosen and run", [
    I32EnumCase<"simple", 0>, I32EnumCase<"traditional", 1>,
    I32EnumCase<"hip", 2>, I32EnumCase<"hip_cache", 3, "hip-cache">,
    I32EnumCase<"lts", 4>]> {
  let cppNamespace = "::mlir::sim";
  let description = [{
    `simple`: every big step is one base step. `traditional`: every component
    estimates, the global minimum is the big step, and every component takes
    it in one evaluation. `hip` (the paper's method): the big step is the
    minimum estimate of the components that read through the back edge, and
    every component advances through it in sub-steps, reading earlier
    components' buffers interpolated in time. `hip-cache`: `hip` with
    shared-memory caches of interpolated values (Section 4.1). `lts`: `hip`
    with local time stepping: a component that reads its own buffers at
    other items through windows advances every thread group at its own rate
    (`advance = local_steps`) instead of the range-wide minimum, and the big
    step is rounded down to a power of two when one does. Recorded on a
    simulation by `--sim-plan-memory`; the pass options use the same names.
    A name with a `-` is printed in quotes:

    ```mlir
    sim.simulation @s range(1024) dt(1.0e-3 : f32) max_steps(4)
        attributes {strategy = #sim<strategy "hip-cache">} { ... }
    ```
  }];
}
def Sim_StrategyAttr : EnumAttr<Sim_Dialect, Sim_Strategy, "strategy">;

//===----------------------------------------------------------------------===//
// Interpolation functions
//===----------------------------------------------------------------------===//

class Sim_Attr<string name, string attrMnemonic, list<Trait> traits = []>
    : AttrDef<Sim_Dialect, name, traits> {
  let mnemonic = attrMnemonic;
}

def Sim_LinearInterpAttr : Sim_Attr<"LinearInterp", "linear", [
    DeclareAttrInterfaceMethods<Sim_InterpolationAttrInterface>]> {
  let summary = "linear interpolation, order 2";
  let description = [{
    `(1 - f) * a + f * b` between the value `a` at `T` and `b` at `T + h`.
    Written in this form (not `a + (b - a) * f`) so that both ends are exact.
    Interpolating a smooth signal has an error in O(h^2).

    ```mlir
    sim.buffer @X : f32 interp(#sim.linear) init { ... }
    ```
  }];
}

def Sim_CubicInterpAttr : Sim_Attr<"CubicInterp", "cubic", [
    DeclareAttrInterfaceMethods<Sim_InterpolationAttrInterface>]> {
  let summary = "the paper's two-point cubic (smoothstep) interpolation, order 1";
  let description = [{
    The paper's cubic spline in the fraction: `s = f * f * (3 - 2 * f)`, then
    `(1 - s) * a + s * b`. It needs no more data than linear interpolation and
    has zero slope at both ends, but it reproduces only constants, so the
    error for a smooth signal is in O(h) (order 1). Use `#sim.hermite` when a
    time derivative is available.

    ```mlir
    sim.buffer @X : vector<4xf32> interp(#sim.cubic) init { ... }
    ```
  }];
}

def Sim_HermiteInterpAttr : Sim_Attr<"HermiteInterp", "hermite", [
    DeclareAttrInterfaceMethods<Sim_InterpolationAttrInterface,
                                ["getAuxiliaryBuffers",
                                 "getAuxiliaryBufferRole"]>]> {
  let summary = "cubic Hermite interpolation with a derivative buffer, order 4";
  let description = [{
    Cubic Hermite interpolation between `(a, a')` at `T` and `(b, b')` at
    `T + h`, where the derivatives come from the named buffer (for example
    velocity for position): `h00(f) a + h10(f) h a' + h01(f) b + h11(f) h b'`.
    It is exact for cubic signals; the error for a smooth signal is in O(h^4).
    The derivative buffer must exist and have the same element type.

    ```mlir
    sim.buffer @X : f64 interp(#sim.hermite<@V>) init { ... }
    sim.buffer @V : f64 init { ... }
    ```
  }];
  let parameters = (ins "::mlir::FlatSymbolRefAttr":$derivative);
  let assemblyFormat = "`<` $derivative `>`";
}

def Sim_NoneInterpAttr : Sim_Attr<"NoneInterp", "none", [
    DeclareAttrInterfaceMethods<Sim_InterpolationAttrInterface,
                                ["isInterpolable"]>]> {
  let summary = "no interpolation: the value means nothing between step ends";
  let description = [{
    Declares that a buffer's value is meaningful only at the ends of a big
    step, such as a momentum at half steps of a leapfrog integrator. Written
    `interp(none)` in a buffer (the printer always uses that form). Reading
    it through the back edge (at `T`), as the own state, or under `simple`
    and `traditional` is fine; under `hip` and `hip-cache` a read that would
    need an intermediate value (an `interpolate` read in `evaluate` or
    `num_steps`) is an error of `--sim-plan-memory`. It may still be the
    derivative buffer of a `#sim.hermite` interpolation, which reads it only
    at both ends.

    ```mlir
    sim.buffer @P : f32 interp(none) init { ... }
    ```
  }];
}

def Sim_FluxInterpAttr : Sim_Attr<"FluxInterp", "flux", [
    DeclareAttrInterfaceMethods<Sim_InterpolationAttrInterface>]> {
  let summary = "a flux through interfaces, constant over its writer's step";
  let description = [{
    Declares that item `j` of the buffer is a flux through an interface
    (between items `j` and `j + 1` for a 1-D scene) over its writer's whole
    step: a read at any time inside the step returns the value the writer
    computed for that step (`b` for every fraction above 0, `a` at 0), so
    every reader that integrates the flux over the step integrates the same
    amount, whatever its own sub-steps. Order 1.

    Under `lts` a component that writes only such buffers, all read by one
    component that writes every buffer the first one reads, forms a **flux
    pair** with it (`--sim-substep-legality` records `flux_window`): each
    interface then steps with the coarsest block among the items that read
    it, and the readers add their shares of its flux in their own
    sub-steps, so a `sim.total` of what the readers update is conserved to
    round-off (docs/Model.md, "Conservation").

    ```mlir
    sim.buffer @F : f64 interp(#sim.flux) boundary(zero) init { ... }
    ```
  }];
}

//===----------------------------------------------------------------------===//
// Memory plan
//===----------------------------------------------------------------------===//

def Sim_CacheAttr : Sim_Attr<"Cache", "cache"> {
  let summary = "a shared-memory cache of a window of interpolated values";
  let description = [{
    Recorded by `--sim-plan-memory` under `hip-cache` in a component's
    `caches`: the component reads buffer `buffer`, interpolated, at the
    items `i + minOffset` to `i + maxOffset` (the window over all of its
    window reads of that buffer in `num_steps` and `evaluate`; own-item
    reads count as offset 0). A thread group of `G` threads shares the
    interpolated values of the items `[first + minOffset, last + maxOffset]`
    around its own items: `G + maxOffset - minOffset` elements of shared
    memory. A read outside the cached items falls back to global memory.

    The plan records a cache only where it can be hit: the range has at
    least 2 items, the window has more than one offset
    (`minOffset < maxOffset`, which the attribute requires) and its halo
    fits the group (`maxOffset - minOffset < group-size`).

    ```mlir
    sim.component @C1 writes(@B1) attributes {caches = [#sim.cache<@B0, -4, 4>]} ...
    ```
  }];
  let parameters = (ins "::mlir::FlatSymbolRefAttr":$buffer,
                        "int64_t":$minOffset, "int64_t":$maxOffset);
  let assemblyFormat = "`<` $buffer `,` $minOffset `,` $maxOffset `>`";
  let genVerifyDecl = 1;
  let extraClassDeclaration = [{
    /// The number of items the window spans around one item, less one:
    /// `maxOffset - minOffset`, the halo a group caches besides its own
    /// items.
    int64_t getHalo() const { return getMaxOffset() - getMinOffset(); }
  }];
}

#endif // SIM_DIALECT_SIM_IR_SIMATTRS_TD
