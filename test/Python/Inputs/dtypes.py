"""f32, f64 and vector buffers round trip between numpy and the runtime with
the right dtype and shape (sim-dtypes.test).

An f32 scene with f32 and vector<3xf32> buffers and an f64 scene with f64
and vector<2xf64> buffers: the arrays a session returns have the buffer's
scalar type and the shape [range] or [range, lanes]; arrays set before a
run are what the components start from (each doubles its buffer, exactly);
simrt.get() reads the type from the bundle (the format-letter trap).
Integer `//` and `%` of traced values give Python's results (totals).
"""
import numpy as np

import sim
import simrt
from sim import f32, f64, vector


def scene(name, precision, types):
    s = sim.Scene(name, range=8, dt=0.5, max_steps=1, precision=precision)
    buffers, components = [], []
    for k, dtype in enumerate(types):
        b = s.buffer(dtype, name=f"B{k}")(lambda i, k=k: k + 0.5)
        components.append(s.component(writes=b, name=f"Double{k}")(
            lambda i, b=b: b[i] * 2.0))
        buffers.append(b)
    s.schedule(*components)
    s.observe(*buffers)
    return s


cases = [
    ("single", f32, [f32, vector(3, f32)]),
    ("double", f64, [f64, vector(2, f64)]),
]
rng = np.random.default_rng(7)
for name, precision, types in cases:
    bundle = sim.compile(scene(name, precision, types), strategies=["simple"])
    print(f"{name}: dt {bundle.dt_type}")
    session = bundle.session("simple", "cpu", range=5)
    for buffer in bundle.observed:
        info = session.info(buffer)
        initial = session[buffer]
        print(f"  {buffer} {info.element_type}: {initial.dtype} "
              f"{initial.shape} init {initial.ravel()[0]}")
        values = rng.standard_normal(initial.shape)   # float64
        session[buffer] = values
        back = session[buffer]
        expected = values.astype(info.dtype)          # rounded like numpy
        print(f"    set/get equal: {back.dtype == info.dtype and np.array_equal(back, expected)}")
    before = {b: session[b] for b in bundle.observed}
    session.run(1)
    for buffer, start in before.items():
        after = session[buffer]
        print(f"  {buffer} after a step: doubled exactly "
              f"{np.array_equal(after, start * 2)}")
    # simrt, the standard-library binding, takes the type from the bundle.
    raw = simrt.Session(bundle._rt, "simple", "cpu")
    raw.set("range", "5")
    raw.run(0)
    first = bundle.observed[0]
    data = raw.get(first)
    print(f"  simrt.get({first}): typecode {data.typecode}, "
          f"{len(data)} values, first {data[0]}")
    wrong = "d" if data.typecode == "f" else "f"
    try:
        raw.get(first, wrong)
    except ValueError as error:
        print(f"  simrt.get({first}, {wrong!r}): {error}")
    raw.close()

# A scalar broadcast to the whole buffer, and a shape that does not fit.
session = sim.compile(scene("b", f32, [vector(3, f32)]),
                      strategies=["simple"]).session("simple", "cpu")
session["B0"] = [1.0, 2.0, 3.0]
print("broadcast:", session["B0"][5].tolist(), session["B0"].shape)
try:
    session["B0"] = np.zeros((3, 3))
except ValueError as error:
    print("shape error:", str(error).split("\n")[0])

# Integer semantics are Python's: `//` floors, `%` takes the divisor's sign.
ints = sim.Scene("ints", range=11, dt=1.0, precision=f64)
Z = ints.buffer(f64, name="Z")(lambda i: 0.0)
ints.component(writes=Z, name="Keep")(lambda i: Z[i])
ints.total(f64, name="Mod")(lambda i: f64((sim.i32(i) - 5) % 3))
ints.total(f64, name="NegMod")(lambda i: f64((sim.i32(i) - 5) % -3))
ints.total(f64, name="Floor")(lambda i: f64((sim.i64(i) - 5) // 2))
ints.total(f64, name="Trunc")(lambda i: f64(sim.div(sim.i64(i) - 5, 2)))
ints.observe(Z)
totals = sim.compile(ints, strategies=["simple"]).session(
    "simple", "cpu").totals()
python = {"Mod": sum((i - 5) % 3 for i in range(11)),
          "NegMod": sum((i - 5) % -3 for i in range(11)),
          "Floor": sum((i - 5) // 2 for i in range(11)),
          "Trunc": sum(int((i - 5) / 2) for i in range(11))}
print("integer division and modulo as in Python:",
      {k: (totals[k], float(v)) for k, v in python.items()
       if totals[k] != v} or "yes")
