"""Bool constants in traced bodies compile and run (sim-bool-constants.test).

`~c`, `c & True`, `c ^ np.bool_(True)` and `sim.boolean(True)` make i1
constants, which MLIR spells `arith.constant true` (no type: `true : i1`
is no attribute its parser reads), and a vector of bools `dense<[true,
false]> : vector<2xi1>`. The scene compiles and its results are those of
numpy.
"""
import re

import numpy as np

import sim
from sim import boolean, f32, vector

N = 6
s = sim.Scene("bools", range=N, dt=1e-3, max_steps=1)


@s.buffer(f32)
def X(i):
    return f32(i)


NAMES = ("NotGt", "AndTrue", "XorTrue", "Boolean", "Lanes")
results = [s.buffer(f32, name=name)(lambda i: -1.0) for name in NAMES]


@s.component(writes=[X] + results)
def Step(i):
    big = X[i] > 3.0
    lanes = sim.select(vector(2, boolean)(True, False),
                       vector(2, f32)(X[i], X[i]), vector(2, f32)(10.0, 20.0))
    return (X[i],
            sim.select(~big, X[i], 2.0),
            sim.select(big & True, 1.0, 0.0),
            sim.select(big ^ np.bool_(True), 1.0, 0.0),
            sim.select(sim.boolean(True), X[i], -2.0),
            sim.sum(lanes))


s.observe(X, *results)
text = s.mlir()
for line in text.splitlines():
    if re.search(r"arith\.constant (true|false|dense<\[?(true|false))", line):
        print(re.sub(r" loc\([^)]*\)", "", line.split("= ", 1)[1]))

bundle = sim.compile(s, strategies=["simple"])
x = np.arange(N, dtype=np.float32)
expected = {
    "NotGt": np.where(~(x > 3.0), x, 2.0),
    "AndTrue": np.where((x > 3.0) & True, 1.0, 0.0),
    "XorTrue": np.where((x > 3.0) ^ np.bool_(True), 1.0, 0.0),
    "Boolean": x,
    "Lanes": x + 20.0,
}
for backend in ("cpu", "reference"):
    session = bundle.session("simple", backend)
    session.run(1)
    for name, want in expected.items():
        got = session[name]
        same = np.array_equal(got, want.astype(np.float32))
        print(f"{backend} {name}: {got.tolist()} {'ok' if same else 'WRONG'}")
