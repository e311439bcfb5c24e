"""Outputs over time: run(steps, output_every=N) and the .npz layout
(sim-output.test).

Runs the Kepler example (python/examples/kepler.py: vector<2xf64> buffers,
exact solutions, two totals) on 16 items for 50 base steps with an output
every 20, and prints the keys, dtypes and shapes of the saved file, the
output times, and checks that the values are the session's.
"""
import os
import sys
import tempfile

import numpy as np

import sim

sys.path.insert(0, os.path.join(os.path.dirname(sim.__file__), "..",
                                "examples"))
from kepler import scene  # noqa: E402

bundle = sim.compile(scene, strategies=["simple", "hip"])
session = bundle.session("hip", "cpu", range=16)
calls = []
out = session.run(50, output_every=20, errors=True,
                  progress=lambda done, total: calls.append((done, total)))
print("t", out.t.tolist(), "time", out.time.tolist())
print("progress ends with", calls[-1], "never goes back:",
      all(a[0] <= b[0] for a, b in zip(calls, calls[1:])))
with tempfile.TemporaryDirectory() as tmp:
    path = out.save(os.path.join(tmp, "kepler.npz"))
    with np.load(path, allow_pickle=False) as data:
        for key in sorted(data.files):
            print(f"{key}: {data[key].dtype} {data[key].shape}")
        print("meta", data["meta/scene"].item(), data["meta/strategy"].item(),
              data["meta/backend"].item())
        final = {b: session[b] for b in bundle.observed}
        print("last output is the final state:",
              all(np.array_equal(data[f"buffer/{b}"][-1], v)
                  for b, v in final.items()))
        print("totals are the session's:",
              all(data[f"total/{n}"][-1] == v
                  for n, v in session.totals().items()))
        print("exact at t = 0 is the initial state:",
              data["error/X/max_abs"][0] == 0.0,
              "errors grow:", data["error/X/max_abs"][-1] > 0)
    again = sim.Output.load(path)
    print("load round trip:", again.meta == out.meta and
          all(np.array_equal(a, out.arrays()[k])
              for k, a in again.arrays().items()))

# Output times fall on big-step boundaries: under simple, a run in chunks
# gives the state of one run, bit for bit.
whole = bundle.session("simple", "cpu", range=16)
whole.run(50)
chunked = bundle.session("simple", "cpu", range=16)
chunked.run(50, output_every=7)
print("simple in chunks equals one run:",
      all(np.array_equal(whole[b], chunked[b]) for b in bundle.observed))

metrics = session.metrics()
print("metrics:", metrics["steps"], "steps,", sorted(metrics))

# A progress callback that raises stops the run and the error comes back.
stopped = bundle.session("hip", "cpu", range=16)


def stop(done, total):
    raise KeyboardInterrupt


try:
    stopped.run(5000, progress=stop)
except KeyboardInterrupt:
    print("stopped by the callback at T <", 5000, stopped.time < 5000)
stopped.run(10)
print("and runs on afterwards: T", stopped.time > 10)

# Ctrl-C (SIGINT) during a long run without a progress callback stops it
# at the next host synchronisation with KeyboardInterrupt, restores
# Python's handler, and the session runs on. A watchdog ends the test
# instead of letting a lost interrupt hang it.
import signal  # noqa: E402
import threading  # noqa: E402

# (lit may start the test with SIGINT ignored; an interactive Python has
# this handler.)
signal.signal(signal.SIGINT, signal.default_int_handler)
watchdog = threading.Timer(120, lambda: (print("SIGINT lost: still running"),
                                         sys.stdout.flush(), os._exit(1)))
watchdog.start()
threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
long_run = bundle.session("hip", "cpu", range=16)
try:
    long_run.run(10**12)
    print("SIGINT: the run ended on its own")
except KeyboardInterrupt:
    print("SIGINT stopped the run: T < 10^12", long_run.time < 10**12)
watchdog.cancel()
print("handler restored:",
      signal.getsignal(signal.SIGINT) is signal.default_int_handler)
before = long_run.time
long_run.run(10)
print("and runs on afterwards:", long_run.time == before + 10)

# Arguments of the wrong type are refused with what was expected.
for call in (lambda: bundle.session(3), lambda: bundle.session(
        "hip", "cpu", check_finite="no"), lambda: stopped.run(True)):
    try:
        call()
    except (TypeError, ValueError) as error:
        print(type(error).__name__ + ":", error)
stopped.run(np.int64(2))
print("numpy steps:", stopped.time)

# max_memory bounds what a session allocates, as sim-run --max-memory.
try:
    bundle.session("hip", "cpu", max_memory=1000, range=4096).run(1)
except sim.RunError as error:
    print("max_memory:", error)

# The strategy is the session's from its first run on.
fresh = bundle.session("hip", "cpu")
fresh.run(0, strategy="simple")
print("switched before running:", fresh.strategy)
fresh.run(1)
try:
    fresh.run(1, strategy="hip")
except ValueError as error:
    print("after running:", error)
