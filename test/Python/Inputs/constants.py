"""Python and numpy numbers in traced bodies (sim-constants.test).

A numpy scalar is the Python number it holds, on either side of an
operator: `np.float64(0.1) * x` traces to the text of `0.1 * x`, although
numpy's arithmetic runs first and hands the traced value to the ufunc
(`__array_ufunc__`). numpy arrays and numpy functions on traced values stay
errors. Float constants: an infinity is kept where one is written, the
largest f32 stays itself, and a value that rounds to 0 is ordinary
rounding (a finite value that rounds to an infinity is an error,
trace_errors.py).
"""
import re

import numpy as np

import sim
from sim import f32, i32, vector


def evaluate_text(body):
    """The evaluate body traced from `body(A, k, i)`, without locations."""
    s = sim.Scene("consts", range=8, dt=1e-3, precision=f32)
    k = s.param("k", 2.0)
    A = s.buffer(f32, name="A")(lambda i: 1.0)
    s.component(writes=A, name="C")(lambda i: body(A, k, i))
    s.observe(A)
    text = s.mlir()
    start = text.index("sim.component @C")
    return re.sub(r" loc\([^)]*\)", "", text[start:])


pairs = {
    "np.float64 * x": (lambda A, k, i: np.float64(0.1) * A[i],
                       lambda A, k, i: 0.1 * A[i]),
    "np.float32 - x": (lambda A, k, i: np.float32(0.1) - A[i],
                       lambda A, k, i: float(np.float32(0.1)) - A[i]),
    "np.float64 / x": (lambda A, k, i: np.float64(2.0) / A[i],
                       lambda A, k, i: 2.0 / A[i]),
    "np.float64 ** x": (lambda A, k, i: np.float64(2.0) ** A[i],
                        lambda A, k, i: 2.0 ** A[i]),
    "np.int32 // n": (lambda A, k, i: f32(np.int32(7) // i32(i)),
                      lambda A, k, i: f32(7 // i32(i))),
    "np.int64 % n": (lambda A, k, i: f32(np.int64(-7) % i32(i)),
                     lambda A, k, i: f32(-7 % i32(i))),
    "np.int32 << n": (lambda A, k, i: f32(np.int32(1) << i32(i)),
                      lambda A, k, i: f32(1 << i32(i))),
    "np.float64 < x": (lambda A, k, i: sim.select(np.float64(0.5) < A[i],
                                                  A[i], 0.0),
                       lambda A, k, i: sim.select(0.5 < A[i], A[i], 0.0)),
    "np.bool_ & c": (lambda A, k, i: sim.select(np.True_ & (A[i] > 0.0),
                                                A[i], 0.0),
                     lambda A, k, i: sim.select(True & (A[i] > 0.0),
                                                A[i], 0.0)),
    "np.float64 * param": (lambda A, k, i: np.float64(0.1) * k * A[i],
                           lambda A, k, i: 0.1 * k * A[i]),
    "np.float64 * vector": (
        lambda A, k, i: sim.sum(np.float64(2.0) * vector(2, f32)(A[i], k)),
        lambda A, k, i: sim.sum(2.0 * vector(2, f32)(A[i], k))),
    "x * np.float32": (lambda A, k, i: A[i] * np.float32(0.1),
                       lambda A, k, i: A[i] * float(np.float32(0.1))),
    "0-d array * x": (lambda A, k, i: np.array(0.5) * A[i],
                      lambda A, k, i: 0.5 * A[i]),
}
for name, (numpy_body, python_body) in pairs.items():
    same = evaluate_text(numpy_body) == evaluate_text(python_body)
    print(f"{name}: as the Python number: {same}")

errors = {
    "array * x": lambda A, k, i: np.array([1.0, 2.0]) * A[i],
    "np.sin(x)": lambda A, k, i: np.sin(A[i]),
    "np.sin(param)": lambda A, k, i: np.sin(k),
    "np.multiply(.., out=)": lambda A, k, i: np.multiply(
        np.float64(2.0), A[i], out=np.empty(())),
    "np.asarray(param)": lambda A, k, i: np.asarray(k),
}
for name, body in errors.items():
    try:
        evaluate_text(body)
        print(f"{name}: no error")
    except sim.TraceError as error:
        print(f"{name}: line {error.line}: {error.message}")

constants = {
    "inf": float("inf"), "-inf": float("-inf"),
    "largest f32": 3.4028234663852886e+38,
    "rounds to the largest f32": 3.4028235e+38,
    "underflows to 0": 1e-50,
}
for name, value in constants.items():
    text = evaluate_text(lambda A, k, i, value=value: A[i] * value)
    print(f"{name}:", re.search(r"arith\.constant (\S+) : f32", text)[1])
