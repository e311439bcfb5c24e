"""Names in the keys of the .npz layout (sim-output-names.test).

`output_names.py make DIR` compiles a scene whose buffer and total names
sim-run escapes (`x$y`, `tot$al`) or keeps apart (`X.reference` after `X`:
its dump file would be X's) into DIR/names.simb and saves a Python run as
DIR/python.npz; `output_names.py compare DIR` compares that file with
sim-run's DIR/run.npz of the same run: the same keys, and both load to the
scene's names.
"""
import os
import sys

import numpy as np

import sim
from sim import f64

mode, folder = sys.argv[1:]
if mode == "make":
    s = sim.Scene("names", range=16, dt=0.01, max_steps=2, precision=f64)

    @s.buffer(name="x$y", boundary="wrap")
    def XY(i):
        return sim.sin(f64(i))

    @XY.exact
    def XY(i, t):
        return sim.sin(f64(i)) * sim.exp(-t)

    @s.buffer(name="X")
    def X(i):
        return f64(i)

    @s.buffer(name="X.reference")
    def XR(i):
        return f64(1.0)

    @s.component(writes=[XY, X, XR])
    def C(i, n, dt):
        return XY[i] * (1.0 - f64(n) * dt), X[i] + f64(n), XR[i] + f64(n)

    @s.total(name="tot$al")
    def T(i):
        return XY[i]

    s.observe(XY, X, XR)
    bundle = sim.compile(s, strategies=["simple"],
                         output=os.path.join(folder, "names.simb"))
    out = bundle.session("simple", "cpu").run(4, output_every=2, errors=True)
    out.save(os.path.join(folder, "python.npz"))
else:
    paths = [os.path.join(folder, f) for f in ("python.npz", "run.npz")]
    keys = []
    for path in paths:
        with np.load(path) as data:
            keys.append(sorted(data.files))
    print("keys:", " ".join(keys[0]))
    print("sim-run's keys are the same:", keys[0] == keys[1])
    for path in paths:
        out = sim.Output.load(path)
        print(os.path.basename(path), "loads buffers", sorted(out.buffers),
              "totals", sorted(out.totals), "errors", sorted(out.errors),
              "exact", sorted(out.exact))
    python, run = (sim.Output.load(path) for path in paths)
    print("the same values:",
          all(np.array_equal(python.buffers[n], run.buffers[n])
              for n in run.buffers))
