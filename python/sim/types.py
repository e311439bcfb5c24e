"""Element types of traced values: scalars and small vectors.

A `DType` is what the tracer knows about a value: its MLIR type and how
Python operators on it map to `arith` operations. Signed and unsigned
integers share MLIR's signless types (`u64` is `i64`); the Python-level type
picks the operation (`//` on `u64` is `arith.divui`, on `i64`
`arith.floordivsi`; `>>` is `arith.shrui` or `arith.shrsi`).

Calling a type converts or builds a value inside a traced body:
`sim.f32(n)` (`arith.sitofp`), `sim.u64(i)` (`arith.index_castui`),
`sim.vector(2, sim.f64)(x, y)` (`vector.from_elements`), `sim.f32(0.1)`
(a constant rounded to f32).
"""

from __future__ import annotations

import math
import struct

__all__ = [
    "DType", "VectorType", "f32", "f64", "i32", "i64", "u32", "u64", "index",
    "boolean", "vector", "SCALARS", "parse_type",
]


class DType:
    """A scalar type. `kind` is one of float, sint, uint, index, bool."""

    def __init__(self, name: str, mlir: str, kind: str, bits: int,
                 numpy: str | None):
        self.name = name
        self.mlir = mlir
        self.kind = kind
        self.bits = bits
        self.numpy = numpy
        self.lanes = None

    @property
    def elem(self) -> "DType":
        return self

    @property
    def is_vector(self) -> bool:
        return self.lanes is not None

    @property
    def is_float(self) -> bool:
        return self.elem.kind == "float"

    @property
    def is_int(self) -> bool:
        return self.elem.kind in ("sint", "uint", "index")

    @property
    def is_unsigned(self) -> bool:
        return self.elem.kind == "uint"

    @property
    def is_bool(self) -> bool:
        return self.elem.kind == "bool"

    def with_lanes(self, lanes: int | None) -> "DType":
        """This element type with `lanes` (a scalar with None)."""
        return self.elem if lanes is None else vector(lanes, self.elem)

    def __call__(self, *args):
        from . import ops  # the conversions live with the other operations
        return ops.convert(self, *args)

    def __repr__(self) -> str:
        return f"sim.{self.name}"

    def __str__(self) -> str:
        return self.name


class VectorType(DType):
    """A vector of 1 to 16 lanes of a scalar type (`vector<4xf32>`)."""

    def __init__(self, lanes: int, elem: DType):
        super().__init__(f"vector({lanes}, {elem.name})",
                         f"vector<{lanes}x{elem.mlir}>", elem.kind, elem.bits,
                         elem.numpy)
        self._elem = elem
        self.lanes = lanes

    @property
    def elem(self) -> DType:
        return self._elem

    def __repr__(self) -> str:
        return f"sim.vector({self.lanes}, sim.{self._elem.name})"


f32 = DType("f32", "f32", "float", 32, "float32")
f64 = DType("f64", "f64", "float", 64, "float64")
i32 = DType("i32", "i32", "sint", 32, "int32")
i64 = DType("i64", "i64", "sint", 64, "int64")
u32 = DType("u32", "i32", "uint", 32, "uint32")
u64 = DType("u64", "i64", "uint", 64, "uint64")
index = DType("index", "index", "index", 64, "int64")
boolean = DType("bool", "i1", "bool", 1, "bool")

SCALARS = {t.name: t for t in (f32, f64, i32, i64, u32, u64, index, boolean)}

_vectors: dict[tuple[int, str], VectorType] = {}


def vector(lanes: int, elem: DType) -> VectorType:
    """The vector type of `lanes` (1 to 16) elements of scalar type `elem`."""
    if not isinstance(lanes, int) or not 1 <= lanes <= 16:
        raise ValueError(f"a vector has 1 to 16 lanes, not {lanes!r}")
    if not isinstance(elem, DType) or elem.is_vector:
        raise ValueError(f"a vector's element is a scalar type, not {elem!r}")
    key = (lanes, elem.name)
    if key not in _vectors:
        _vectors[key] = VectorType(lanes, elem)
    return _vectors[key]


def parse_type(text: str) -> DType:
    """A type from its MLIR spelling (`f32`, `vector<2xf64>`, `i32`...);
    signless integers read as signed."""
    text = text.strip()
    if text.startswith("vector<") and text.endswith(">"):
        lanes, _, elem = text[len("vector<"):-1].partition("x")
        return vector(int(lanes), parse_type(elem))
    by_mlir = {"f32": f32, "f64": f64, "i32": i32, "i64": i64,
               "index": index, "i1": boolean}
    if text not in by_mlir:
        raise ValueError(f"unsupported type {text!r}")
    return by_mlir[text]


# -- Constants as MLIR text ----------------------------------------------------

def round_f32(value: float) -> float:
    """`value` rounded to the nearest f32 (as a Python float)."""
    try:
        return struct.unpack("<f", struct.pack("<f", value))[0]
    except OverflowError:
        return float("inf") if value > 0 else float("-inf")


F32_MAX = 3.4028234663852886e+38  # the largest finite f32
F32_TINY = 1.401298464324817e-45  # the smallest positive (subnormal) f32


def float_literal(value: float, dtype: DType) -> str:
    """An MLIR literal that parses to exactly `value` in `dtype` (f32/f64).

    Finite values are printed as the shortest decimal of the (rounded)
    double, with a '.' before any exponent as MLIR's lexer wants; the double
    is exact in f32 when rounded first, so the parser's conversion is exact.
    Infinities and NaNs are printed as their bit patterns. A finite value
    that rounds to an infinity in `dtype` raises ValueError, as an integer
    that does not fit does: an infinity is kept only when it was written
    (float("inf")), never made by rounding. A value that rounds to 0 is
    ordinary rounding and is kept.
    """
    value = float(value)
    if dtype.elem is f32:
        rounded = round_f32(value)
        if math.isinf(rounded) and math.isfinite(value):
            raise ValueError(f"{value!r} overflows f32 (the largest finite "
                             f"f32 is {F32_MAX!r})")
        value = rounded
    if value != value or value in (float("inf"), float("-inf")):
        if dtype.elem is f32:
            (bits,) = struct.unpack("<I", struct.pack("<f", value))
            return f"0x{bits:08X}"
        (bits,) = struct.unpack("<Q", struct.pack("<d", value))
        return f"0x{bits:016X}"
    text = repr(value)
    mantissa, e, exponent = text.partition("e")
    if "." not in mantissa:
        mantissa += ".0"
    return mantissa + (("e" + exponent) if e else "")


def int_literal(value: int, dtype: DType, unsigned_hint: bool = True) -> str:
    """An integer constant of `dtype` in MLIR's signed spelling; raises
    ValueError when it does not fit: signed types (i32, i64, index) hold
    -2^(n-1) to 2^(n-1) - 1, unsigned ones (u32, u64) 0 to 2^n - 1 (the
    bits of 2^n - 1 are those of the signed -1); with `unsigned_hint` the
    message names the unsigned type that would hold it. A bool is `true`
    or `false`, which MLIR spells without a type (`arith.constant true`).
    """
    elem = dtype.elem
    if elem.kind == "bool":
        return "true" if value else "false"
    bits = elem.bits
    if elem.kind == "uint":
        lo, hi = 0, (1 << bits) - 1
    else:
        lo, hi = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    if not lo <= value <= hi:
        hint = ""
        if unsigned_hint and elem.kind == "sint" and 0 <= value < 1 << bits:
            hint = f"; sim.u{bits} holds 0 to 2^{bits} - 1"
        raise ValueError(f"{value} does not fit in {elem.name} ({lo} to "
                         f"{hi}){hint}")
    value &= (1 << bits) - 1
    if value >= 1 << (bits - 1):
        value -= 1 << bits
    return str(value)
