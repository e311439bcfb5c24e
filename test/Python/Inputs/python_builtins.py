"""Python's builtins on traced values (sim-python-builtins.test).

`pow(x, y, m)`, `round(x)`, `math.floor(x)`, `math.ceil(x)`,
`math.trunc(x)`, `divmod(x, y)`, `max(x, y)` and `min(x, y)` want a Python
value that a traced value does not have: each is a sim.TraceError at the
user's line that names the sim function to use, never a TypeError about
the package's internals. This file is also the FileCheck file: the CHECK
line above each offending line matches its message and line.
"""
import math

import sim
from sim import f32

from trace_cases import case, run


def component(body):
    s = sim.Scene("builtins", range=4, dt=1e-3)
    k = s.param("k", 2.0)
    A = s.buffer(f32, name="A")(lambda i: 1.0)
    s.component(writes=A, name="C")(lambda i: body(A[i], k))
    s.mlir()


@case
def pow_modulus():
    # CHECK: pow_modulus: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: pow(a, b, modulus) on a traced value: sim has no modular power; use a ** b (sim.pow(a, b) on floats) and then % (integers) or sim.fmod (floats)
    component(lambda x, k: pow(x, 2.0, 3))


@case
def pow_modulus_param():
    # CHECK-NEXT: pow_modulus_param: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: pow(a, b, modulus) on a traced value
    component(lambda x, k: pow(k, 2.0, 3))


@case
def round_value():
    # CHECK-NEXT: round_value: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: round() of a traced value: its value is not known while tracing; use sim.round(x) (halves away from zero) or sim.roundeven(x) (halves to even, as Python's round)
    component(lambda x, k: round(x))


@case
def round_digits():
    # CHECK-NEXT: round_digits: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: round() of a traced value: {{.*}} use sim.round(x)
    component(lambda x, k: round(x, 2))


@case
def round_param():
    # CHECK-NEXT: round_param: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: round() of a traced value: {{.*}} use sim.round(x)
    component(lambda x, k: x * round(k))


@case
def math_floor():
    # CHECK-NEXT: math_floor: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: math.floor() of a traced value: its value is not known while tracing; use sim.floor(x) (a float; sim.i32(sim.floor(x)) for an integer)
    component(lambda x, k: math.floor(x))


@case
def math_ceil():
    # CHECK-NEXT: math_ceil: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: math.ceil() of a traced value: {{.*}} use sim.ceil(x)
    component(lambda x, k: math.ceil(x))


@case
def math_trunc():
    # CHECK-NEXT: math_trunc: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: math.trunc() of a traced value: {{.*}} use sim.trunc(x) (a float), or sim.i32(x), which truncates
    component(lambda x, k: math.trunc(x))


@case
def divmod_value():
    # CHECK-NEXT: divmod_value: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: divmod() of a traced value: use a // b and a % b on integers, sim.floor(a / b) and sim.fmod(a, b) on floats
    component(lambda x, k: divmod(x, 2.0)[0])


@case
def builtin_max():
    # CHECK-NEXT: builtin_max: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: Python's max() or min() on a traced value: they compare with bool(), whose value is not known while tracing; use sim.max(a, b, ...) or sim.min(a, b, ...)
    component(lambda x, k: max(x, 1.0))


@case
def builtin_min_param():
    # CHECK-NEXT: builtin_min_param: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: Python's max() or min() on a traced value: {{.*}} use sim.max(a, b, ...) or sim.min(a, b, ...)
    component(lambda x, k: x * min(k, 1.0))


@case
def sim_max_and_if():
    # sim.max is no builtin: an `if` on the same line keeps its message.
    # CHECK-NEXT: sim_max_and_if: python_builtins.py:[[@LINE+1]]:{{[0-9]+}}: a Python `if`, `while`, `and`, `or`, `not`, `assert`, comparison chain or bool() on a traced value
    component(lambda x, k: x if sim.max(x, 1.0) > 2.0 else k)


@case
def sim_functions():
    # What the messages name traces.
    component(lambda x, k: sim.max(sim.round(x), sim.roundeven(k)) ** 2.0 +
              sim.fmod(sim.pow(x, 2.0), 3.0) + sim.floor(x / 2.0) +
              sim.trunc(x))
    print("sim_functions: traced")
    # CHECK-NEXT: sim_functions: traced


run(quiet=(sim_functions,), report_others=True)
# CHECK-NOT: no error
