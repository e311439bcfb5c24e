"""The paper's two benchmark scenes (Section 5), built with `simscene`.

A scene is a list of `ComponentSpec`s: which buffer each component writes and
which buffers it reads, and how (in the window i-4..i+4, or at item i). From
that, `build_scene` makes every body:

* init: a deterministic pseudo-random vec4 in [-1, 1) per item
  (`emit_init_value`, one seed per buffer);
* num_steps: n in [1..3] from a hash of the component, a key that `@dist`
  selects, and the local time (`emit_step_count`);
* evaluate: the reads, four rows derived from them, `@L` rounds of a 4x4
  matrix product (`emit_matrix_load`), then the new value
  (`emit_relaxation`).

`gravity_like` and `pbd_like` take the scene parameters as keyword arguments
so that benchmarks can generate variants (other defaults, `#sim.cubic`
everywhere) without editing the checked-in examples.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass
from typing import Callable, Mapping

from .builder import Body, Simulation
from .emitters import (
    VEC4F,
    emit_init_value,
    emit_matrix_load,
    emit_relaxation,
    emit_step_count,
    emit_window_gather,
)

__all__ = ["ComponentSpec", "build_scene", "gravity_like", "pbd_like",
           "schedule_order"]

WINDOW = "i-4..i+4"


@dataclass(frozen=True)
class ComponentSpec:
    """What a component of a benchmark scene writes and reads.

    `windows` are read at the 9 items i-4..i+4, `points` at item i; `own`
    means the component reads its own buffer at item i (it has a state that
    relaxes); otherwise it recomputes its buffer from its inputs.
    """

    name: str
    writes: str
    windows: tuple[str, ...] = ()
    points: tuple[str, ...] = ()
    own: bool = False
    role: str = ""


def schedule_order(specs: list[ComponentSpec]) -> tuple[list[str], set[tuple[str, str]]]:
    """The step order with `specs[0]` as the entry, as `--sim-schedule` sees it.

    Reads of other components' buffers by the entry are back edges; the other
    reads order writer before reader. Raises ValueError unless exactly one
    order remains. Returns the order and the back-edge reads (reader, buffer).
    """
    writer = {s.writes: s.name for s in specs}
    entry = specs[0].name
    preds: dict[str, set[str]] = {s.name: set() for s in specs}
    back_edges: set[tuple[str, str]] = set()
    for s in specs:
        for buffer in s.windows + s.points:
            w = writer[buffer]
            if w == s.name:
                continue
            if s.name == entry:
                back_edges.add((s.name, buffer))
                continue
            preds[s.name].add(w)
    order: list[str] = []
    remaining = dict(preds)
    while remaining:
        ready = sorted(c for c, p in remaining.items() if not p - set(order))
        if len(ready) != 1:
            raise ValueError(f"the dependency graph leaves no unique order "
                             f"after {order}: ready {ready}")
        order.append(ready[0])
        del remaining[ready[0]]
    if order[0] != entry:
        raise ValueError(f"{entry} is not the first component of {order}")
    return order, back_edges


def _read_list(spec: ComponentSpec, back_edges: set[tuple[str, str]]) -> str:
    parts = []
    if spec.own:
        parts.append(f"{spec.writes}[i] (own)")
    for b in spec.windows:
        parts.append(f"{b}[{WINDOW}]")
    for b in spec.points:
        note = " (back edge: value at T)" if (spec.name, b) in back_edges else ""
        parts.append(f"{b}[i]{note}")
    return ", ".join(parts)


def _evaluate_body(spec: ComponentSpec, back_edges: set[tuple[str, str]],
                   dt_type: str) -> Body:
    body = Body.for_evaluate(dt_type)
    i = body.arg("i")

    state = None
    if spec.own:
        body.comment(f"Own state at item i (the start of the relaxation).")
        state = body.op("self", f"sim.read @{spec.writes}[{i}] : {VEC4F}")
    points = []
    for b in spec.points:
        if (spec.name, b) in back_edges:
            body.comment(f"{b} at item i through the back edge: its value at "
                         "T.")
        else:
            body.comment(f"{b} at item i.")
        points.append(body.op(b.lower(), f"sim.read @{b}[{i}] : {VEC4F}"))

    means = []
    if spec.windows:
        names = ", ".join(spec.windows)
        body.comment(f"Gather the 9 neighbours {WINDOW} of {names} "
                     "(a window read).")
        sums = emit_window_gather(body, spec.windows)
        ninth = body.const("dense<0.111111112>", VEC4F, hint="ninth",
                           comment="1/9")
        means = [body.op(f"mean_{b}", f"arith.mulf {s}, {ninth} : {VEC4F}")
                 for b, s in zip(spec.windows, sums)]

    # Row candidates in order of preference; only the first four are emitted.
    def read_at(buffer: str, offset: int) -> Callable[[], str]:
        def emit() -> str:
            if offset == 0:
                return body.op(f"{buffer.lower()}_i",
                               f"sim.read @{buffer}[{i}] : {VEC4F}")
            c = body.const(offset, "index")
            j = body.op("left" if offset < 0 else "right",
                        f"arith.addi {i}, {c} : index")
            return body.op(f"{buffer.lower()}_{'left' if offset < 0 else 'right'}",
                           f"sim.read @{buffer}[{j}] : {VEC4F}")
        return emit

    candidates: list[tuple[str, Callable[[], str]]] = []
    candidates += [(f"mean of {b}", (lambda v=v: v))
                   for b, v in zip(spec.windows, means)]
    candidates += [(f"{b}[i]", read_at(b, 0)) for b in spec.windows]
    candidates += [(f"{b}[i]", (lambda v=v: v))
                   for b, v in zip(spec.points, points)]
    if state is not None:
        candidates.append((f"{spec.writes}[i] (own)", lambda: state))
    if spec.windows:
        candidates.append((f"{spec.windows[0]}[i-1]",
                           read_at(spec.windows[0], -1)))
        candidates.append((f"{spec.windows[0]}[i+1]",
                           read_at(spec.windows[0], +1)))
    if len(candidates) < 2:
        raise ValueError(f"{spec.name} reads too little to build the load")
    chosen = candidates[:4]
    labels = [label for label, _ in chosen]
    body.comment("The rows of the load: " + ", ".join(labels) +
                 ("" if len(chosen) == 4 else
                  ",\nthe product of the first two and half their difference")
                 + ".")
    rows = [emit() for _, emit in chosen]
    if len(rows) < 4:
        a, b = rows[0], rows[1]
        half = body.const("dense<5.0E-1>", VEC4F, hint="half")
        rows.append(body.op("prod", f"arith.mulf {a}, {b} : {VEC4F}"))
        diff = body.op("diff", f"arith.subf {a}, {b} : {VEC4F}")
        rows.append(body.op("half_diff", f"arith.mulf {diff}, {half} : {VEC4F}"))
    rows = rows[:4]

    force = emit_matrix_load(body, rows, bias=rows[0])
    if state is not None:
        body.comment("Relax towards tanh(force):\n"
                     "new = self + h * (tanh(force) - self), h = min(n * dt, 1).")
    else:
        body.comment("No own state: the new value is tanh(force).")
    new = emit_relaxation(body, state, force)
    body.yield_([new], [VEC4F])
    return body


def build_scene(name: str, header: str, specs: list[ComponentSpec],
                observe: list[str], interp: Mapping[str, str], *,
                range_: int, dt: float, max_steps: int, rounds: int,
                dist: int, group: int) -> Simulation:
    """A scene from its component specs (see the module documentation)."""
    order, back_edges = schedule_order(specs)
    readers: dict[str, list[str]] = {s.writes: [] for s in specs}
    for s in specs:
        for b in s.windows:
            readers[b].append(f"{s.name} ({WINDOW})")
        for b in s.points:
            kind = "back edge" if (s.name, b) in back_edges else "i"
            readers[b].append(f"{s.name} ({kind})")

    graph = ["Dependency graph (who reads what; the order that follows):"]
    for s in specs:
        graph.append(f"  {s.name} writes {s.writes}, reads "
                     f"{_read_list(s, back_edges)}")
    graph.append(f"With {specs[0].name} as the entry the only order is "
                 f"{', '.join(order)}.")
    kinds: dict[str, list[str]] = {}
    for s in specs:
        kinds.setdefault(interp.get(s.writes, "linear"), []).append(s.writes)
    if len(kinds) == 1:
        interp_line = f"Interpolation: #sim.{next(iter(kinds))} for every buffer."
    else:
        interp_line = "Interpolation: " + "; ".join(
            f"#sim.{kind} for {', '.join(buffers)}"
            for kind, buffers in kinds.items()) + "."
    stateless = [s.name for s in specs if not s.own]
    full_header = "\n".join([
        header.strip(),
        "",
        *graph,
        "",
        textwrap.fill(
            "Every component: num_steps = (splitmix64 hash of the component, "
            "a key and the local time t) % 3 + 1, with key = 0 (@dist = 0), "
            "i / @group (@dist = 1) or i (@dist = 2); every n is 1 with @dist = 3 "
            "and max_steps with @dist = 4. evaluate builds four "
            "vec4 rows from its reads, runs @L rounds of a 4x4 matrix product "
            "X := M * X (the paper's per-item load) and relaxes its own state "
            "towards tanh of the result; components without an own state ("
            + ", ".join(stateless) + ") yield tanh of the result. All values "
            "stay in [-1, 1].", width=77),
        textwrap.fill(interp_line, width=77),
    ])

    sim = Simulation(name, range_=range_, dt=dt, max_steps=max_steps,
                     header=full_header)
    sim.param("L", rounds, "i32",
              doc="Rounds of the 4x4 matrix product per item and evaluation "
                  "(the load).")
    sim.param("dist", dist, "i32",
              doc="Step counts: 0 per component, 1 per group of @group "
                  "items, 2 per item, 3 all 1, 4 all max_steps.")
    sim.param("group", group, "i32", doc="Items per group when @dist = 1.")

    for seed, s in enumerate(specs):
        init = Body.for_init()
        init.yield_([emit_init_value(init, seed)], [VEC4F])
        kind = interp.get(s.writes, "linear")
        who = ", ".join(readers[s.writes]) or "nobody"
        sim.buffer(s.writes, VEC4F, init, interp=f"#sim.{kind}",
                   doc=f"Written by {s.name}; read by {who}.")

    for index, s in enumerate(specs):
        num_steps = Body.for_num_steps()
        num_steps.yield_([emit_step_count(num_steps, index)], ["i32"])
        doc = f"{s.name}: {s.role}" if s.role else s.name
        doc += f"\nReads {_read_list(s, back_edges)}."
        reads = [(s.writes, "i")] if s.own else []
        reads += [(b, WINDOW) for b in s.windows] + [(b, "i") for b in s.points]
        sim.component(s.name, [s.writes],
                      _evaluate_body(s, back_edges, sim.dt_type),
                      num_steps=num_steps, doc=doc, reads=reads)

    sim.schedule = [specs[0].name]
    sim.observe = list(observe)
    return sim


def _interp_map(specs: list[ComponentSpec], default: Mapping[str, str],
                interp: str | Mapping[str, str] | None) -> dict[str, str]:
    if interp is None:
        return dict(default)
    if isinstance(interp, str):
        return {s.writes: interp for s in specs}
    return dict(interp)


GRAVITY_SPECS = [
    ComponentSpec("C0", "B0", points=("B2",), own=True,
                  role="per-particle information (reads the result of the "
                       "previous step)."),
    ComponentSpec("C1", "B1", windows=("B0",),
                  role="accumulates neighbourhood information for C2."),
    ComponentSpec("C2", "B2", windows=("B0", "B1"), own=True,
                  role="item updates from the neighbourhoods of B0 and B1."),
]

GRAVITY_HEADER = """\
gravity_like: the gravity-like scene of the paper's Section 5.1 (Fig. 9).
C0 computes particle-specific information from its own state and the result
of the previous step (B2 through the back edge), C1 iterates over the 9
neighbouring items of B0 and prepares accumulated results for C2, and C2
reads the neighbourhoods of B0 and B1 and updates the items. B2 is observed."""


def gravity_like(*, range_: int = 65536, dt: float = 1.0e-3,
                 max_steps: int = 3, rounds: int = 8, dist: int = 0,
                 group: int = 32,
                 interp: str | Mapping[str, str] | None = None) -> Simulation:
    """The gravity-like scene (Section 5.1, Fig. 9): 3 components.

    `interp` is one interpolation (`"linear"`, `"cubic"`) for every buffer
    or a map from buffer to interpolation; the default is linear everywhere.
    """
    return build_scene("gravity_like", GRAVITY_HEADER, GRAVITY_SPECS, ["B2"],
                       _interp_map(GRAVITY_SPECS, {}, interp),
                       range_=range_, dt=dt, max_steps=max_steps,
                       rounds=rounds, dist=dist, group=group)


PBD_SPECS = [
    ComponentSpec("C0", "B0", points=("B6",), own=True,
                  role="basic per-particle information (a position "
                       "prediction)."),
    ComponentSpec("C1", "B1", windows=("B0",),
                  role="accumulated neighbourhood information for C2."),
    ComponentSpec("C2", "B2", windows=("B1",), points=("B0",),
                  role="an imaginary collision-detection step."),
    ComponentSpec("C3", "B3", windows=("B2",),
                  role="an SPH-like sum over the neighbours."),
    ComponentSpec("C4", "B4", windows=("B3",),
                  role="a second SPH-like sum over the neighbours."),
    ComponentSpec("C5", "B5", windows=("B4", "B3"),
                  role="iterates over the neighbours in B4 and B3."),
    ComponentSpec("C6", "B6", windows=("B5",), own=True,
                  role="the final item updates from B5."),
]

# B3 and B4 (the outputs of the SPH-like components, read in windows by C4
# and C5) use the paper's cubic interpolation, so the scene exercises both.
PBD_INTERP = {"B3": "cubic", "B4": "cubic"}

PBD_HEADER = """\
pbd_like: the PBD-like scene of the paper's Section 5.2 (Fig. 10).
C0 computes basic information per particle (a position prediction) from its
own state and the result of the previous step (B6 through the back edge). C1
prepares accumulated neighbourhood information for an imaginary collision
detection in C2. C3 and C4 are SPH-like sums over the neighbours, C5 iterates
over the neighbours in B4 and B3, and C6 computes the final item updates
from B5. B6 is observed."""

PBD_INTERP_NOTE = """\
B3 and B4 (the outputs of the SPH-like components, read in windows by C4 and
C5) use the paper's cubic interpolation and the other buffers linear
interpolation, so the scene exercises both."""


def pbd_like(*, range_: int = 65536, dt: float = 1.0e-3, max_steps: int = 3,
             rounds: int = 8, dist: int = 0, group: int = 32,
             interp: str | Mapping[str, str] | None = None) -> Simulation:
    """The PBD-like scene (Section 5.2, Fig. 10): 7 components.

    By default B3 and B4 use `#sim.cubic` and the other buffers
    `#sim.linear`; `interp` overrides that as in `gravity_like`.
    """
    header = PBD_HEADER if interp else PBD_HEADER + "\n" + PBD_INTERP_NOTE
    return build_scene("pbd_like", header, PBD_SPECS, ["B6"],
                       _interp_map(PBD_SPECS, PBD_INTERP, interp),
                       range_=range_, dt=dt, max_steps=max_steps,
                       rounds=rounds, dist=dist, group=group)
