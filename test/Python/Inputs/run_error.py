"""sim.RunError is a sim.SimError (sim-run-error.test).

The runtime's errors (a bundle that does not open, a value it refuses, a
closed bundle or session, a run stopped by check_finite) come back as
sim.RunError, which `except sim.SimError` catches with TraceError and
CompileError; it stays a simrt.Error (a RuntimeError) with the runtime's
`status`, and simrt used directly raises it too once sim is loaded.
"""
import sys

import numpy as np

import sim
import simrt


def show(label, call):
    try:
        call()
    except sim.SimError as error:
        print(f"{label}: {type(error).__name__} SimError=True "
              f"simrt.Error={isinstance(error, simrt.Error)} "
              f"RuntimeError={isinstance(error, RuntimeError)} "
              f"status={getattr(error, 'status', None)} "
              f"line={error.line}: {error.message}")
    except Exception as error:  # not a SimError
        print(f"{label}: {type(error).__name__} SimError=False: {error}")
    else:
        print(f"{label}: no error")


print("issubclass:", issubclass(sim.RunError, sim.SimError),
      issubclass(sim.RunError, simrt.Error))
show("missing bundle", lambda: sim.Bundle(sys.argv[1]))

s = sim.Scene("errors", range=4, dt=1e-3)
k = s.param("k", 2, sim.i32)
A = s.buffer(sim.f32, name="A")(lambda i: 1.0)
s.component(writes=A, name="C")(lambda i: A[i] / sim.f32(k - 2))
s.observe(A)
bundle = sim.compile(s, strategies=["simple"])
session = bundle.session("simple", "cpu")
show("set k=2.5", lambda: session.set(k=2.5))
show("check_finite", lambda: bundle.session("simple", "cpu",
                                            check_finite=True).run(1))
raw = simrt.Bundle(bundle.path)
raw.close()
show("simrt closed bundle", lambda: raw.range)
# The TraceError and CompileError of the same base class.
show("trace", lambda: sim.i32(1))
