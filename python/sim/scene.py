"""Scenes written in Python: parameters, buffers, components, totals.

    rod = sim.Scene("rod", range=1024, dt=1e-3, max_steps=4)
    k = rod.param("k", 2.0)                     # sim.param @k = 2.0 : f32

    @rod.buffer(sim.f32, boundary="clamp")      # sim.buffer @T ... init
    def T(i):
        return sim.f32(i) * 1e-3

    @rod.component(writes=T)                    # sim.component @Relax ...
    def Relax(i, n, dt):
        mean = (T[i - 1] + T[i] + T[i + 1]) * (1 / 3)
        return T[i] + k * (sim.f32(n) * dt) * (mean - T[i])

    rod.observe(T)
    print(rod.mlir())

Bodies are traced lazily, when the scene's text is made (`mlir()`,
`compile()`), so a body may read buffers declared after it. A body's
parameters are matched by name (`i`, `t`, `n`, `dt`) when they all are
among those (any of them, in any order: `def Relax(i, dt)`), else passed by
position in the order (i, t, n, dt) (`def Relax(k, time, steps, h)`), where
a parameter named like an argument must stand in its place: `def Relax(j,
n, dt)` would give `n` the time t, and is a TraceError at its `def` line;
see sim.trace.call_body.
"""

from __future__ import annotations

import math
import numbers
import re
import sys
from typing import Callable, Sequence

from . import ops, trace
from .trace import Body, LocationTable, Value, entered, trace_error, user_location
from .types import (F32_MAX, F32_TINY, DType, f32, f64, float_literal, i32,
                    i64, index, int_literal, round_f32)

__all__ = ["Scene", "Param", "Buffer", "Component", "Total", "hermite",
           "Hermite"]

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_$.]*$")
_INTERPS = ("linear", "cubic", "none", "flux")
_BOUNDARIES = ("clamp", "wrap", "zero")
_BUILTIN_PARAMS = ("range", "dt", "max_steps")
# sim.simulation's kMaxRange and kMaxMaxSteps (include/sim/Dialect/Sim/IR/
# SimOps.td).
_MAX_RANGE = 1 << 40
_MAX_MAX_STEPS = 1 << 20


class Hermite:
    """Cubic Hermite interpolation with a derivative buffer (order 4)."""

    def __init__(self, derivative):
        self.derivative = derivative

    def __repr__(self):
        return f"sim.hermite({_name_of(self.derivative)})"


def hermite(derivative) -> Hermite:
    """`interp=sim.hermite(V)`: `#sim.hermite<@V>`, V the derivative buffer
    (a Buffer or its name)."""
    return Hermite(derivative)


def _name_of(x) -> str:
    return x if isinstance(x, str) else getattr(x, "name", repr(x))


class Param(ops.Traceable):
    """A scene parameter (`sim.param`, or `range`, `dt`, `max_steps`):
    used in a body, it reads its current value (`sim.get_param`)."""

    def __init__(self, scene: "Scene", name: str, dtype: DType, default,
                 loc):
        self.scene = scene
        self.name = name
        self.dtype = dtype
        self.default = default
        self.loc = loc

    def _sim_value(self) -> Value:
        loc = user_location(3)
        body = trace.current_body(f"reading the parameter @{self.name}")
        if body.scene is not self.scene._tracer:
            raise trace_error(f"the parameter @{self.name} of scene "
                              f"@{self.scene.name} read in another scene",
                              loc)
        return trace.get_param(self.name, self.dtype, loc)

    def __repr__(self):
        return f"<sim.Param @{self.name} : {self.dtype}>"


class _Params:
    """`scene.params.<name>`: the scene's parameters and its `range`
    (i64), `dt` (its precision) and `max_steps` (i32)."""

    def __init__(self, scene: "Scene"):
        object.__setattr__(self, "_scene", scene)

    def __getattr__(self, name: str) -> Param:
        scene = object.__getattribute__(self, "_scene")
        try:
            return scene._params[name]
        except KeyError:
            raise AttributeError(f"scene @{scene.name} has no parameter "
                                 f"{name!r}") from None

    def __getitem__(self, name: str) -> Param:
        return getattr(self, name)

    def __iter__(self):
        return iter(object.__getattribute__(self, "_scene")._params.values())

    def __setattr__(self, name, value):
        raise AttributeError("declare parameters with scene.param(name, "
                             "default)")


class Buffer:
    """A double-buffered state buffer: `B[j]` in a body reads item `j`
    (`sim.read @B[%j]`)."""

    def __init__(self, scene: "Scene", name: str, dtype: DType, init: Callable,
                 interp, boundary: str, loc, constant: bool = False):
        self.scene = scene
        self.constant = constant
        self.name = name
        self.dtype = dtype
        self.init = init
        self.interp = interp
        self.boundary = boundary
        self.exact_fn: Callable | None = None
        self.loc = loc

    def __getitem__(self, item) -> Value:
        loc = user_location(2)
        body = trace.current_body(f"reading @{self.name}")
        if body.scene is not self.scene._tracer:
            raise trace_error(f"@{self.name} of scene @{self.scene.name} "
                              "read in another scene", loc)
        return ops.read(self.name, self.dtype, item, loc)

    def __setitem__(self, item, value):
        raise trace_error(f"assigning to @{self.name}[...]: a component "
                          f"changes its buffers by returning their new "
                          f"values from evaluate")

    def exact(self, fn: Callable) -> "Buffer":
        """Decorator: the exact solution `fn(i, t)` (t: f64 time), which
        runs compare against (`sim-run --reference exact`, errors=True)."""
        if self.constant:
            raise trace_error(f"@{self.name} is constant, so it takes no "
                              "exact solution: its init is its value at "
                              "every time", user_location(2))
        self.exact_fn = fn
        return self

    def __repr__(self):
        return f"<sim.Buffer @{self.name} : {self.dtype.mlir}>"


class Component:
    """A component: `evaluate(i, t, n, dt)` returns the new value of each
    buffer it writes; `num_steps(i, t)` (optional) how many base steps item
    i could take."""

    def __init__(self, scene: "Scene", name: str, writes: list[Buffer],
                 evaluate: Callable, num_steps: Callable | None, loc):
        self.scene = scene
        self.name = name
        self.writes = writes
        self.evaluate = evaluate
        self.num_steps_fn = num_steps
        self.loc = loc

    def num_steps(self, fn: Callable) -> "Component":
        """Decorator: the component's `num_steps(i, t)` body (an i32)."""
        self.num_steps_fn = fn
        return self

    def __repr__(self):
        return f"<sim.Component @{self.name}>"


class Total:
    """A total: the sum over items of what its body returns for item i."""

    def __init__(self, scene, name: str, dtype: DType, fn: Callable, loc):
        self.scene = scene
        self.name = name
        self.dtype = dtype
        self.fn = fn
        self.loc = loc

    def __repr__(self):
        return f"<sim.Total @{self.name} : {self.dtype}>"


class _Tracer:
    """What the bodies of one rendering of a scene share."""

    def __init__(self):
        self.locations = LocationTable()


class Scene:
    """A `sim.simulation`: `range` items advanced in base steps of `dt`.

    `precision` (f32 or f64) is the type of `dt` and of Python float
    constants in bodies without a typed operand; `dt` must be positive and
    finite in it, and not subnormal (1e-50 underflows f32, 1e-40 is
    subnormal in it: a TraceError here, not a tool's error about the
    rounded value). Components, buffers and totals are declared
    with the decorators `buffer`, `component` and `total`; `observe` names
    the outputs.
    """

    def __init__(self, name: str, *, range: int, dt: float, max_steps: int = 1,
                 precision: DType = f32):
        loc = user_location(2)
        _check_name(name, "scene", loc)
        if precision not in (f32, f64):
            raise trace_error(f"a scene's precision is sim.f32 or sim.f64, "
                              f"not {precision!r}", loc)
        # The dialect's bounds, checked here at the user's line: the tools
        # would report them at the text's, and read True as no number.
        range = _check_int("range", range, _MAX_RANGE, "2^40", loc)
        max_steps = _check_int("max_steps", max_steps, _MAX_MAX_STEPS,
                               "2^20", loc)
        self.name = name
        self.range = range
        self.dt = _check_dt(dt, precision, loc)
        self.max_steps = max_steps
        self.precision = precision
        self.loc = loc
        self._params: dict[str, Param] = {}
        self._decls: list = []
        self._names: dict[str, object] = {}
        self._schedule: list | None = None
        self._schedule_loc = None
        self._observe: list | None = None
        self._observe_loc = None
        self._tracer: _Tracer | None = None
        self.params = _Params(self)
        for pname, dtype in (("range", i64), ("dt", precision),
                             ("max_steps", i32)):
            self._params[pname] = Param(self, pname, dtype, None, loc)

    # -- Declarations ----------------------------------------------------------

    def _declare(self, name: str, what: str, decl, loc):
        _check_name(name, what, loc)
        if name in self._names or name in _BUILTIN_PARAMS:
            raise trace_error(f"the name @{name} is declared twice in scene "
                              f"@{self.name}", loc)
        self._names[name] = decl
        self._decls.append(decl)

    def param(self, name: str, default, dtype: DType | None = None) -> Param:
        """Declares `sim.param @name = default : dtype` (i32, i64, index,
        f32 or f64, the types a bundle holds; default: i32 for an int, the
        precision for a float); returns the handle that reads it in
        bodies. `default` is a number (Python's or numpy's) that fits the
        type: an integer type takes an integer (or a float that is one,
        2.0), never a fraction. Runs change it with
        `session.set(name=value)`."""
        loc = user_location(2)
        # numpy's numbers too (np.int64(3) is an int).
        if isinstance(default, bool) or not isinstance(default, numbers.Real):
            raise trace_error(f"the default of @{name} must be an int or "
                              f"a float, not {type(default).__name__}", loc)
        if dtype is None:
            dtype = i32 if _is_int(default) else self.precision
        # The dialect's signless types do not say u32 from i32: a bundle
        # would hold an unsigned parameter as a signed one.
        if not isinstance(dtype, DType) or \
                dtype not in (i32, i64, index, f32, f64):
            raise trace_error(f"unsupported parameter type {dtype!r}: "
                              "i32, i64, index, f32 or f64", loc)
        try:
            if dtype.is_float:
                literal = float_literal(float(default), dtype)
            else:
                if not _is_int(default):
                    if not float(default).is_integer():
                        hint = (" (for a fraction declare it sim.f32 or "
                                "sim.f64)"
                                if math.isfinite(float(default)) else "")
                        raise ValueError(f"not an integer, as an {dtype} "
                                         f"parameter needs{hint}")
                    default = int(default)
                literal = int_literal(int(default), dtype,
                                      unsigned_hint=False)
        except (TypeError, ValueError, OverflowError) as error:
            raise trace_error(f"the default {default!r} of @{name}: {error}",
                              loc) from None
        param = Param(self, name, dtype, default, loc)
        param.literal = literal
        self._declare(name, "parameter", param, loc)
        self._params[name] = param
        return param

    def buffer(self, dtype: DType | Callable | None = None, *,
               interp=None, boundary: str = "clamp", constant: bool = False,
               name: str | None = None):
        """Decorator: a buffer whose `init(i)` body is the function; the
        buffer takes the function's name. `dtype`: f32, f64 or a vector of
        them (default: the scene's precision). `interp`: "linear" (the
        default), "cubic", "none", "flux" (a flux through interfaces,
        constant over its writer's step; docs/Model.md, "Conservation") or
        sim.hermite(V). `boundary`: "clamp", "wrap" or "zero".
        `constant=True`: no component writes it, and `init(i)` is its value
        at every time (a material field, a mass); the compiler computes it
        where it is read, so it takes no `interp` and no exact solution, and
        cannot be observed."""
        loc = user_location(2)
        if constant and interp is not None:
            raise trace_error("a constant buffer takes no interpolation: its "
                              "value is its init at every time", loc)
        if interp is None:
            interp = "linear"
        fn = None
        # A Python type (`int`, `float`, numpy's) is callable too, but it is
        # a mistaken element type, not the init body.
        if callable(dtype) and not isinstance(dtype, (DType, type)):
            fn, dtype = dtype, None
        dtype = self.precision if dtype is None else dtype
        if not isinstance(dtype, DType) or not dtype.is_float:
            raise trace_error(f"unsupported buffer type {dtype!r}: a buffer "
                              "holds f32, f64 or a vector of them", loc)
        if not (isinstance(interp, Hermite) or interp in _INTERPS):
            raise trace_error(f"unknown interpolation {interp!r}: linear, "
                              "cubic, none or sim.hermite(V)", loc)
        if boundary not in _BOUNDARIES:
            raise trace_error(f"unknown boundary {boundary!r}: clamp, wrap "
                              "or zero", loc)

        def declare(init: Callable) -> Buffer:
            buffer = Buffer(self, name or init.__name__, dtype, init, interp,
                            boundary, loc, constant=bool(constant))
            self._declare(buffer.name, "buffer", buffer, loc)
            return buffer

        return declare(fn) if fn is not None else declare

    def component(self, writes, *, name: str | None = None,
                  num_steps: Callable | None = None):
        """Decorator: a component whose `evaluate(i, t, n, dt)` body is the
        function (it returns the new value of each buffer in `writes`, in
        that order); `num_steps` or the decorator `@C.num_steps` adds its
        `num_steps(i, t)` body."""
        loc = user_location(2)
        buffers = list(writes) if isinstance(writes, (list, tuple)) else [writes]
        for b in buffers:
            if not isinstance(b, Buffer) or b.scene is not self:
                raise trace_error(f"a component writes buffers of this scene, "
                                  f"not {b!r}", loc)
        if not buffers:
            raise trace_error("a component writes at least one buffer", loc)
        for b in buffers:
            if b.constant:
                raise trace_error(f"@{b.name} is constant, so no component "
                                  "writes it; drop constant=True from it or "
                                  "it from writes", loc)

        def declare(evaluate: Callable) -> Component:
            component = Component(self, name or evaluate.__name__, buffers,
                                  evaluate, num_steps, loc)
            self._declare(component.name, "component", component, loc)
            return component

        return declare

    def total(self, dtype: DType | Callable = f64, *, name: str | None = None):
        """Decorator: a total (`sim.total`), the sum over all items of what
        the function returns for item i (f32 or f64), with reads at the
        current time."""
        loc = user_location(2)
        fn = None
        if callable(dtype) and not isinstance(dtype, DType):
            fn, dtype = dtype, f64
        if dtype not in (f32, f64):
            raise trace_error(f"unsupported total type {dtype!r}: f32 or f64",
                              loc)

        def declare(body: Callable) -> Total:
            total = Total(self, name or body.__name__, dtype, body, loc)
            self._declare(total.name, "total", total, loc)
            return total

        return declare(fn) if fn is not None else declare

    def schedule(self, *components):
        """`sim.schedule [...]`: the component that starts a step (and
        optionally more of the order)."""
        self._schedule = [self._lookup(c, Component, "schedule")
                          for c in components]
        self._schedule_loc = user_location(2)

    def observe(self, *buffers):
        """`sim.observe [...]`: the buffers the scene is for."""
        self._observe = [self._lookup(b, Buffer, "observe")
                         for b in buffers]
        for name in self._observe:
            if self._names[name].constant:
                raise trace_error(f"observe: @{name} is constant (no run "
                                  "changes it, and no backend stores it); "
                                  "observe the buffers components write, "
                                  "or a total", user_location(2))
        self._observe_loc = user_location(2)

    def _lookup(self, x, cls, what):
        name = _name_of(x)
        found = self._names.get(name)
        if not isinstance(found, cls):
            raise trace_error(f"{what}: @{name} is not a "
                              f"{cls.__name__.lower()} of scene @{self.name}",
                              user_location(3))
        return name

    @property
    def buffers(self) -> list[Buffer]:
        return [d for d in self._decls if isinstance(d, Buffer)]

    @property
    def components(self) -> list[Component]:
        return [d for d in self._decls if isinstance(d, Component)]

    @property
    def totals(self) -> list[Total]:
        return [d for d in self._decls if isinstance(d, Total)]

    # -- Text --------------------------------------------------------------------

    def mlir(self) -> str:
        """The scene as `sim` dialect text, every operation located at the
        Python line that made it. Traces every body."""
        tracer = _Tracer()
        self._tracer = tracer
        ref = tracer.locations.ref
        try:
            lines = [f"sim.simulation @{self.name} range({self.range}) "
                     f"dt({float_literal(self.dt, self.precision)} : "
                     f"{self.precision.mlir}) max_steps({self.max_steps}) {{"]
            for decl in self._decls:
                if isinstance(decl, Param):
                    lines.append(f"  sim.param @{decl.name} = {decl.literal} : "
                                 f"{decl.dtype.mlir}{ref(decl.loc)}")
                elif isinstance(decl, Buffer):
                    lines += self._render_buffer(decl)
                elif isinstance(decl, Component):
                    lines += self._render_component(decl)
                else:
                    lines += self._render_total(decl)
            if self._schedule:
                lines.append("  sim.schedule [" + ", ".join(
                    f"@{c}" for c in self._schedule) + "]" +
                    ref(self._schedule_loc))
            if self._observe:
                lines.append("  sim.observe [" + ", ".join(
                    f"@{b}" for b in self._observe) + "]" +
                    ref(self._observe_loc))
            lines.append("}" + ref(self.loc))
        finally:
            self._tracer = None
        header = (f"// Scene @{self.name}, traced from Python by the sim "
                  "package (python/sim).\n")
        return header + tracer.locations.render() + "\n" + "\n".join(lines) + "\n"

    def _render_buffer(self, b: Buffer) -> list[str]:
        ref = self._tracer.locations.ref
        if isinstance(b.interp, Hermite):
            derivative = self._names.get(_name_of(b.interp.derivative))
            if not isinstance(derivative, Buffer):
                raise trace_error(f"the derivative buffer "
                                  f"@{_name_of(b.interp.derivative)} of "
                                  f"@{b.name}'s Hermite interpolation is not "
                                  f"a buffer of scene @{self.name}", b.loc)
            interp = f"interp(#sim.hermite<@{derivative.name}>)"
        elif b.interp == "none":
            interp = "interp(none)"
        else:
            interp = f"interp(#sim.{b.interp})"
        if b.constant:
            interp = "constant"
        head = (f"  sim.buffer @{b.name} : {b.dtype.mlir} {interp} "
                f"boundary({b.boundary}) init {{")
        lines = [head]
        lines += self._trace("init", f"@{b.name}", b.init, [("i", index)],
                             [(b.dtype, f"@{b.name}")])
        if b.exact_fn is not None:
            lines.append("  } exact {")
            lines += self._trace("exact", f"@{b.name}", b.exact_fn,
                                 [("i", index), ("t", f64)],
                                 [(b.dtype, f"@{b.name}")])
        lines.append("  }" + ref(b.loc))
        return lines

    def _render_component(self, c: Component) -> list[str]:
        ref = self._tracer.locations.ref
        writes = ", ".join(f"@{b.name}" for b in c.writes)
        lines = [f"  sim.component @{c.name} writes({writes})"]
        if c.num_steps_fn is not None:
            lines[0] += " num_steps {"
            lines += self._trace("num_steps", f"@{c.name}", c.num_steps_fn,
                                 [("i", index), ("t", i64)],
                                 [(i32, "the step count")])
            lines.append("  } evaluate {")
        else:
            lines[0] += " evaluate {"
        lines += self._trace("evaluate", f"@{c.name}", c.evaluate,
                             [("i", index), ("t", i64), ("n", i32),
                              ("dt", self.precision)],
                             [(b.dtype, f"@{b.name}") for b in c.writes])
        lines.append("  }" + ref(c.loc))
        return lines

    def _render_total(self, t: Total) -> list[str]:
        ref = self._tracer.locations.ref
        lines = [f"  sim.total @{t.name} : {t.dtype.mlir} {{"]
        lines += self._trace("total", f"@{t.name}", t.fn, [("i", index)],
                             [(t.dtype, f"@{t.name}")])
        lines.append("  }" + ref(t.loc))
        return lines

    def _trace(self, kind: str, owner: str, fn: Callable,
               args: Sequence[tuple[str, DType]],
               results: Sequence[tuple[DType, str]]) -> list[str]:
        body = Body(self._tracer, kind, owner, self.precision)
        for name, dtype in args:
            body.args[name] = Value(f"%{name}", dtype, body.root)
        what = body.title
        with entered(body.root):
            result, ret_loc = trace.call_body(fn, body.args,
                                              [n for n, _ in args], what)
            single_vector = (len(results) == 1 and results[0][0].is_vector
                             and isinstance(result, (tuple, list)) and
                             not any(isinstance(r, (tuple, list))
                                     for r in result))
            if isinstance(result, (tuple, list)) and not single_vector:
                values = list(result)
            else:
                values = [result]
            if result is None or len(values) != len(results):
                expected = ", ".join(w for _, w in results)
                got = ("None" if result is None else
                       f"{len(values)} value(s)")
                raise trace_error(f"{what} returns {got}; it must return "
                                  f"{len(results)} value(s): {expected}",
                                  ret_loc)
            yields = []
            for value, (dtype, who) in zip(values, results):
                if isinstance(value, (tuple, list)) and dtype.is_vector:
                    value = ops.convert(dtype, *value, loc=ret_loc)
                v = ops.value_of(value, dtype, f"the result of {what}",
                                 loc=ret_loc)
                if v.dtype.mlir != dtype.mlir:
                    hint = (f"; convert with sim.{dtype.name}(x)"
                            if not dtype.is_vector else
                            f"; build it with {dtype!r}(...)")
                    raise trace_error(f"{what} returns {v.dtype} for {who} "
                                      f": {dtype.mlir}{hint}", ret_loc)
                trace.check_visible(v, body.root, ret_loc)
                yields.append(v)
            names = ", ".join(v.name for v in yields)
            types = ", ".join(v.dtype.mlir for v in yields)
            body.root.items.append(f"sim.yield {names} : {types}" +
                                   self._tracer.locations.ref(ret_loc))
        arg_text = ", ".join(f"%{n}: {t.mlir}" for n, t in args)
        return [f"  ^bb0({arg_text}):"] + body.render("    ")

    def save(self, path) -> str:
        """Writes the scene's text to `path`; returns the path."""
        text = self.mlir()
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        return str(path)

    def verify(self, *args: str) -> str:
        """Runs sim-opt on the scene (with extra options `args`); returns its
        output, raises CompileError at the Python line of a diagnostic."""
        from .compiler import run_sim_opt
        return run_sim_opt(self.mlir(), list(args))

    def __repr__(self):
        return f"<sim.Scene @{self.name}>"


def _is_int(value) -> bool:
    """An integer, Python's or numpy's; not a bool (True is no count)."""
    return (isinstance(value, numbers.Integral) and
            not isinstance(value, bool))


def _check_int(what: str, value, most: int, most_text: str, loc) -> int:
    """`value` as an int, refused at the user's line unless it is an
    integer from 1 to `most`."""
    if not _is_int(value) or not 1 <= value <= most:
        raise trace_error(f"{what} must be an int from 1 to {most_text}, "
                          f"not {value!r}", loc)
    return int(value)


def _check_dt(dt, precision: DType, loc) -> float:
    """`dt` as a float, refused at the user's line unless it is positive and
    finite in the scene's precision: sim-opt would say so only of the
    rounded value (a dt that underflows f32 reads as 0)."""
    if isinstance(dt, bool) or not isinstance(dt, numbers.Real):
        raise trace_error(f"dt must be a positive number, not {dt!r}", loc)
    try:
        value = float(dt)
    except OverflowError:  # an int or a fraction beyond the doubles
        value = None
    if not dt > 0 or (value is not None and not math.isfinite(value)):
        raise trace_error(f"dt must be a positive, finite number, not "
                          f"{dt!r}", loc)
    rounded = (math.inf if value is None else
               round_f32(value) if precision is f32 else value)
    if math.isinf(rounded):
        largest = F32_MAX if precision is f32 else sys.float_info.max
        raise trace_error(f"dt {dt!r} overflows {precision} (the largest "
                          f"finite {precision} is {largest!r})", loc)
    if rounded == 0:
        tiny = F32_TINY if precision is f32 else 5e-324
        hint = "; use precision=sim.f64" if precision is f32 else ""
        raise trace_error(f"dt {dt!r} underflows {precision} to 0 (the "
                          f"smallest positive {precision} is {tiny!r}){hint}",
                          loc)
    # A subnormal dt is no time step: the verifier and the runtime refuse
    # it too, but only of the rounded value and not at the user's line.
    smallest = 2.0 ** -126 if precision is f32 else sys.float_info.min
    if rounded < smallest:
        hint = "; use precision=sim.f64" if precision is f32 else ""
        raise trace_error(f"dt {dt!r} is subnormal in {precision} (the "
                          f"smallest normal {precision} is {smallest!r})"
                          f"{hint}", loc)
    return value


def _check_name(name, what, loc):
    if not isinstance(name, str) or not _NAME.match(name):
        raise trace_error(f"invalid {what} name {name!r}: a letter or _ then "
                          "letters, digits, _ $ .", loc)
