"""The operations of traced bodies: operators, math, casts, vectors, loops.

Every function here takes traced values (`Value`s, parameters) and Python
numbers, and appends `arith`, `math`, `vector` or `scf` operations to the
body being traced. Python numbers take the type of the traced operand they
meet (`x * 0.5` with an f32 `x` is `arith.mulf` by an f32 constant 0.5);
without one, an int is an i32 and a float has the scene's precision (the
type of its `dt`). Scalars meet vectors by `vector.broadcast`. Mixed types
(f32 with f64, u64 with i64, a float constant with an integer) raise
TraceError: convert with `sim.f64(x)`, `sim.u64(x)`, ...

Integers: `+ - *` wrap; `//` is floor division (`arith.floordivsi`,
`arith.divui` on unsigned) and `%` Python's modulo (its sign follows the
divisor); `sim.div` and `sim.rem` truncate like C. `>>` is arithmetic on
signed types and logical on unsigned ones. Floats: `/` is `arith.divf`,
`sim.min`/`sim.max` are `arith.minimumf`/`arith.maximumf` (NaN wins),
comparisons are ordered except `!=` (`une`).
"""

from __future__ import annotations

import numbers
from typing import Callable, Sequence

from . import trace
from .trace import (Block, Value, constant, current_block, emit, entered,
                    trace_error, user_location)
from .types import DType, boolean, i32, i64, index, vector

__all__ = [
    "Traceable", "value_of", "convert", "select", "where", "min", "max",
    "clamp", "fma", "abs", "sum", "dot", "reduce", "broadcast", "bitcast",
    "div", "rem", "fmod", "range", "loop", "read", "UNARY_MATH",
]

_range = range
_abs = abs
_min = min
_max = max
_sum = sum


class Traceable:
    """A handle that stands for a traced value (a parameter): operators
    and sim functions accept it where they accept a Value."""

    def _sim_value(self) -> Value:  # pragma: no cover - abstract
        raise NotImplementedError

    def __bool__(self):
        return bool(self._sim_value())

    def __index__(self):
        return self._sim_value().__index__()

    def __int__(self):
        return int(self._sim_value())

    def __float__(self):
        return float(self._sim_value())


def _is_traced(x) -> bool:
    return isinstance(x, (Value, Traceable))


def _is_bool(x) -> bool:
    """A Python or numpy bool (numpy's is no Python bool, and its type is
    named bool_ before numpy 2 and bool since)."""
    return isinstance(x, bool) or (type(x).__module__ == "numpy" and
                                   type(x).__name__ in ("bool_", "bool"))


def value_of(x, like: DType | None = None, what: str = "an operation",
             loc=None) -> Value:
    """`x` as a Value: a traced value as it is, a Python number as a
    constant of type `like` (default: i32 for ints, the scene's precision
    for floats)."""
    if isinstance(x, Value):
        return x
    if isinstance(x, Traceable):
        return x._sim_value()
    if loc is None:
        loc = user_location(2)
    if _is_bool(x):
        dtype = boolean if like is None else like
        if not dtype.is_bool:
            raise trace_error(f"the Python bool {x!r} mixed with a {dtype} "
                              f"value in {what}", loc)
        return constant(bool(x), dtype, loc)
    if isinstance(x, numbers.Integral):
        dtype = i32 if like is None else like
        if dtype.is_bool:
            raise trace_error(f"the integer {x!r} mixed with a bool value in "
                              f"{what}", loc)
        return constant(int(x), dtype, loc)
    if isinstance(x, numbers.Real):
        dtype = trace.current_body().default_float if like is None else like
        if not dtype.is_float:
            raise trace_error(f"the float constant {x!r} mixed with a "
                              f"{dtype} value in {what}; convert one side "
                              f"(sim.{dtype.elem.name}(...) or "
                              f"sim.f32(...)/sim.f64(...))", loc)
        return constant(float(x), dtype, loc)
    raise trace_error(f"unsupported type {type(x).__name__} in {what}: "
                      "traced bodies compute with sim values, Python ints, "
                      "floats and bools", loc)


def _broadcast(v: Value, lanes: int, loc) -> Value:
    target = vector(lanes, v.dtype.elem)
    return emit(f"vector.broadcast {v.name} : {v.dtype.mlir} to "
                f"{target.mlir}", [v], target, loc)


def _unify(xs: Sequence, what: str, loc=None) -> tuple[list[Value], DType]:
    """The operands of an elementwise operation with one common type."""
    if loc is None:
        loc = user_location(2)
    traced = [value_of(x, what=what) if _is_traced(x) else None for x in xs]
    types = [v.dtype for v in traced if v is not None]
    if not types:
        # Only Python numbers: the defaults of value_of.
        values = [value_of(x, what=what) for x in xs]
        types = [v.dtype for v in values]
        if len({t.mlir + t.kind for t in types}) > 1:
            kinds = [t.kind for t in types]
            if "float" in kinds:
                f = types[kinds.index("float")]
                values = [value_of(x, f, what) for x in xs]
                types = [f] * len(values)
        traced = values
    elems = {t.elem.name for t in types}
    if len(elems) > 1:
        names = " and ".join(sorted(elems))
        raise trace_error(f"mixed types in {what}: {names}; convert one "
                          f"operand, e.g. sim.{sorted(elems)[-1]}(x)", loc)
    lanes = {t.lanes for t in types if t.lanes is not None}
    if len(lanes) > 1:
        raise trace_error(f"vectors of {sorted(lanes)} lanes mixed in "
                          f"{what}", loc)
    elem = types[0].elem
    target = elem.with_lanes(next(iter(lanes)) if lanes else None)
    out = []
    for x, v in zip(xs, traced):
        if v is None:
            v = value_of(x, target, what)
        elif target.is_vector and not v.dtype.is_vector:
            v = _broadcast(v, target.lanes, loc)
        out.append(v)
    return out, target


# -- Arithmetic ----------------------------------------------------------------

_FLOAT_OPS = {"+": "addf", "-": "subf", "*": "mulf", "/": "divf"}
_INT_OPS = {"+": "addi", "-": "subi", "*": "muli", "&": "andi", "|": "ori",
            "^": "xori", "<<": "shli"}


def binary(op: str, a, b, loc=None) -> Value:
    if loc is None:
        loc = user_location(2)
    what = f"`{op}`"
    (va, vb), dtype = _unify([a, b], what, loc)
    t = dtype.mlir
    if dtype.is_bool:
        names = {"&": "andi", "|": "ori", "^": "xori"}
        if op not in names:
            raise trace_error(f"{what} on bool values; use &, |, ^ and "
                              "sim.select", loc)
        return emit(f"arith.{names[op]} {va.name}, {vb.name} : {t}",
                    [va, vb], dtype, loc)
    if dtype.is_float:
        if op == "//":
            raise trace_error("`//` on floats: use sim.floor(a / b)", loc)
        if op == "%":
            raise trace_error("`%` on floats: use sim.fmod(a, b) (C's fmod, "
                              "arith.remf)", loc)
        if op == "**":
            return emit(f"math.powf {va.name}, {vb.name} : {t}", [va, vb],
                        dtype, loc)
        if op not in _FLOAT_OPS:
            raise trace_error(f"{what} on {dtype} values", loc)
        return emit(f"arith.{_FLOAT_OPS[op]} {va.name}, {vb.name} : {t}",
                    [va, vb], dtype, loc)
    unsigned = dtype.is_unsigned
    if op == "/":
        raise trace_error("`/` on integers (a Python true division): use "
                          "`//` (floor), sim.div (truncating) or convert to "
                          "a float first", loc)
    if op == "//":
        name = "divui" if unsigned else "floordivsi"
        return emit(f"arith.{name} {va.name}, {vb.name} : {t}", [va, vb],
                    dtype, loc)
    if op == "%":
        if unsigned:
            return emit(f"arith.remui {va.name}, {vb.name} : {t}", [va, vb],
                        dtype, loc)
        # Python's modulo: the remainder takes the sign of the divisor.
        r = emit(f"arith.remsi {va.name}, {vb.name} : {t}", [va, vb], dtype,
                 loc)
        zero = value_of(0, dtype)
        nonzero = compare("!=", r, zero, loc)
        differ = compare("!=", compare("<", r, zero, loc),
                         compare("<", vb, zero, loc), loc)
        fix = binary("&", nonzero, differ, loc)
        return select(fix, binary("+", r, vb, loc), r, loc=loc)
    if op == ">>":
        name = "shrui" if unsigned else "shrsi"
        return emit(f"arith.{name} {va.name}, {vb.name} : {t}", [va, vb],
                    dtype, loc)
    if op == "**":
        return emit(f"math.ipowi {va.name}, {vb.name} : {t}", [va, vb],
                    dtype, loc)
    if op not in _INT_OPS:
        raise trace_error(f"{what} on {dtype} values", loc)
    return emit(f"arith.{_INT_OPS[op]} {va.name}, {vb.name} : {t}", [va, vb],
                dtype, loc)


_FLOAT_PREDICATES = {"<": "olt", "<=": "ole", ">": "ogt", ">=": "oge",
                     "==": "oeq", "!=": "une"}
_SIGNED_PREDICATES = {"<": "slt", "<=": "sle", ">": "sgt", ">=": "sge",
                      "==": "eq", "!=": "ne"}
_UNSIGNED_PREDICATES = {"<": "ult", "<=": "ule", ">": "ugt", ">=": "uge",
                        "==": "eq", "!=": "ne"}


def compare(op: str, a, b, loc=None) -> Value:
    if loc is None:
        loc = user_location(2)
    (va, vb), dtype = _unify([a, b], f"`{op}`", loc)
    result = boolean.with_lanes(dtype.lanes)
    if dtype.is_float:
        return emit(f"arith.cmpf {_FLOAT_PREDICATES[op]}, {va.name}, "
                    f"{vb.name} : {dtype.mlir}", [va, vb], result, loc)
    table = (_UNSIGNED_PREDICATES if dtype.is_unsigned or dtype.is_bool
             else _SIGNED_PREDICATES)
    return emit(f"arith.cmpi {table[op]}, {va.name}, {vb.name} : "
                f"{dtype.mlir}", [va, vb], result, loc)


def negate(a, loc=None) -> Value:
    if loc is None:
        loc = user_location(2)
    v = value_of(a, what="unary `-`")
    if v.dtype.is_float:
        return emit(f"arith.negf {v.name} : {v.dtype.mlir}", [v], v.dtype,
                    loc)
    if v.dtype.is_bool:
        raise trace_error("unary `-` on a bool value", loc)
    return binary("-", value_of(0, v.dtype), v, loc)


def invert(a, loc=None) -> Value:
    if loc is None:
        loc = user_location(2)
    v = value_of(a, what="`~`")
    if v.dtype.is_float:
        raise trace_error("`~` on a float value", loc)
    # All bits set: -1 is no unsigned value.
    ones = (True if v.dtype.is_bool else
            (1 << v.dtype.bits) - 1 if v.dtype.is_unsigned else -1)
    return binary("^", v, value_of(ones, v.dtype), loc)


def select(condition, if_true, if_false, loc=None):
    """`if_true` where `condition` holds, else `if_false` (`arith.select`;
    a vector of bools selects per lane). Both branches are computed."""
    if loc is None:
        loc = user_location(2)
    if not _is_traced(condition):
        if isinstance(condition, int) or _is_bool(condition):
            return if_true if condition else if_false
        raise trace_error(f"unsupported condition type "
                          f"{type(condition).__name__} in sim.select", loc)
    c = value_of(condition, what="sim.select")
    if not c.dtype.is_bool:
        raise trace_error(f"sim.select needs a bool condition (a "
                          f"comparison), not {c.dtype}", loc)
    (a, b), dtype = _unify([if_true, if_false], "sim.select", loc)
    if c.dtype.is_vector:
        if not dtype.is_vector:
            a, b = (_broadcast(x, c.dtype.lanes, loc) for x in (a, b))
            dtype = a.dtype
        if dtype.lanes != c.dtype.lanes:
            raise trace_error(f"sim.select of {dtype.mlir} by a "
                              f"{c.dtype.mlir} condition", loc)
        types = f"{c.dtype.mlir}, {dtype.mlir}"
    else:
        types = dtype.mlir
    return emit(f"arith.select {c.name}, {a.name}, {b.name} : {types}",
                [c, a, b], dtype, loc)


where = select


def _minmax(kind: str, values, loc) -> Value:
    if len(values) < 2:
        raise trace_error(f"sim.{kind} takes at least two values", loc)
    acc = values[0]
    for other in values[1:]:
        (va, vb), dtype = _unify([acc, other], f"sim.{kind}", loc)
        if dtype.is_float:
            name = "minimumf" if kind == "min" else "maximumf"
        elif dtype.is_bool:
            raise trace_error(f"sim.{kind} of bool values", loc)
        else:
            name = ("min" if kind == "min" else "max") + \
                ("ui" if dtype.is_unsigned else "si")
        acc = emit(f"arith.{name} {va.name}, {vb.name} : {dtype.mlir}",
                   [va, vb], dtype, loc)
    return acc


def min(*values):
    """The smallest value: `arith.minimumf` on floats (a NaN wins),
    `arith.minsi`/`arith.minui` on integers."""
    return _minmax("min", values, user_location(2))


def max(*values):
    """The largest value: `arith.maximumf`, `arith.maxsi`, `arith.maxui`."""
    return _minmax("max", values, user_location(2))


def clamp(x, lo, hi):
    """`min(max(x, lo), hi)`."""
    loc = user_location(2)
    return _minmax("min", [_minmax("max", [x, lo], loc), hi], loc)


def _float_operands(xs, name, loc):
    values, dtype = _unify(xs, f"sim.{name}", loc)
    if not dtype.is_float:
        raise trace_error(f"sim.{name} needs float values, not {dtype}; "
                          f"convert with sim.f32(x) or sim.f64(x)", loc)
    return values, dtype


def fma(a, b, c):
    """`a * b + c` rounded once: `math.fma` on scalars, `vector.fma` on
    vectors (scalars are broadcast)."""
    loc = user_location(2)
    (va, vb, vc), dtype = _float_operands([a, b, c], "fma", loc)
    op = "vector.fma" if dtype.is_vector else "math.fma"
    return emit(f"{op} {va.name}, {vb.name}, {vc.name} : {dtype.mlir}",
                [va, vb, vc], dtype, loc)


UNARY_MATH = ["exp", "exp2", "expm1", "log", "log2", "log10", "log1p",
              "sqrt", "rsqrt", "cbrt", "sin", "cos", "tan", "asin", "acos",
              "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh",
              "erf", "floor", "ceil", "round", "roundeven", "trunc"]


def _make_unary(name: str) -> Callable:
    def function(x):
        loc = user_location(2)
        (v,), dtype = _float_operands([x], name, loc)
        return emit(f"math.{name} {v.name} : {dtype.mlir}", [v], dtype, loc)
    function.__name__ = name
    function.__doc__ = f"`math.{name}` of a float scalar or vector."
    return function


for _name in UNARY_MATH:
    globals()[_name] = _make_unary(_name)
    __all__.append(_name)


def _make_binary_math(name: str, op: str) -> Callable:
    def function(a, b):
        loc = user_location(2)
        (va, vb), dtype = _float_operands([a, b], name, loc)
        return emit(f"math.{op} {va.name}, {vb.name} : {dtype.mlir}",
                    [va, vb], dtype, loc)
    function.__name__ = name
    function.__doc__ = f"`math.{op}` of two float scalars or vectors."
    return function


atan2 = _make_binary_math("atan2", "atan2")
pow = _make_binary_math("pow", "powf")
copysign = _make_binary_math("copysign", "copysign")
__all__ += ["atan2", "pow", "copysign"]


def abs(x):
    """`math.absf` on floats, `math.absi` on integers."""
    loc = user_location(2)
    v = value_of(x, what="sim.abs")
    if v.dtype.is_bool:
        raise trace_error("sim.abs of a bool value", loc)
    op = "math.absf" if v.dtype.is_float else "math.absi"
    return emit(f"{op} {v.name} : {v.dtype.mlir}", [v], v.dtype, loc)


def div(a, b):
    """Truncating division (`arith.divsi`/`arith.divui`; `arith.divf` on
    floats)."""
    loc = user_location(2)
    (va, vb), dtype = _unify([a, b], "sim.div", loc)
    name = ("divf" if dtype.is_float else
            "divui" if dtype.is_unsigned else "divsi")
    return emit(f"arith.{name} {va.name}, {vb.name} : {dtype.mlir}",
                [va, vb], dtype, loc)


def rem(a, b):
    """The remainder of truncating division, with the sign of `a`
    (`arith.remsi`/`arith.remui`/`arith.remf`)."""
    loc = user_location(2)
    (va, vb), dtype = _unify([a, b], "sim.rem", loc)
    name = ("remf" if dtype.is_float else
            "remui" if dtype.is_unsigned else "remsi")
    return emit(f"arith.{name} {va.name}, {vb.name} : {dtype.mlir}",
                [va, vb], dtype, loc)


def fmod(a, b):
    """C's fmod (`arith.remf`)."""
    loc = user_location(2)
    (va, vb), dtype = _float_operands([a, b], "fmod", loc)
    return emit(f"arith.remf {va.name}, {vb.name} : {dtype.mlir}", [va, vb],
                dtype, loc)


# -- Vectors --------------------------------------------------------------------

def broadcast(x, lanes: int, dtype: DType | None = None):
    """A vector of `lanes` copies of the scalar `x` (`vector.broadcast`)."""
    loc = user_location(2)
    v = value_of(x, dtype, "sim.broadcast")
    if v.dtype.is_vector:
        raise trace_error("sim.broadcast of a vector", loc)
    return _broadcast(v, lanes, loc)


def extract(v: Value, lane, loc=None) -> Value:
    if loc is None:
        loc = user_location(2)
    if not v.dtype.is_vector:
        raise trace_error(f"indexing a {v.dtype} scalar (only vectors have "
                          "lanes; buffers are read with B[j])", loc)
    elem = v.dtype.elem
    if _is_traced(lane):
        k = convert(index, lane)
        return emit(f"vector.extract {v.name}[{k.name}] : {elem.mlir} from "
                    f"{v.dtype.mlir}", [v, k], elem, loc)
    if not isinstance(lane, numbers.Integral):
        raise trace_error(f"a vector lane must be an int, not "
                          f"{type(lane).__name__}", loc)
    lanes = v.dtype.lanes
    k = int(lane) + (lanes if lane < 0 else 0)
    if not 0 <= k < lanes:
        raise trace_error(f"lane {lane} of a {lanes}-lane vector", loc)
    return emit(f"vector.extract {v.name}[{k}] : {elem.mlir} from "
                f"{v.dtype.mlir}", [v], elem, loc)


def insert(v: Value, lane: int, x, loc=None) -> Value:
    """A copy of vector `v` with lane `lane` set to `x` (`vector.insert`)."""
    if loc is None:
        loc = user_location(2)
    if not v.dtype.is_vector:
        raise trace_error(f"replace() on a {v.dtype} scalar", loc)
    if not isinstance(lane, numbers.Integral) or not \
            -v.dtype.lanes <= lane < v.dtype.lanes:
        raise trace_error(f"lane {lane!r} of a {v.dtype.lanes}-lane vector",
                          loc)
    lane = int(lane) % v.dtype.lanes
    s = value_of(x, v.dtype.elem, "replace()")
    if s.dtype is not v.dtype.elem:
        raise trace_error(f"replace() of a {v.dtype.elem} lane with {s.dtype}",
                          loc)
    return emit(f"vector.insert {s.name}, {v.name} [{lane}] : "
                f"{s.dtype.mlir} into {v.dtype.mlir}", [s, v], v.dtype, loc)


_REDUCTIONS = {
    "add": ("add", "add", "add"), "mul": ("mul", "mul", "mul"),
    "min": ("minimumf", "minsi", "minui"), "max": ("maximumf", "maxsi", "maxui"),
    "and": (None, "and", "and"), "or": (None, "or", "or"),
    "xor": (None, "xor", "xor"),
}


def reduce(kind: str, v, start=None):
    """`vector.reduction <kind>` of a vector's lanes, in lane order, with an
    optional start value (the accumulator operand). `kind`: add, mul, min,
    max (and, or, xor on integers)."""
    loc = user_location(2)
    vv = value_of(v, what="sim.reduce")
    if not vv.dtype.is_vector:
        raise trace_error(f"sim.reduce of a {vv.dtype} scalar", loc)
    if kind not in _REDUCTIONS:
        raise trace_error(f"unknown reduction {kind!r} (add, mul, min, max, "
                          "and, or, xor)", loc)
    elem = vv.dtype.elem
    float_name, signed_name, unsigned_name = _REDUCTIONS[kind]
    name = (float_name if elem.is_float else
            unsigned_name if elem.is_unsigned else signed_name)
    if name is None:
        raise trace_error(f"reduction {kind!r} of {elem} lanes", loc)
    text = f"vector.reduction <{name}>, {vv.name}"
    operands = [vv]
    if start is not None:
        acc = value_of(start, elem, "sim.reduce")
        if acc.dtype is not elem:
            raise trace_error(f"the start value of sim.reduce is {acc.dtype}, "
                              f"not {elem}", loc)
        text += f", {acc.name}"
        operands.append(acc)
    return emit(f"{text} : {vv.dtype.mlir} into {elem.mlir}", operands, elem,
                loc)


def sum(v, start=0):
    """The sum of a vector's lanes in lane order, added to `start` (0 by
    default): `vector.reduction <add>, %v, %start`."""
    return reduce("add", v, start)


def dot(a, b):
    """`sum(a * b)`: the lanes' products added in lane order to 0."""
    return reduce("add", binary("*", a, b, user_location(2)), 0)


def bitcast(x, dtype: DType):
    """The bits of `x` as `dtype` of the same width (`arith.bitcast`)."""
    loc = user_location(2)
    v = value_of(x, what="sim.bitcast")
    target = dtype.with_lanes(v.dtype.lanes) if not dtype.is_vector else dtype
    if target.elem.bits != v.dtype.elem.bits or target.lanes != v.dtype.lanes:
        raise trace_error(f"sim.bitcast from {v.dtype} to {dtype}: the widths "
                          "differ", loc)
    if target.mlir == v.dtype.mlir:
        return Value(v.name, target, v.block, v.from_read, v.loc)
    return emit(f"arith.bitcast {v.name} : {v.dtype.mlir} to {target.mlir}",
                [v], target, loc)


# -- Conversions ------------------------------------------------------------------

def convert(dtype: DType, *args, loc=None):
    """`dtype(x)`: a conversion, a constant, or a vector built from lanes.
    `loc`: where errors point (default: the user's current line)."""
    if loc is None:
        loc = user_location(2)
    if not trace.in_trace():
        raise trace_error(f"sim.{dtype.elem.name}(...) builds a traced value: "
                          "it is only possible inside a traced body", loc)
    if dtype.is_vector and len(args) == dtype.lanes and len(args) > 1:
        if not any(_is_traced(a) for a in args):
            return constant(list(args), dtype, loc)
        lanes = [_convert_scalar(dtype.elem, a, loc) for a in args]
        names = ", ".join(v.name for v in lanes)
        return emit(f"vector.from_elements {names} : {dtype.mlir}", lanes,
                    dtype, loc)
    if len(args) != 1:
        raise trace_error(f"{dtype!r} takes one value"
                          + (f" or {dtype.lanes} lanes" if dtype.is_vector
                             else "") + f", not {len(args)}", loc)
    (x,) = args
    if not _is_traced(x):
        if isinstance(x, (list, tuple)):
            return convert(dtype, *x, loc=loc)
        return value_of(x, dtype, f"{dtype!r}(...)", loc)
    v = value_of(x)
    if dtype.is_vector:
        if v.dtype.is_vector:
            if v.dtype.lanes != dtype.lanes:
                raise trace_error(f"{dtype!r} of a {v.dtype.lanes}-lane "
                                  "vector", loc)
            return _cast(v, dtype, loc)
        return _broadcast(_convert_scalar(dtype.elem, v, loc), dtype.lanes,
                          loc)
    return _cast(v, dtype.with_lanes(v.dtype.lanes), loc)


def _convert_scalar(elem: DType, x, loc) -> Value:
    if not _is_traced(x):
        return value_of(x, elem, f"sim.{elem.name}(...)", loc)
    v = value_of(x)
    if v.dtype.is_vector:
        raise trace_error("a vector as a lane of a vector", loc)
    return _cast(v, elem, loc)


def _cast(v: Value, target: DType, loc) -> Value:
    """Converts `v` to `target` (same lanes): the arith cast it needs."""
    source = v.dtype
    s, t = source.elem, target.elem
    if s.mlir == t.mlir and s.kind == t.kind:
        return v

    def op(name, value=v, to=target):
        return emit(f"arith.{name} {value.name} : {value.dtype.mlir} to "
                    f"{to.mlir}", [value], to, loc)

    if t.kind == "bool":
        return compare("!=", v, value_of(0, source), loc)
    if s.kind == "float" and t.kind == "float":
        return op("extf" if t.bits > s.bits else "truncf")
    if t.kind == "float":
        if s.kind == "index":
            wide = op("index_cast", v, i64.with_lanes(source.lanes))
            return op("sitofp", wide)
        return op("uitofp" if s.kind in ("uint", "bool") else "sitofp")
    if s.kind == "float":
        if t.kind == "index":
            wide = op("fptosi", v, i64.with_lanes(source.lanes))
            return op("index_cast", wide)
        return op("fptoui" if t.kind == "uint" else "fptosi")
    # Integers (and bools) to integers.
    if s.kind == "index" or t.kind == "index":
        unsigned = t.kind == "uint" or s.kind in ("uint", "bool")
        return op("index_castui" if unsigned else "index_cast")
    if s.bits == t.bits:
        # Same width, other signedness: the same bits, another reading.
        return Value(v.name, target, v.block, v.from_read, v.loc)
    if t.bits > s.bits:
        return op("extui" if s.kind in ("uint", "bool") else "extsi")
    return op("trunci")


# -- Buffers -------------------------------------------------------------------------

def read(buffer: str, dtype: DType, item, loc=None) -> Value:
    """`sim.read @buffer[item]`: the buffer at `item`, at the reader's
    local time (docs/Model.md)."""
    if loc is None:
        loc = user_location(2)
    current_block(f"reading @{buffer}")
    if isinstance(item, numbers.Integral) and not isinstance(item, bool):
        j = value_of(int(item), index, f"@{buffer}[...]")
    elif _is_traced(item):
        j = value_of(item)
        if j.dtype.is_vector or not (j.dtype.is_int):
            raise trace_error(f"the item of a read of @{buffer} must be an "
                              f"integer, not {j.dtype}", loc)
        if j.dtype is not index:
            j = _cast(j, index, loc)
    else:
        raise trace_error(f"unsupported item {item!r} in a read of "
                          f"@{buffer}: an int or a traced integer "
                          f"(i + k)", loc)
    return emit(f"sim.read @{buffer}[{j.name}] : {dtype.mlir}", [j], dtype,
                loc, from_read=True)


# -- Loops ------------------------------------------------------------------------

MAX_UNROLL = 4096


def range(*args):
    """A loop unrolled while tracing: `for k in sim.range(-4, 5)` runs the
    Python body once per k with k a Python int, so `B[i + k]` reads
    `%i + constant` (a window). Bounds must be Python ints; a bound that
    is a parameter needs `sim.loop` (an `scf.for`)."""
    loc = user_location(2)
    for a in args:
        if _is_traced(a):
            v = value_of(a)
            if v.from_read:
                raise trace_error("a data-dependent loop bound (computed from "
                                  "a buffer read) in sim.range: loop bounds "
                                  "must not depend on the state", loc)
            raise trace_error("sim.range unrolls while tracing and needs "
                              "Python int bounds; for a bound that is a "
                              "parameter use sim.loop(lo, hi, carry=...), an "
                              "scf.for", loc)
        if not isinstance(a, numbers.Integral) or isinstance(a, bool):
            raise trace_error(f"sim.range bounds must be ints, not "
                              f"{type(a).__name__}", loc)
    r = _range(*(int(a) for a in args))
    if len(r) > MAX_UNROLL:
        raise trace_error(f"sim.range of {len(r)} iterations unrolls too far "
                          f"(at most {MAX_UNROLL}); use sim.loop", loc)
    return r


def _bound(x, what, loc) -> Value:
    if _is_traced(x):
        v = value_of(x)
        if v.from_read:
            raise trace_error(f"a data-dependent loop bound ({what} computed "
                              "from a buffer read): sim.loop bounds must not "
                              "depend on the state", loc)
        if not v.dtype.is_int or v.dtype.is_vector:
            raise trace_error(f"the {what} of sim.loop must be an integer, "
                              f"not {v.dtype}", loc)
        return v if v.dtype is index else _cast(v, index, loc)
    if not isinstance(x, numbers.Integral) or isinstance(x, bool):
        raise trace_error(f"the {what} of sim.loop must be an int or a "
                          f"traced integer, not {type(x).__name__}", loc)
    return value_of(int(x), index, "sim.loop")


def loop(lo, hi=None, step=1, *, carry, body: Callable | None = None):
    """An `scf.for` from `lo` to `hi` (exclusive) by `step` with loop-carried
    values (`iter_args`), for loops whose bounds are parameters or too
    long to unroll.

    `body(k, *carried)` gets the induction variable `k` (an index) and the
    carried values, and returns their next values. Used as a decorator, the
    name of the function becomes the loop's results:

        @sim.loop(0, rounds, carry=(x0, x1))
        def x(k, a, b):
            return a * 0.5, b + a
        # x is now (x0', x1')

    A single carried value (not a tuple) gives a single result. Bounds may
    be Python ints or traced integers computed from parameters, `i`, `t`
    or `n`, never from a buffer read (a data-dependent loop bound).
    """
    loc = user_location(2)
    if hi is None:
        lo, hi = 0, lo
    single = not isinstance(carry, (tuple, list))
    carried = [carry] if single else list(carry)
    if not carried:
        raise trace_error("sim.loop needs at least one carried value: a "
                          "loop body has no effect but the values it "
                          "returns", loc)

    def run(fn: Callable):
        block = current_block("sim.loop")
        bounds = [_bound(lo, "lower bound", loc), _bound(hi, "upper bound", loc),
                  _bound(step, "step", loc)]
        inits = [value_of(c, what="the carry of sim.loop") for c in carried]
        for v in bounds + inits:
            trace.check_visible(v, block, loc)
        inner = Block(block.body, block, "loop")
        k = Value(block.body.fresh("k"), index, inner, False, loc)
        args = [Value(block.body.fresh("a"), v.dtype, inner, v.from_read, loc)
                for v in inits]
        with entered(inner):
            result, ret_loc = _call_loop(fn, k, args)
            results = [result] if single else (
                list(result) if isinstance(result, (tuple, list)) else None)
            if results is None or len(results) != len(inits):
                raise trace_error(
                    f"a sim.loop body must return {len(inits)} value(s) like "
                    f"its carry, not {_describe(result)}", ret_loc)
            nexts = []
            for n, (r, init) in enumerate(zip(results, inits)):
                v = value_of(r, init.dtype, "the result of a sim.loop body",
                             ret_loc)
                if v.dtype.mlir != init.dtype.mlir:
                    raise trace_error(
                        f"result {n} of the sim.loop body is {v.dtype}, its "
                        f"carry is {init.dtype}", ret_loc)
                trace.check_visible(v, inner, ret_loc)
                nexts.append(v)
        scene = block.body.scene
        types = ", ".join(v.dtype.mlir for v in inits)
        yield_line = (f"scf.yield {', '.join(v.name for v in nexts)} : {types}"
                      + scene.locations.ref(ret_loc))
        inner.items.append(yield_line)
        name = block.body.fresh("r")
        iter_args = ", ".join(f"{a.name} = {v.name}"
                              for a, v in zip(args, inits))
        count = len(inits)
        header = (f"{name}{':' + str(count) if count > 1 else ''} = scf.for "
                  f"{k.name} = {bounds[0].name} to {bounds[1].name} step "
                  f"{bounds[2].name} iter_args({iter_args}) -> ({types}) {{")
        block.items.append((header, inner, "}" + scene.locations.ref(loc)))
        from_read = any(v.from_read for v in inits + nexts)
        if count == 1:
            outs = [Value(name, inits[0].dtype, block, from_read, loc)]
        else:
            outs = [Value(f"{name}#{n}", v.dtype, block, from_read, loc)
                    for n, v in enumerate(inits)]
        return outs[0] if single else tuple(outs)

    if body is not None:
        return run(body)
    return run


def _call_loop(fn, k, args):
    code = getattr(fn, "__code__", None)
    with trace.returns.active():
        result = fn(k, *args)
        ret_loc = trace.returns.returns.get(code) if code is not None else None
    return result, ret_loc or trace.function_location(fn)


def _describe(x) -> str:
    if isinstance(x, (tuple, list)):
        return f"{len(x)} values"
    if x is None:
        return "None"
    return "1 value"


# -- Operators on values ------------------------------------------------------------

# The numpy ufuncs of Python's operators. A numpy scalar on the left of an
# operator (`np.float64(0.1) * x`) is numpy's arithmetic first, which calls
# the ufunc with the traced value and so comes to __array_ufunc__, never to
# the traced value's reflected operator.
_UFUNC_OPERATORS = {"add": "+", "subtract": "-", "multiply": "*",
                    "divide": "/", "true_divide": "/", "floor_divide": "//",
                    "remainder": "%", "power": "**", "bitwise_and": "&",
                    "bitwise_or": "|", "bitwise_xor": "^", "left_shift": "<<",
                    "right_shift": ">>"}
_UFUNC_COMPARISONS = {"less": "<", "less_equal": "<=", "greater": ">",
                      "greater_equal": ">=", "equal": "==", "not_equal": "!="}
_REFLECTED = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "==": "==",
              "!=": "!="}


def _array_ufunc(self, ufunc, method, *inputs, **kwargs):
    """numpy's hook for its functions on a traced value: an operator between
    a numpy scalar (or a 0-d array) and a traced value is that operator on
    the scalar as on the Python number (either side); any other numpy
    function, and numpy arrays, raise TraceError."""
    import numpy as np  # numpy calls this, so it is loaded already
    loc = user_location(2)
    name = ufunc.__name__
    # numpy's comparisons make a 0-d array of the scalar on their left:
    # it is that scalar.
    inputs = tuple(x[()] if isinstance(x, np.ndarray) and x.ndim == 0
                   else x for x in inputs)
    if method == "__call__" and not kwargs and len(inputs) == 2 and \
            all(_is_traced(x) or isinstance(x, np.generic) for x in inputs):
        if name in _UFUNC_OPERATORS:
            return binary(_UFUNC_OPERATORS[name], *inputs, loc)
        if name in _UFUNC_COMPARISONS:
            op = _UFUNC_COMPARISONS[name]
            a, b = inputs
            if not _is_traced(a):
                # As Python does for a number on the left: the reflected
                # comparison of the traced value (`0.5 < x` is `x > 0.5`).
                a, b, op = b, a, _REFLECTED[op]
            return compare(op, a, b, loc)
    if any(isinstance(x, np.ndarray) for x in inputs):
        raise trace_error(f"a numpy array with a traced value (numpy's "
                          f"{name}): a traced body computes one item from "
                          f"sim values and scalars; take the array's "
                          f"element as a Python or numpy scalar", loc)
    raise trace_error(f"the numpy function {name} on a traced value: use the "
                      f"functions of sim (sim.exp, sim.sqrt, sim.where, ...)",
                      loc)


def _no_modulus(modulus, loc):
    """Python's three-argument pow(a, b, m) on a traced value: refused."""
    if modulus is not None:
        raise trace_error("pow(a, b, modulus) on a traced value: sim has no "
                          "modular power; use a ** b (sim.pow(a, b) on "
                          "floats) and then % (integers) or sim.fmod "
                          "(floats)", loc)


def _python_rounding(name: str, use: str) -> Callable:
    """round(), math.floor(), math.ceil(), math.trunc() of a traced value:
    a TraceError that names the sim function (Python wants an int back,
    which a traced value cannot be)."""
    def refuse(self, *args):
        raise trace_error(f"{name}() of a traced value: its value is not "
                          f"known while tracing; use {use}", user_location(2))
    return refuse


_ROUNDING = {
    "round": ("round", "sim.round(x) (halves away from zero) or "
              "sim.roundeven(x) (halves to even, as Python's round); both "
              "give a float: sim.i32(sim.round(x)) for an integer"),
    "floor": ("math.floor", "sim.floor(x) (a float; sim.i32(sim.floor(x)) "
              "for an integer)"),
    "ceil": ("math.ceil", "sim.ceil(x) (a float; sim.i32(sim.ceil(x)) for an "
             "integer)"),
    "trunc": ("math.trunc", "sim.trunc(x) (a float), or sim.i32(x), which "
              "truncates"),
}


def _divmod(self, other):
    raise trace_error("divmod() of a traced value: use a // b and a % b on "
                      "integers, sim.floor(a / b) and sim.fmod(a, b) on "
                      "floats", user_location(2))


def _attach():
    def make_binary(op):
        if op == "**":
            # pow(a, b, m) calls __pow__ with the modulus.
            def forward(self, other, modulus=None):
                loc = user_location(2)
                _no_modulus(modulus, loc)
                return binary(op, self, other, loc)

            def reverse(self, other, modulus=None):
                loc = user_location(2)
                _no_modulus(modulus, loc)
                return binary(op, other, self, loc)
            return forward, reverse

        def forward(self, other):
            return binary(op, self, other, user_location(2))

        def reverse(self, other):
            return binary(op, other, self, user_location(2))
        return forward, reverse

    names = {"+": "add", "-": "sub", "*": "mul", "/": "truediv",
             "//": "floordiv", "%": "mod", "**": "pow", "&": "and",
             "|": "or", "^": "xor", "<<": "lshift", ">>": "rshift"}
    compares = {"<": "lt", "<=": "le", ">": "gt", ">=": "ge", "==": "eq",
                "!=": "ne"}
    for cls in (Value, Traceable):
        for op, name in names.items():
            forward, reverse = make_binary(op)
            setattr(cls, f"__{name}__", forward)
            setattr(cls, f"__r{name}__", reverse)
        for op, name in compares.items():
            setattr(cls, f"__{name}__",
                    (lambda op: lambda self, other: compare(
                        op, self, other, user_location(2)))(op))
        cls.__neg__ = lambda self: negate(self, user_location(2))
        cls.__pos__ = lambda self: value_of(self)
        cls.__invert__ = lambda self: invert(self, user_location(2))
        cls.__abs__ = lambda self: abs(self)
        for name, (python, use) in _ROUNDING.items():
            setattr(cls, f"__{name}__", _python_rounding(python, use))
        cls.__divmod__ = cls.__rdivmod__ = _divmod
        cls.__hash__ = object.__hash__
        cls.__array_ufunc__ = _array_ufunc
        cls.__array__ = Value.__array__

    Value.__getitem__ = lambda self, lane: extract(self, lane,
                                                   user_location(2))
    Value.replace = lambda self, lane, x: insert(self, lane, x,
                                                 user_location(2))
    for lane, attr in enumerate("xyzw"):
        setattr(Value, attr, property(
            (lambda lane: lambda self: extract(self, lane,
                                               user_location(2)))(lane)))


_attach()
