"""How a body's parameters take its arguments (sim-body-args.test).

By name when every parameter is named among the body's arguments (i, t, n,
dt for evaluate; i, t for exact and num_steps), in any order; else by
position in that order, where a parameter named like an argument must stand
in its place. `def C(j, n, dt)` would give `n` the time t and `dt` the
step count n: a TraceError at the `def` line, never a silently wrong
binding. This file is also the FileCheck file of the errors: the CHECK
line above each `def` matches its message and line ([[@LINE+1]]).
"""

import sim
from sim import f32

from trace_cases import case, run


def scene():
    s = sim.Scene("args", range=4, dt=1e-3, max_steps=2)
    A = s.buffer(f32, name="A")(lambda i: 1.0)
    return s, A


def bound(**args):
    """What each parameter got: the argument's SSA name (%i, %t, %n, %dt)."""
    return " ".join(f"{k}={v.name}" for k, v in args.items())


# -- Bindings that trace ------------------------------------------------------

@case
def by_name_subset():
    s, A = scene()

    # CHECK: by_name_subset: dt=%dt i=%i
    # CHECK-NEXT: by_name_subset: traced
    @s.component(writes=A)
    def C(dt, i):
        print("by_name_subset:", bound(dt=dt, i=i))
        return A[i] * dt
    s.mlir()


@case
def by_position_unknown_names():
    s, A = scene()

    # CHECK-NEXT: by_position_unknown_names: k=%i time=%t steps=%n h=%dt
    # CHECK-NEXT: by_position_unknown_names: traced
    @s.component(writes=A)
    def C(k, time, steps, h):
        print("by_position_unknown_names:",
              bound(k=k, time=time, steps=steps, h=h))
        return A[k] * h
    s.mlir()


@case
def by_position_known_in_place():
    # i, n and dt where positional binding puts them: no ambiguity.
    s, A = scene()

    # CHECK-NEXT: by_position_known_in_place: i=%i time=%t n=%n dt=%dt
    # CHECK-NEXT: by_position_known_in_place: traced
    @s.component(writes=A)
    def C(i, time, n, dt):
        print("by_position_known_in_place:",
              bound(i=i, time=time, n=n, dt=dt))
        return A[i] * dt
    s.mlir()


@case
def num_steps_by_name():
    s, A = scene()

    @s.component(writes=A)
    def C(i):
        return A[i]

    # CHECK-NEXT: num_steps_by_name: t=%t i=%i
    # CHECK-NEXT: num_steps_by_name: traced
    @C.num_steps
    def C(t, i):
        print("num_steps_by_name:", bound(t=t, i=i))
        return sim.i32(2)
    s.mlir()


# -- Bindings that are refused ------------------------------------------------

@case
def renamed_first():
    s, A = scene()

    @s.component(writes=A)
    # CHECK-NEXT: renamed_first: body_args.py:[[@LINE+1]]:5: the evaluate body of @C has the parameters (j, n, dt): `n` would get the argument `t` by position. A body's parameters are either all named among i, t, n, dt (any of them, in any order; each gets its namesake) or take the arguments by position in the order (i, t, n, dt), a parameter named like an argument in that argument's place
    def C(j, n, dt):
        return A[j] * dt
    s.mlir()


@case
def known_out_of_place():
    s, A = scene()

    @s.component(writes=A)
    # CHECK-NEXT: known_out_of_place: body_args.py:[[@LINE+1]]:5: the evaluate body of @C has the parameters (i, n, dt, extra): `n` would get the argument `t` by position
    def C(i, n, dt, extra):
        return A[i] * dt
    s.mlir()


@case
def exact_swapped():
    s, A = scene()

    @A.exact
    # CHECK-NEXT: exact_swapped: body_args.py:[[@LINE+1]]:5: the exact body of @A has the parameters (time, i): `i` would get the argument `t` by position. A body's parameters are either all named among i, t (any of them
    def A(time, i):
        return sim.f32(time)
    s.component(writes=A, name="C")(lambda i: A[i])
    s.mlir()


@case
def default_not_given():
    # `dt` keeps its default under positional binding: refused too.
    s, A = scene()

    @s.component(writes=A)
    # CHECK-NEXT: default_not_given: body_args.py:[[@LINE+1]]:5: the evaluate body of @C has the parameters (j, dt): `dt` would not get the argument `dt`
    def C(j, dt=0.5):
        return A[j] * dt
    s.mlir()


@case
def lambda_renamed():
    s, A = scene()
    # CHECK-NEXT: lambda_renamed: body_args.py:[[@LINE+1]]:37: the evaluate body of @C has the parameters (j, n): `n` would get the argument `t` by position
    s.component(writes=A, name="C")(lambda j, n: A[j])
    s.mlir()


run(ok="traced")
