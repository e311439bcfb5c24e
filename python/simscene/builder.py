"""A small builder that emits `sim` dialect text.

The builder knows only the structure of a scene: a `Simulation` holds
`Param`s, `Buffer`s and `Component`s plus the schedule prefix and the observed
buffers; each buffer and component body is a `Body`, a single block of
upstream ops (arith, math, vector, scf and the sim body ops) written as text.

`Body` takes care of the chores that make hand-written MLIR error prone:

* SSA names: every value gets a readable, unique name derived from a hint
  (`%mean_B0`, `%mean_B0_1`, ...). One `Body` is one isolated region, so names
  never clash with an enclosing scope.
* Constants: `Body.const` deduplicates constants and emits them at the top of
  the block, where they dominate every use, including uses in nested `scf.for`
  bodies.
* Nested loops: `Body.scf_for` emits an `scf.for` with iter_args and returns
  the names of its results.

Nothing here knows about the paper's scenes; the emitters for the hash, the
neighbour gather and the matrix load are in `simscene.emitters`, the scenes in
`simscene.scenes`. The text is meant to parse with `sim-opt`; the builder does
not verify it (sim-opt does).

Example::

    sim = Simulation("decay", range_=1024, dt=1.0e-2, max_steps=4)
    sim.param("k", 2.5, "f32")
    init = Body.for_init()
    init.yield_([init.const("1.0", "f32")], ["f32"])
    sim.buffer("X", "f32", init)
    ...
    text = sim.render()
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Callable, Sequence

__all__ = [
    "Body",
    "Buffer",
    "Component",
    "Namer",
    "Param",
    "Simulation",
    "format_float",
    "format_sci",
    "signed64",
]

INDENT = "  "


def signed64(value: int) -> int:
    """Returns `value` (taken modulo 2**64) as a signed 64-bit integer."""
    value &= (1 << 64) - 1
    return value - (1 << 64) if value >= 1 << 63 else value


def format_float(value: float) -> str:
    """Formats a float as an MLIR float literal (always with a '.')."""
    text = repr(float(value))
    if "e" in text and "." not in text.split("e")[0]:
        mantissa, exponent = text.split("e")
        text = f"{mantissa}.0e{exponent}"
    elif "e" not in text and "." not in text:
        text += ".0"
    return text


def format_sci(value: float) -> str:
    """The shortest exact scientific MLIR literal of `value` (`1.0e-3`)."""
    for digits in range(17):
        text = f"{float(value):.{digits}e}"
        if float(text) == float(value):
            break
    mantissa, exponent = text.split("e")
    if "." not in mantissa:
        mantissa += ".0"
    return f"{mantissa}e{int(exponent)}"


class Namer:
    """Hands out unique SSA names (without the '%') from readable hints."""

    _INVALID = re.compile(r"[^A-Za-z0-9_$.\-]")

    def __init__(self) -> None:
        self._used: set[str] = set()

    def reserve(self, name: str) -> str:
        if name in self._used:
            raise ValueError(f"SSA name %{name} is already taken")
        self._used.add(name)
        return name

    def fresh(self, hint: str) -> str:
        """Returns `hint` made unique (`hint`, `hint_1`, `hint_2`, ...)."""
        base = self._INVALID.sub("_", hint) or "v"
        if not (base[0].isalpha() or base[0] in "_$."):
            base = "v" + base
        name, suffix = base, 1
        while name in self._used:
            name = f"{base}_{suffix}"
            suffix += 1
        self._used.add(name)
        return name


class Body:
    """One block of a buffer or component body, built op by op.

    Values are passed around as their SSA spelling (`"%i"`, `"%x#0"`). Ops are
    added with `op` (one result) or `stmt` (no result); `const` adds a
    constant at the top of the block; `yield_` sets the `sim.yield`.
    """

    def __init__(self, args: Sequence[tuple[str, str]]) -> None:
        self.namer = Namer()
        self.args = [(self.namer.reserve(name), type_) for name, type_ in args]
        self._consts: list[str] = []
        self._const_names: dict[tuple[str, str], str] = {}
        self._lines: list[str] = []
        self._depth = 0
        self._terminator: str | None = None

    # Bodies with the signatures the verifier expects.
    @classmethod
    def for_init(cls) -> "Body":
        """An `init` body: `(%i: index)`."""
        return cls([("i", "index")])

    @classmethod
    def for_num_steps(cls) -> "Body":
        """A `num_steps` body: `(%i: index, %t: i64)`, yields an `i32`."""
        return cls([("i", "index"), ("t", "i64")])

    @classmethod
    def for_evaluate(cls, dt_type: str = "f32") -> "Body":
        """An `evaluate` body: `(%i: index, %t: i64, %n: i32, %dt: <dt>)`."""
        return cls([("i", "index"), ("t", "i64"), ("n", "i32"),
                    ("dt", dt_type)])

    def arg(self, name: str) -> str:
        """The SSA spelling of the block argument `name`."""
        if not any(arg == name for arg, _ in self.args):
            raise KeyError(f"the body has no argument %{name}")
        return "%" + name

    # Emission.
    def comment(self, text: str) -> None:
        """Adds `// text` lines (one per line of `text`) at the current depth."""
        for line in text.splitlines() or [""]:
            self._lines.append(INDENT * self._depth + ("// " + line).rstrip())

    def blank(self) -> None:
        if self._lines and self._lines[-1]:
            self._lines.append("")

    def op(self, hint: str, rhs: str, comment: str | None = None) -> str:
        """Adds `%<name> = <rhs>` and returns `%<name>`."""
        name = "%" + self.namer.fresh(hint)
        line = f"{name} = {rhs}"
        if comment:
            line += f" // {comment}"
        self._lines.append(INDENT * self._depth + line)
        return name

    def stmt(self, text: str) -> None:
        """Adds an op without results."""
        self._lines.append(INDENT * self._depth + text)

    def const(self, value: str | int | float, type_: str,
              hint: str | None = None, comment: str | None = None) -> str:
        """A constant, emitted once at the top of the block.

        `value` is the attribute text for vector types (e.g. `dense<1.0>`) and
        a number (or its text) for scalars.
        """
        if isinstance(value, float):
            text = format_float(value)
        else:
            text = str(value)
        key = (text, type_)
        if key in self._const_names:
            return self._const_names[key]
        if hint is None:
            if type_ == "index":
                hint = f"c{text}"
            elif type_.startswith(("i", "vector<")) and re.fullmatch(
                    r"-?\d+", text):
                hint = f"c{text}_{type_}"
            else:
                hint = "cst"
        name = "%" + self.namer.fresh(hint)
        line = f"{name} = arith.constant {text} : {type_}"
        if comment:
            line += f" // {comment}"
        self._consts.append(line)
        self._const_names[key] = name
        return name

    def scf_for(self, lower: str, upper: str, step: str,
                inits: Sequence[tuple[str, str]], result_types: Sequence[str],
                build: Callable[[str, list[str]], list[str]], *,
                iv_hint: str = "k", result_hint: str = "loop") -> list[str]:
        """Emits an `scf.for` and returns its results.

        `inits` pairs a name hint for each iter_arg with its initial value;
        `build(iv, iter_args)` emits the loop body (through this `Body`) and
        returns the values to `scf.yield`.
        """
        if len(inits) != len(result_types):
            raise ValueError("one result type per iter_arg")
        iv = "%" + self.namer.fresh(iv_hint)
        iter_args = ["%" + self.namer.fresh(h) for h, _ in inits]
        results_name = self.namer.fresh(result_hint)
        count = len(inits)
        if count == 0:
            head = ""
            results: list[str] = []
        elif count == 1:
            head = f"%{results_name} = "
            results = [f"%{results_name}"]
        else:
            head = f"%{results_name}:{count} = "
            results = [f"%{results_name}#{k}" for k in range(count)]
        line = f"{head}scf.for {iv} = {lower} to {upper} step {step}"
        if count:
            bindings = ", ".join(f"{arg} = {init}"
                                 for arg, (_, init) in zip(iter_args, inits))
            line += f" iter_args({bindings}) -> ({', '.join(result_types)})"
        self._lines.append(INDENT * self._depth + line + " {")
        self._depth += 1
        yielded = build(iv, iter_args)
        if len(yielded) != count:
            raise ValueError("the loop body must yield one value per iter_arg")
        if count:
            self.stmt(f"scf.yield {', '.join(yielded)} : "
                      f"{', '.join(result_types)}")
        self._depth -= 1
        self._lines.append(INDENT * self._depth + "}")
        return results

    def yield_(self, values: Sequence[str], types: Sequence[str]) -> None:
        """Sets the block's terminator, `sim.yield values : types`."""
        if self._depth:
            raise RuntimeError("sim.yield inside a nested region")
        self._terminator = (f"sim.yield {', '.join(values)} : "
                            f"{', '.join(types)}")

    def render(self, indent: str) -> list[str]:
        """The block as lines (header, constants, ops, terminator)."""
        if self._terminator is None:
            raise RuntimeError("the body has no sim.yield")
        args = ", ".join(f"%{name}: {type_}" for name, type_ in self.args)
        lines = [f"{indent}^bb0({args}):"]
        inner = indent + INDENT
        lines += [inner + line for line in self._consts]
        if self._consts and self._lines and self._lines[0]:
            lines.append("")
        lines += [(inner + line) if line else "" for line in self._lines]
        lines.append(inner + self._terminator)
        return lines


def _doc_lines(doc: str | None, indent: str) -> list[str]:
    if not doc:
        return []
    return [(indent + "// " + line).rstrip() for line in doc.splitlines()]


@dataclass
class Param:
    """`sim.param @name = value : type` (an integer or float scalar)."""

    name: str
    value: int | float
    type: str
    doc: str | None = None

    def render(self, indent: str) -> list[str]:
        value = (format_float(self.value) if isinstance(self.value, float)
                 else str(self.value))
        return _doc_lines(self.doc, indent) + [
            f"{indent}sim.param @{self.name} = {value} : {self.type}"]


@dataclass
class Buffer:
    """`sim.buffer @name : type interp(...) boundary(...) init {...}`."""

    name: str
    element_type: str
    init: Body
    interp: str | None = "#sim.linear"
    boundary: str | None = None  # clamp (the default), wrap or zero
    doc: str | None = None

    def render(self, indent: str) -> list[str]:
        head = f"{indent}sim.buffer @{self.name} : {self.element_type}"
        if self.interp:
            head += f" interp({self.interp})"
        if self.boundary and self.boundary != "clamp":
            head += f" boundary({self.boundary})"
        return (_doc_lines(self.doc, indent) + [head + " init {"] +
                self.init.render(indent) + [indent + "}"])


@dataclass
class Component:
    """`sim.component @name writes(...) num_steps {...} evaluate {...}`."""

    name: str
    writes: list[str]
    evaluate: Body
    num_steps: Body | None = None
    doc: str | None = None
    # Filled in by the scene code for the header comments and the order check:
    # (buffer, how) pairs such as ("B0", "i-4..i+4").
    reads: list[tuple[str, str]] = field(default_factory=list)

    def render(self, indent: str) -> list[str]:
        writes = ", ".join("@" + w for w in self.writes)
        lines = _doc_lines(self.doc, indent)
        head = f"{indent}sim.component @{self.name} writes({writes})"
        if self.num_steps is not None:
            lines.append(head + " num_steps {")
            lines += self.num_steps.render(indent)
            lines.append(indent + "} evaluate {")
        else:
            lines.append(head + " evaluate {")
        lines += self.evaluate.render(indent)
        lines.append(indent + "}")
        return lines


@dataclass
class Simulation:
    """A whole `sim.simulation`, rendered with `render()`."""

    name: str
    range_: int
    dt: float
    max_steps: int
    dt_type: str = "f32"
    header: str | None = None  # comment lines above the simulation
    params: list[Param] = field(default_factory=list)
    buffers: list[Buffer] = field(default_factory=list)
    components: list[Component] = field(default_factory=list)
    schedule: list[str] = field(default_factory=list)
    observe: list[str] = field(default_factory=list)

    def param(self, name: str, value: int | float, type_: str,
              doc: str | None = None) -> Param:
        p = Param(name, value, type_, doc)
        self.params.append(p)
        return p

    def buffer(self, name: str, element_type: str, init: Body,
               interp: str | None = "#sim.linear", boundary: str | None = None,
               doc: str | None = None) -> Buffer:
        b = Buffer(name, element_type, init, interp, boundary, doc)
        self.buffers.append(b)
        return b

    def component(self, name: str, writes: list[str], evaluate: Body,
                  num_steps: Body | None = None, doc: str | None = None,
                  reads: list[tuple[str, str]] | None = None) -> Component:
        c = Component(name, writes, evaluate, num_steps, doc, reads or [])
        self.components.append(c)
        return c

    def render(self) -> str:
        lines = _doc_lines(self.header, "")
        if lines:
            lines.append("")
        dt = format_sci(self.dt)
        lines.append(f"sim.simulation @{self.name} range({self.range_}) "
                     f"dt({dt} : {self.dt_type}) max_steps({self.max_steps}) {{")
        inner = INDENT
        for p in self.params:
            lines += p.render(inner)
        for group in (self.buffers, self.components):
            for item in group:
                lines.append("")
                lines += item.render(inner)
        lines.append("")
        if self.schedule:
            lines.append(inner + "sim.schedule [" +
                         ", ".join("@" + c for c in self.schedule) + "]")
        if self.observe:
            lines.append(inner + "sim.observe [" +
                         ", ".join("@" + b for b in self.observe) + "]")
        lines.append("}")
        return "\n".join(lines) + "\n"
