"""Buffer data that is no real numbers is refused (sim-buffer-values.test).

numpy converts what it can: np.asarray(None, float) is NaN, complex
numbers lose their imaginary part with only a ComplexWarning, text parses
("1.5" is 1.5). Session.__setitem__ (and init(**buffers)) refuses all of
these with a TypeError that names the buffer and what was given, and the
buffer keeps its state; numbers of any kind (bools, numpy scalars, Python
ints too large for int64, Decimal and Fraction) still set it.
"""
import decimal
import fractions
import warnings

import numpy as np

import sim
from sim import f32, f64, vector

s = sim.Scene("values", range=4, dt=0.5, max_steps=1, precision=f64)


@s.buffer
def X(i):
    return 1.0


@s.buffer(vector(2, f32))
def V(i):
    return vector(2, f32)(sim.f32(1.0), sim.f32(2.0))


@s.component(writes=[X, V])
def Keep(i):
    return X[i], V[i]


s.observe(X, V)
bundle = sim.compile(s, strategies=["simple"])
session = bundle.session("simple", "cpu")


class Thing:
    def __repr__(self):
        return "Thing()"


refused = [
    ("X", None),
    ("X", np.zeros(4, dtype=complex)),
    ("X", 1 + 2j),
    ("X", [1.0, 2j, 3.0, 4.0]),
    ("X", ["a", "b", "c", "d"]),
    ("X", "1.5"),
    ("X", b"1.5"),
    ("X", {"a": 1}),
    ("X", [1.0, None, 2.0, 3.0]),
    ("X", (1.0, 2.0, Thing(), 4.0)),
    ("X", np.array(["2020-01-01"] * 4, dtype="datetime64[D]")),
    ("V", np.array([[1.0, None]] * 4, dtype=object)),
    ("V", np.ones((4, 2), dtype=np.complex64)),
]
for name, values in refused:
    before = session[name]
    try:
        with warnings.catch_warnings():
            # numpy's ComplexWarning is no refusal: an exception here.
            warnings.simplefilter("error")
            session[name] = values
        print(f"{name} = {values!r}: accepted {session[name].tolist()}")
    except TypeError as error:
        kept = np.array_equal(session[name], before)
        print(f"TypeError: {error} (kept: {kept})")

try:
    session.init(X=None)
except TypeError as error:
    print(f"init: TypeError: {error}")

accepted = [
    ("X", [1, 2, 3, 4]),
    ("X", np.array([True, False, True, True])),
    ("X", [np.float32(0.5), 2, 3.0, np.int8(4)]),
    ("X", 2**70),
    ("X", [decimal.Decimal("1.5")] * 4),
    ("X", fractions.Fraction(1, 4)),
    ("X", np.array([1, 2, 3, 4], dtype=object)),
    ("V", [[1, 2], [3, 4], [5, 6], [7, 8]]),
]
for name, values in accepted:
    session[name] = values
    print(f"{name}: {session[name].tolist()}")

# A ragged list is a ValueError, as a shape that does not broadcast.
try:
    session["X"] = [[1, 2], [3]]
except ValueError as error:
    print(f"ValueError: {error}")
