"""Integer constants and parameter defaults must fit their type
(sim-int-range.test).

Signed types (i32, i64, index) hold -2^(n-1) to 2^(n-1) - 1: 2**31 as an
i32 is a TraceError at the user's line, not the bits of -2^31. Unsigned
types (u32, u64) hold 0 to 2^n - 1, written in MLIR's signed spelling.
Parameters are i32, i64, index, f32 or f64 (a bundle holds no unsigned
one), and an integer parameter's default is an integer: 1.5 is refused,
not truncated to 1. This file is also the FileCheck file: the CHECK line
above each case's offending line matches its message and line.
"""
import re

import sim
from sim import f32, i32, i64, index, u32, u64

from trace_cases import case, run


def constants(body):
    """The constants of the evaluate body `body(i)` returns (as an f32)."""
    s = sim.Scene("ints", range=4, dt=1e-3)
    A = s.buffer(f32, name="A")(lambda i: 1.0)
    s.component(writes=A, name="C")(lambda i: A[i] + f32(body(i)))
    text = s.mlir()
    start = text.index("sim.component @C")
    return " | ".join(re.findall(r"arith\.constant (-?\d+ : \w+)",
                                 text[start:]))


def scene():
    return sim.Scene("ints", range=4, dt=1e-3)


def param(*args):
    p = scene().param(*args)
    return f"@{p.name} = {p.literal} : {p.dtype.mlir}"


# -- What fits ----------------------------------------------------------------

@case
def fits():
    # CHECK: fits: 2147483647 : i32 | -2147483648 : i32
    print("fits:", constants(lambda i: (i32(i) + (2**31 - 1)) * -2**31))
    # CHECK-NEXT: fits: 9223372036854775807 : i64 | -9223372036854775808 : i64
    print("fits:", constants(lambda i: (i64(i) + (2**63 - 1)) * -2**63))
    # The largest unsigned values, in MLIR's signed spelling.
    # CHECK-NEXT: fits: -1 : i32
    print("fits:", constants(lambda i: u32(i) + (2**32 - 1)))
    # CHECK-NEXT: fits: -1 : i64
    print("fits:", constants(lambda i: u64(i) ^ (2**64 - 1)))
    # CHECK-NEXT: fits: 9223372036854775807 : index
    print("fits:", constants(lambda i: i + (2**63 - 1)))
    # CHECK-NEXT: fits: @j = -9223372036854775808 : i64
    print("fits:", param("j", -2**63, i64))
    # An integral float is that integer.
    # CHECK-NEXT: fits: @a = 2 : i32
    print("fits:", param("a", 2.0, i32))


# -- Constants that do not fit ------------------------------------------------

@case
def i32_plus_2_31():
    # CHECK-NEXT: i32_plus_2_31: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the constant 2147483648 is not a valid i32: 2147483648 does not fit in i32 (-2147483648 to 2147483647); sim.u32 holds 0 to 2^32 - 1
    constants(lambda i: i32(i) + 2**31)


@case
def i32_unsigned_spelling():
    # CHECK-NEXT: i32_unsigned_spelling: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the constant 4294967295 is not a valid i32: 4294967295 does not fit in i32 (-2147483648 to 2147483647)
    constants(lambda i: i32(i) + (2**32 - 1))


@case
def i64_plus_2_63():
    # CHECK-NEXT: i64_plus_2_63: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the constant 9223372036854775808 is not a valid i64: 9223372036854775808 does not fit in i64 (-9223372036854775808 to 9223372036854775807); sim.u64 holds 0 to 2^64 - 1
    constants(lambda i: i64(i) + 2**63)


@case
def i32_conversion():
    # CHECK-NEXT: i32_conversion: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the constant 2147483648 is not a valid i32: 2147483648 does not fit in i32
    constants(lambda i: i32(2**31))


@case
def i32_below():
    # CHECK-NEXT: i32_below: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the constant -2147483649 is not a valid i32: -2147483649 does not fit in i32 (-2147483648 to 2147483647){{$}}
    constants(lambda i: i32(i) + (-2**31 - 1))


@case
def index_plus_2_63():
    # CHECK-NEXT: index_plus_2_63: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the constant 9223372036854775808 is not a valid index: 9223372036854775808 does not fit in index (-9223372036854775808 to 9223372036854775807){{$}}
    constants(lambda i: i + 2**63)


@case
def u32_negative():
    # CHECK-NEXT: u32_negative: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the constant -1 is not a valid u32: -1 does not fit in u32 (0 to 4294967295)
    constants(lambda i: u32(i) + -1)


@case
def u64_beyond():
    # CHECK-NEXT: u64_beyond: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the constant 18446744073709551616 is not a valid u64: 18446744073709551616 does not fit in u64 (0 to 18446744073709551615)
    constants(lambda i: u64(i) + 2**64)


# -- Parameter defaults -------------------------------------------------------

@case
def param_i64_2_63():
    # CHECK-NEXT: param_i64_2_63: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the default 9223372036854775808 of @j: 9223372036854775808 does not fit in i64 (-9223372036854775808 to 9223372036854775807){{$}}
    scene().param("j", 2**63, i64)


@case
def param_i32_2_31():
    # CHECK-NEXT: param_i32_2_31: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the default 2147483648 of @count: 2147483648 does not fit in i32 (-2147483648 to 2147483647){{$}}
    scene().param("count", 2**31)


@case
def param_fraction():
    # CHECK-NEXT: param_fraction: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the default 1.5 of @a: not an integer, as an i32 parameter needs (for a fraction declare it sim.f32 or sim.f64)
    scene().param("a", 1.5, i32)


@case
def param_nan():
    # CHECK-NEXT: param_nan: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the default nan of @a: not an integer, as an index parameter needs{{$}}
    scene().param("a", float("nan"), index)


@case
def param_u32():
    # CHECK-NEXT: param_u32: int_range.py:[[@LINE+1]]:{{[0-9]+}}: unsupported parameter type sim.u32: i32, i64, index, f32 or f64
    scene().param("l", 1.0, u32)


@case
def param_u64():
    # CHECK-NEXT: param_u64: int_range.py:[[@LINE+1]]:{{[0-9]+}}: unsupported parameter type sim.u64: i32, i64, index, f32 or f64
    scene().param("l", 1, u64)


@case
def param_text():
    # CHECK-NEXT: param_text: int_range.py:[[@LINE+1]]:{{[0-9]+}}: the default of @a must be an int or a float, not str
    scene().param("a", "3", i32)


run(quiet=(fits,))
# CHECK-NOT: no error
