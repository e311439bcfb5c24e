"""sim.compile(ftz=True): the bundle flushes subnormals to zero, on the CPU
backend and in the reference executor alike (sim-ftz.test).

A value that halves every base step from 1e-36 is subnormal after 10 steps
(below 2^-126) under IEEE arithmetic and zero when subnormals are flushed.
"""
import sim
from sim import f32


def scene():
    s = sim.Scene("halving", range=4, dt=1e-2, max_steps=1, precision=f32)
    x = s.buffer(f32, name="X")(lambda i: 1e-36)
    s.component(writes=x, name="Halve")(lambda i: x[i] * 0.5)
    s.observe(x)
    return s


for ftz in (False, True):
    bundle = sim.compile(scene(), strategies=["simple"], ftz=ftz)
    for backend in ("cpu", "reference"):
        session = bundle.session("simple", backend)
        session.run(10)
        value = float(session["X"][0])
        print(f"ftz={ftz} flushes={bundle.flushes_subnormals} {backend}: "
              f"{value!r}")
