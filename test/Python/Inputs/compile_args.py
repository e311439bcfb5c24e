"""sim.compile's ftz and strategies are checked before the tool runs
(sim-compile-args.test).

`ftz` is a bool: a str such as "no" or "false" is true to Python and would
build a flush-to-zero bundle, so anything but True or False (Python's or
numpy's) is a TypeError. `strategies=None` (the default) compiles every
strategy; an empty list names none and is a ValueError, not all of them.
"""
import numpy as np

import sim


def show(label, call):
    try:
        call()
    except (TypeError, ValueError) as error:
        print(f"{label}: {type(error).__name__}: {error}")
    else:
        print(f"{label}: compiled")


s = sim.Scene("args", range=4, dt=1e-3)
A = s.buffer(sim.f32, name="A")(lambda i: 1.0)
s.component(writes=A, name="C")(lambda i: A[i] * 0.5)
s.observe(A)

show('ftz="no"', lambda: sim.compile(s, strategies="simple", ftz="no"))
show('ftz="false"', lambda: sim.compile(s, strategies="simple", ftz="false"))
show("ftz=1", lambda: sim.compile(s, strategies="simple", ftz=1))
show("ftz=None", lambda: sim.compile(s, strategies="simple", ftz=None))
show("strategies=[]", lambda: sim.compile(s, strategies=[]))
show("strategies=()", lambda: sim.compile(s, strategies=()))
show('strategies=""', lambda: sim.compile(s, strategies=""))
# A bool passes the check: the scene's type is what is refused next.
show("ftz=np.True_", lambda: sim.compile(42, strategies="simple",
                                         ftz=np.True_))
show("ftz=False", lambda: sim.compile(42, ftz=False))
for label, ftz in (("False", False), ("True", True),
                   ("np.True_", np.True_)):
    bundle = sim.compile(s, strategies=["simple"], ftz=ftz)
    print(f"ftz={label}: {bundle.strategies} flushes "
          f"{bundle.flushes_subnormals}")
    bundle.close()
