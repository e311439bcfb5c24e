"""Every error of the tracer, each at the user's line (sim-trace-errors.test).

This file is also the FileCheck file: each case prints its TraceError, and
the CHECK line above the offending line matches the message and the line
number ([[@LINE+1]]).
"""
import math

import sim
from sim import f32, f64, i32

from trace_cases import case, run


def scene():
    global A  # the buffer the bodies of component() read
    s = sim.Scene("errors", range=16, dt=1e-3, max_steps=2)
    A = s.buffer(f32, name="A")(lambda i: 1.0)
    return s, A


def component(body, num_steps=None):
    s, A = scene()
    s.component(writes=A, name="C", num_steps=num_steps)(body)
    s.observe(A)
    s.mlir()


@case
def python_if():
    def body(i, n, dt):
        # CHECK: python_if: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: a Python `if`, `while`, `and`, `or`, `not`, `assert`, comparison chain or bool() on a traced value: {{.*}} use sim.select(condition, a, b)
        if A[i] > 0.0:
            return A[i]
        return -A[i]
    s, A = scene()
    s.component(writes=A)(body)
    s.mlir()


@case
def python_and():
    def body(i, n, dt):
        x = A[i]
        # CHECK: python_and: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: a Python `if`, `while`, `and`
        return x if x > 0.0 and x < 1.0 else x
    s, A = scene()
    s.component(writes=A)(body)
    s.mlir()


@case
def data_dependent_loop():
    def body(i, n, dt):
        # CHECK: data_dependent_loop: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: a data-dependent loop bound (upper bound computed from a buffer read): sim.loop bounds must not depend on the state
        return sim.loop(0, i32(A[i]), carry=A[i], body=lambda k, x: x * 0.5)
    s, A = scene()
    s.component(writes=A)(body)
    s.mlir()


@case
def builtin_range():
    def body(i, n, dt):
        x = A[i]
        # CHECK: builtin_range: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: a traced value used as a Python integer (range(), {{.*}} a data-dependent loop bound; use sim.loop(lo, hi, carry=...)
        for _ in range(n):
            x = x * 0.5
        return x
    s, A = scene()
    s.component(writes=A)(body)
    s.mlir()


@case
def range_of_param():
    s, A = scene()
    count = s.param("count", 3)

    def body(i, n, dt):
        x = A[i]
        # CHECK: range_of_param: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: sim.range unrolls while tracing and needs Python int bounds; for a bound that is a parameter use sim.loop
        for _ in sim.range(count):
            x = x * 0.5
        return x
    s.component(writes=A)(body)
    s.mlir()


@case
def range_of_read():
    def body(i, n, dt):
        # CHECK: range_of_read: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: a data-dependent loop bound (computed from a buffer read) in sim.range
        for k in sim.range(i32(A[i])):
            pass
        return A[i]
    s, A = scene()
    s.component(writes=A)(body)
    s.mlir()


@case
def list_side_effect():
    def body(i, n, dt):
        seen = []

        @sim.loop(0, 3, carry=A[i])
        def x(k, acc):
            seen.append(acc * 2.0)
            return acc * 0.5
        # CHECK: list_side_effect: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: a value traced inside a sim.loop body (line [[@LINE-2]]) is used outside it: a Python side effect (appending to a list, setting a variable or attribute outside the loop) cannot carry traced values out of a loop
        return x + seen[0]
    s, A = scene()
    s.component(writes=A)(body)
    s.mlir()


@case
def global_side_effect():
    stash = {}
    s, A = scene()

    @s.buffer(f32)
    def B(i):
        stash["x"] = f32(i) * 2.0
        return stash["x"]

    @s.component(writes=A)
    def C(i, n, dt):
        # CHECK: global_side_effect: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: a value traced in the init body of @B (line [[@LINE-5]]) is used in the evaluate body of @C: a Python side effect
        return A[i] + stash["x"]
    s.component(writes=B, name="D")(lambda i: B[i])
    s.mlir()


@case
def mixed_types():
    def body(i, n, dt):
        # CHECK: mixed_types: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: mixed types in `+`: f32 and f64; convert one operand, e.g. sim.f64(x)
        return A[i] + f64(1.5)
    component(body)


@case
def float_with_integer():
    def body(i, n, dt):
        # CHECK: float_with_integer: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the float constant 0.5 mixed with a index value in `+`
        return A[i + 0.5]
    component(body)


@case
def unsupported_operand():
    def body(i, n, dt):
        # CHECK: unsupported_operand: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: unsupported type str in `*`: traced bodies compute with sim values, Python ints, floats and bools
        return A[i] * "2"
    component(body)


@case
def f32_overflow_constant():
    def body(i, n, dt):
        # A float that is finite in Python but not in f32 is no infinity.
        # CHECK: f32_overflow_constant: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the constant 1e+39 is not a valid f32: 1e+39 overflows f32 (the largest finite f32 is 3.4028234663852886e+38)
        return A[i] * 1e39
    component(body)


@case
def f32_overflow_result():
    s, _ = scene()
    # CHECK: f32_overflow_result: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the constant 1e+300 is not a valid f32: 1e+300 overflows f32
    B = s.buffer(f32, name="B")(lambda i: 1e300)
    s.component(writes=B, name="D")(lambda i: B[i])
    s.mlir()


@case
def f32_overflow_conversion():
    def body(i, n, dt):
        # CHECK: f32_overflow_conversion: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the constant -3.5e+38 is not a valid f32: -3.5e+38 overflows f32
        return A[i] + f32(-3.5e38)
    component(body)


@case
def f32_overflow_param():
    s, _ = scene()
    # CHECK: f32_overflow_param: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the default 1e+40 of @big: 1e+40 overflows f32
    s.param("big", 1e40)


@case
def dt_underflow():
    # CHECK: dt_underflow: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: dt 1e-50 underflows f32 to 0 (the smallest positive f32 is 1.401298464324817e-45); use precision=sim.f64
    sim.Scene("tiny", range=4, dt=1e-50, precision=f32)


@case
def dt_subnormal():
    # CHECK: dt_subnormal: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: dt 1e-40 is subnormal in f32 (the smallest normal f32 is 1.1754943508222875e-38); use precision=sim.f64
    sim.Scene("tiny", range=4, dt=1e-40, precision=f32)


@case
def dt_subnormal_f64():
    # CHECK: dt_subnormal_f64: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: dt 1e-320 is subnormal in f64 (the smallest normal f64 is 2.2250738585072014e-308)
    sim.Scene("tiny", range=4, dt=1e-320, precision=f64)


@case
def dt_overflow():
    # CHECK: dt_overflow: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: dt 1e+39 overflows f32 (the largest finite f32 is 3.4028234663852886e+38)
    sim.Scene("huge", range=4, dt=1e39, precision=f32)


@case
def dt_not_positive():
    # CHECK: dt_not_positive: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: dt must be a positive, finite number, not -0.001
    sim.Scene("back", range=4, dt=-1e-3, precision=f64)


@case
def dt_not_a_number():
    # CHECK: dt_not_a_number: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: dt must be a positive number, not '1e-3'
    sim.Scene("text", range=4, dt="1e-3")


@case
def range_bool():
    # True is an int to Python, but no number of items.
    # CHECK: range_bool: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: range must be an int from 1 to 2^40, not True
    sim.Scene("flag", range=True, dt=1e-3)


@case
def range_too_large():
    # CHECK: range_too_large: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: range must be an int from 1 to 2^40, not 2199023255552
    sim.Scene("vast", range=2**41, dt=1e-3)


@case
def max_steps_bool():
    # CHECK: max_steps_bool: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: max_steps must be an int from 1 to 2^20, not True
    sim.Scene("flag", range=4, dt=1e-3, max_steps=True)


@case
def max_steps_too_large():
    # sim-translate would refuse it at the line of the temporary .mlir.
    # CHECK: max_steps_too_large: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: max_steps must be an int from 1 to 2^20, not 2147483648
    sim.Scene("long", range=4, dt=1e-3, max_steps=2**31)


@case
def unsupported_buffer_type():
    s, _ = scene()
    # CHECK: unsupported_buffer_type: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: unsupported buffer type sim.i32: a buffer holds f32, f64 or a vector of them
    s.buffer(i32, name="B")


@case
def python_type_as_buffer_type():
    s, _ = scene()
    # A Python type is callable, but it is no init body.
    # CHECK: python_type_as_buffer_type: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: unsupported buffer type <class 'float'>: a buffer holds f32, f64 or a vector of them
    s.buffer(float, name="B")


@case
def unsupported_param_type():
    s, _ = scene()
    # CHECK: unsupported_param_type: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: unsupported parameter type sim.vector(2, sim.f32): i32, i64, index, f32 or f64
    s.param("p", 1.0, sim.vector(2, f32))


@case
def python_math():
    def body(i, n, dt):
        # CHECK: python_math: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: float() of a traced value (or a function of Python's math module on it): {{.*}} use sim.f32(x) / sim.f64(x) and the functions of sim (sim.exp, sim.sqrt, ...)
        return math.exp(A[i])
    component(body)


@case
def int_of_value():
    def body(i, n, dt):
        # CHECK: int_of_value: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: int() of a traced value
        return A[int(i)]
    component(body)


@case
def result_type():
    def body(i, n, dt):
        # CHECK: result_type: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the evaluate body of @C returns f64 for @A : f32; convert with sim.f32(x)
        return f64(A[i])
    component(body)


@case
def result_count():
    def body(i, n, dt):
        # CHECK: result_count: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the evaluate body of @C returns 2 value(s); it must return 1 value(s): @A
        return A[i], A[i]
    s, A = scene()
    s.component(writes=[A], name="C")(body)
    B = s.buffer(f32, name="B")(lambda i: 0.0)
    s.component(writes=[B], name="D")(lambda i: B[i])
    # Two buffers, one value:
    s.mlir()


@case
def result_none():
    # CHECK: result_none: trace_errors.py:[[@LINE+2]]:{{[0-9]+}}: the num_steps body of @C returns None; it must return 1 value(s): the step count
    def steps(i, t):
        A[i] > 0.0
    component(lambda i: A[i], num_steps=steps)


@case
def integer_division():
    def steps(i, t):
        # CHECK: integer_division: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: `/` on integers (a Python true division): use `//` (floor), sim.div (truncating) or convert to a float first
        return i32(t / 2)
    component(lambda i: A[i], num_steps=steps)


@case
def float_modulo():
    def body(i, n, dt):
        # CHECK: float_modulo: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: `%` on floats: use sim.fmod(a, b)
        return A[i] % 2.0
    component(body)


@case
def lane_out_of_range():
    def body(i, n, dt):
        v = sim.vector(2, f32)(A[i], A[i])
        # CHECK: lane_out_of_range: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: lane 2 of a 2-lane vector
        return v[2]
    component(body)


@case
def read_outside_body():
    s, A = scene()
    # CHECK: read_outside_body: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: reading @A is only possible inside a traced body
    A[0]


@case
def assign_buffer():
    def body(i, n, dt):
        # CHECK: assign_buffer: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: assigning to @A[...]: a component changes its buffers by returning their new values from evaluate
        A[i] = 1.0
    component(body)


@case
def duplicate_name():
    s, A = scene()
    # CHECK: duplicate_name: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the name @A is declared twice in scene @errors
    s.buffer(f32, name="A")(lambda i: 0.0)


@case
def unknown_interp():
    s, A = scene()
    # CHECK: unknown_interp: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: unknown interpolation 'quadratic': linear, cubic, none or sim.hermite(V)
    s.buffer(f32, interp="quadratic")


@case
def loop_result_count():
    def body(i, n, dt):
        @sim.loop(0, 2, carry=(A[i], A[i]))
        def x(k, a, b):
            # CHECK: loop_result_count: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: a sim.loop body must return 2 value(s) like its carry, not 1 value
            return a
        return x[0]
    component(body)


@case
def loop_without_carry():
    def body(i, n, dt):
        # CHECK: loop_without_carry: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: sim.loop needs at least one carried value
        sim.loop(0, 2, carry=(), body=lambda k: ())
        return A[i]
    component(body)


@case
def select_condition():
    def body(i, n, dt):
        # CHECK: select_condition: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: sim.select needs a bool condition (a comparison), not f32
        return sim.select(A[i], A[i], 0.0)
    component(body)


@case
def hermite_derivative():
    s, A = scene()
    # CHECK: hermite_derivative: trace_errors.py:[[@LINE+1]]:{{[0-9]+}}: the derivative buffer @Nope of @X's Hermite interpolation is not a buffer of scene @errors
    X = s.buffer(f32, interp=sim.hermite("Nope"), name="X")(lambda i: 0.0)
    s.component(writes=[A, X], name="C")(lambda i: (A[i], X[i]))
    s.mlir()


run()
# CHECK-NOT: no error
