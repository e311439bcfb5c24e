"""The operators python/README.md lists for each element type are those the
tracer takes (sim-readme-operators.test): each operator of each group on
each type it names traces; the float `//` and `%` the README says are
refused are refused, naming what to use instead.
"""
import os
import re

import sim

README = os.path.join(os.path.dirname(os.path.abspath(sim.__file__)),
                      os.pardir, "README.md")
with open(README) as f:
    text = f.read()
# The bullet "- operators ...", up to the next bullet.
bullet = re.search(r"^- operators (.*?)(?=^- )", text, re.S | re.M).group(0)
bullet = " ".join(bullet.split())
# Each "`OPERATORS`, ... on `TYPE`, `TYPE` and ..." up to a `;`.
groups = []
for part in bullet.split(";"):
    match = re.search(r"`([^`a-z]+)`[^;]*? on ((?:`\w+`(?:,? (?:and )?)?)+)",
                      part)
    if match:
        groups.append((match.group(1).split(),
                       re.findall(r"`(\w+)`", match.group(2))))


def trace(type_name, op):
    """Traces `a op b` (`~a`) on values of type `type_name`."""
    dtype = getattr(sim, type_name)
    s = sim.Scene("ops", range=8, dt=0.5)

    @s.buffer
    def X(i):
        return sim.f32(0.0)

    @s.component(writes=X)
    def C(i, n, dt):
        operands = {"a": dtype(sim.i32(i)) if type_name != "index" else i,
                    "b": dtype(n) if type_name != "index" else i}
        c = eval(f"{op}a" if op == "~" else f"a {op} b", {}, operands)
        if type_name == "index":
            c = sim.i32(c)
        return X[i] + sim.f32(c)

    s.schedule(C)
    s.observe(X)
    s.mlir()


types_seen = set()
for ops, types in groups:
    for type_name in types:
        types_seen.add(type_name)
        refused = []
        for op in ops:
            try:
                trace(type_name, op)
            except sim.TraceError as error:
                refused.append(f"{op} ({error.message})")
        print(f"{' '.join(ops)} on {type_name}:",
              "all trace" if not refused else "refused: " + "; ".join(refused))
print("types:", " ".join(sorted(types_seen)))

# The README says `//` and `%` on floats are refused, and names the
# replacements.
print("README refuses float // and %:",
      "`//` and `%` on floats are a `TraceError`" in bullet)
for type_name in ("f32", "f64"):
    for op in ("//", "%"):
        try:
            trace(type_name, op)
            print(f"{op} on {type_name}: traced")
        except sim.TraceError as error:
            print(f"{op} on {type_name}: {error.message}")

# `~` on an unsigned value flips all its bits: an xori by the all-ones
# constant, which MLIR spells -1.
s = sim.Scene("invert", range=8, dt=0.5)


@s.buffer
def Y(i):
    return sim.f32(0.0)


@s.component(writes=Y)
def Flip(i, n, dt):
    return Y[i] + sim.f32(~sim.u32(n))


s.schedule(Flip)
s.observe(Y)
text = s.mlir()
print("~ on u32:", "arith.xori by -1 : i32 (all bits)"
      if re.search(r"(%\w+) = arith.constant -1 : i32.*\n(.*\n)*.*"
                   r"arith.xori %n, \1 : i32", text) else text)
