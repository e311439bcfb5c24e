"""A session's arguments and its state between runs
(sim-session-args.test).

A buffer the compiler pruned (no output needs it) has no state in the
session: runs do not read it for the NaN check, and reading or setting it
says so. Integers beyond the runtime's C types are refused, naming the
argument, instead of wrapping (2**64 + 10 steps ran 10). A parameter named
like a session option is set through params={...}, and a keyword that could
be either is refused; buffers and parameters named `self` or `params` work.
Setting the current range keeps the state (and the buffers set before a
switch of strategy); another range warns that it drops them. progress hears
of the end of a chunk once. Bad scene, compile and dt values are refused
before anything runs, saying why.
"""
import warnings

import numpy as np

import sim
import simrt


def show(call):
    """Prints the error `call` raises (or its result)."""
    try:
        print("  ok:", call())
    except (TypeError, ValueError, KeyError, sim.RunError) as error:
        message = error.args[0] if isinstance(error, KeyError) else error
        print(f"  {type(error).__name__}: {message}")


# -- A buffer the plan pruned ------------------------------------------------

s = sim.Scene("pruned", range=8, dt=0.5)


@s.buffer
def X(i):
    return sim.f32(i)


@s.buffer
def Unused(i):
    return sim.f32(-1.0)


@s.component(writes=X)
def C(i, n, dt):
    return X[i] + 1.0


@s.component(writes=Unused)
def D(i, n, dt):
    return Unused[i] * 2.0 + X[i]


s.observe(X)
bundle = sim.compile(s, strategies=["simple", "hip"])
session = bundle.session("hip", "cpu")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    session.run(3)
    out = session.run(2, output_every=1)
print("pruned: ran to", session.time, "warnings", len(caught), "buffers",
      list(bundle.buffers), "plan", session.plan_buffers)
show(lambda: session["Unused"])
show(lambda: session.__setitem__("Unused", 0.0))
# Buffers set before the first run go into the session of the strategy
# run() switches to.
switched = bundle.session("hip", "cpu")
switched["X"] = 5.0
switched.run(1, strategy="simple")
print("switched to", switched.strategy, "from X = 5:", switched["X"][:2])

# -- Integers beyond the C types -----------------------------------------------

print("integers:")
show(lambda: session.run(2**64 + 10))
show(lambda: session.run(2**63))
show(lambda: bundle.session("simple", "cpu", group_size=2**64 + 32))
show(lambda: bundle.session("simple", "cpu", max_memory=2**64 + 5))
show(lambda: bundle.session("simple", "cpu", threads=2**32 + 1))
raw = simrt.Session(bundle._rt, "simple", "cpu")
show(lambda: raw.run(2**64 + 10))
print("nothing ran:", session.time == 5 and raw.time == 0)
raw.close()

# -- Compile and scene values ---------------------------------------------------

print("compile:")
show(lambda: sim.compile(s, strategies=["simple"], group_size=1.7))
show(lambda: sim.compile(s, strategies=["simple"], group_size=True))
show(lambda: sim.compile(s, strategies=["simple"], group_size=48))
numpy_ints = sim.Scene("numpy", range=np.int64(8), dt=0.5,
                       max_steps=np.int32(2))
lim = numpy_ints.param("lim", np.int64(3))
print("numpy ints:", numpy_ints.range, type(numpy_ints.range).__name__,
      numpy_ints.max_steps, lim.dtype)

# -- Parameters named like options, and buffers named self ----------------------

k = sim.Scene("kw", range=8, dt=0.5)
threads = k.param("threads", 2)
params = k.param("params", 1)


@k.buffer(name="self")
def Self(i):
    return sim.f32(i)


@k.component(writes=Self)
def Add(i, n, dt):
    return Self[i] + sim.f32(threads) + sim.f32(params)


k.observe(Self)
kw = sim.compile(k, strategies=["simple"])
print("names like options:")
show(lambda: kw.session("simple", "cpu", threads=5))
show(lambda: kw.session("simple", "cpu", params=7))
show(lambda: kw.session("simple", "cpu", params={"range": 8}, range=8))
by_params = kw.session("simple", "cpu", params={"threads": 5, "params": 7})
print("  params= sets them:", by_params.get("threads"),
      by_params.get("params"))
option = kw.session("simple", "cpu", params={}, threads=1)
print("  with params= given, threads= is the option:",
      option.get("threads"), "1 thread" in option.device)
option.set(params={"params": 9})
print("  set(params=...):", option.get("params"))
option.init(self=np.full(8, 4.0))
print("  init(self=...):", option["self"][:2])

# -- The state across set(range=...) ----------------------------------------------

heat = bundle.session("hip", "cpu")
heat["X"] = 7.0
heat.set(range=8)  # the current range: the state stays
heat.run(2, strategy="simple")
reference = bundle.session("simple", "cpu")
reference["X"] = 7.0
reference.run(2)
print("set(range=current) keeps the buffers set:",
      np.array_equal(heat["X"], reference["X"]))
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    heat.set(range=16)
    heat.set(range=32)  # nothing set since: no warning
    for w in caught:
        print(f"  {w.category.__name__}: {w.message}")
print("  state from init:", heat["X"][:2], "T", heat.time)

# -- progress, dt, a closed bundle -------------------------------------------------

calls = []
bundle.session("hip", "cpu").run(
    10, output_every=4, progress=lambda done, total: calls.append(done))
print("progress:", calls, "each once:", len(calls) == len(set(calls)))
show(lambda: bundle.session("hip", "cpu", dt=1e-50))
show(lambda: bundle.session("hip", "cpu", dt=1e-45).dt)
before = bundle.session("hip", "cpu")
bundle.close()
show(lambda: before.run(1, strategy="simple"))
before.run(1)
print("runs on with its own strategy:", before.strategy, before.time)
