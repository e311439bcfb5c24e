"""A session over its bundle's life, its values and its runs
(sim-session.test).

A session keeps what it needs of its bundle (docs/Runtime.md), so it runs,
records outputs and reports after the bundle is closed. Values set from
numpy scalars are exact (an f64 parameter set to np.float32(0.1) holds the
float32's value). A run that ends with NaN or infinity in the state or the
totals warns with sim.NonFiniteWarning at the caller's line, as sim-run
warns and exits with status 3. Arguments of the wrong type or an unknown
strategy are refused before anything runs, saying what was expected.
"""
import os
import sys
import warnings

import numpy as np

import sim
from sim import f64

s = sim.Scene("grow", range=8, dt=0.5, precision=f64)
kappa = s.param("kappa", 1.0, f64)


@s.buffer
def X(i):
    return 1.0


@s.buffer
def Y(i):
    return 0.0


@s.component(writes=[X, Y])
def Grow(i, n, dt):
    # Item 3 grows by kappa a step: inf once kappa * X overflows, and Y, 0
    # times it, NaN.
    x = sim.select(i == 3, X[i] * kappa, X[i])
    return x, x * 0.0


@s.total
def Sum(i):
    return X[i]


s.observe(X, Y)
bundle = sim.compile(s, strategies=["simple", "hip"])

# Values from numpy scalars are the numbers they hold.
session = bundle.session("hip", "cpu", kappa=np.float32(0.1))
print("kappa from np.float32(0.1):", session.get("kappa"),
      float(session.get("kappa")) == float(np.float32(0.1)))
session.set(kappa=np.float64(0.1))
print("kappa from np.float64(0.1):", session.get("kappa"))
session.set(range=np.int64(6))
print("range from np.int64(6):", session.range)

# The bundle closed first: the sessions made before run on.
blowing = bundle.session("simple", "cpu")
reference = bundle.session("hip", "reference")
bundle.close()
session.run(3)
print("after close: T", session.time, "histogram",
      session.metrics()["histogram"])
out = session.run(2, output_every=1)
print("output:", out.meta["scene"], out.t.tolist(), "dt", session.dt)
print(repr(session))

# The kernels of the plan: their launches add up to the run's (over the
# chunks of an output run too), and the CPU times each launch.
m = session.metrics()
kernels = m["kernels"]
print("kernels: launches add up:",
      sum(k["launches"] for k in kernels.values()) == m["launches"],
      "timed:", all(k["seconds"] is not None and k["seconds"] >= 0
                    for k in kernels.values()),
      "seconds add up:",
      abs(sum(k["seconds"] for k in kernels.values()) - m["kernel_seconds"])
      <= 1e-9 * max(1.0, m["kernel_seconds"]),
      "launched:", sorted(k for k in kernels if kernels[k]["launches"]))
reference.run(2)
print("reference kernels:", reference.metrics()["kernels"])

# NaN and infinity at the end of a run warn, at the line of run().
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    blowing.set(kappa=1e200)
    blowing.run(1)
    print("finite run warns:", len(caught))
    blowing.run(1)
    line = sys._getframe().f_lineno - 1  # the line of run()
    for w in caught:
        print(f"{w.category.__name__} at {os.path.basename(w.filename)}"
              f"{' (the run line)' if w.lineno == line else ''}: {w.message}")
        print("  buffers", w.message.buffers, "totals", w.message.totals)
    caught.clear()
    out = blowing.run(1, output_every=1)
    print("output run warns:", len(caught), "is a RuntimeWarning:",
          issubclass(caught[0].category, RuntimeWarning))
    caught.clear()
    blowing.warn_nonfinite = False
    blowing.run(1)
    print("warn_nonfinite=False warns:", len(caught))

# Wrong arguments are refused before anything runs.
T = blowing.time
for call in (lambda: sim.compile(42),
             lambda: sim.compile(s, strategies=["hip", "nope"]),
             lambda: sim.compile(s, strategies=["hip", "hip"]),
             lambda: sim.compile(s, args="--sim-ftz"),
             lambda: sim.run_sim_opt(None),
             lambda: sim.Session(42),
             lambda: sim.find_tool(3),
             lambda: blowing.get(3),
             lambda: blowing.run(5, progress=3)):
    try:
        call()
        print("no error")
    except (TypeError, ValueError) as error:
        print(type(error).__name__ + ":", error)
print("nothing ran:", blowing.time == T)
