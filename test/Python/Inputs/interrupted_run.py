"""A run that an exception stops (sim-session-interrupted.test).

A progress callback that raises, or Ctrl-C, stops a run on the big-step
boundary it reached: metrics() then counts every base step the run did
(the C API's metrics of an interrupted run), and with output_every the
exception carries the Output of the output times reached (as sim-run
--output writes them when a signal stops it), with the frame of a chunk
that ended before the exception came. A RunError (check_finite) that ends
an output run carries them too. threads= with the reference backend, which
runs on one thread, is refused as sim-run refuses --threads there.
"""
import os
import signal
import sys
import threading

import numpy as np

import sim

# Decay with big steps of 4 base steps (max_steps 4).
s = sim.Scene("decay", range=16, dt=0.01, max_steps=4)


@s.buffer
def X(i):
    return sim.f32(1.0) + sim.f32(i)


@s.component(writes=X)
def Decay(i, n, dt):
    return X[i] - sim.f32(n) * dt * X[i]


@Decay.num_steps
def Decay(i, t):
    return sim.i32(4)


s.observe(X)
bundle = sim.compile(s, strategies=["simple", "hip"])


def stop_at(when, error=RuntimeError):
    """A progress callback that raises `error` once done reaches `when`."""
    def progress(done, total):
        if done >= when:
            raise error(f"stopped at {done}")
    return progress


def counted(session):
    """The steps metrics() counts, and whether its histogram has every big
    step."""
    m = session.metrics()
    big = m.get("big_steps", 0)
    histogram = big > 0 and sum(m["histogram"].values()) == big
    return (f"steps {m.get('steps')} begin {m.get('begin')} end "
            f"{m.get('end')} (T {session.time}); big steps counted: "
            f"{histogram}")


# -- Without outputs ----------------------------------------------------------
# check_finite=True synchronises after every big step: the stops are exact.

plain = bundle.session("hip", "cpu", check_finite=True)
try:
    plain.run(1000, progress=stop_at(42))
except RuntimeError as error:
    print("plain:", error, "has output:", hasattr(error, "output"))
print("  metrics:", counted(plain))
plain.run(8)
print("  the next run's own:", counted(plain))

# -- With outputs: stopped inside a chunk -------------------------------------

inside = bundle.session("hip", "cpu", check_finite=True)
try:
    inside.run(1000, output_every=10,
               progress=stop_at(54, KeyboardInterrupt))
except KeyboardInterrupt as error:
    out = error.output
    print("inside a chunk:", error, "output t", out.t.tolist())
print("  metrics:", counted(inside))
# The frames are those an uninterrupted run takes.
whole = bundle.session("hip", "cpu", check_finite=True).run(
    60, output_every=10)
print("  frames equal an uninterrupted run's:",
      np.array_equal(out.buffers["X"], whole.buffers["X"][:6]),
      "time", out.time.tolist()[-1] == whole.time.tolist()[5])

# -- Stopped at the end of a chunk: its frame is kept -------------------------

end = bundle.session("hip", "cpu", check_finite=True)
try:
    end.run(1000, output_every=10, progress=stop_at(40))
except RuntimeError as error:
    print("at a chunk's end:", error, "output t", error.output.t.tolist())
    print("  last frame is the state:",
          np.array_equal(error.output.buffers["X"][-1], end["X"]))
print("  metrics:", counted(end))

# -- Ctrl-C (SIGINT) during a long output run ---------------------------------
# A watchdog ends the test instead of letting a lost interrupt hang it.

signal.signal(signal.SIGINT, signal.default_int_handler)
watchdog = threading.Timer(120, lambda: (
    print("SIGINT lost: still running"), sys.stdout.flush(), os._exit(1)))
watchdog.start()
threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
long_run = bundle.session("hip", "cpu")
try:
    long_run.run(10**12, output_every=1000)
    print("SIGINT: the run ended on its own")
except KeyboardInterrupt as error:
    T = long_run.time
    t = error.output.t.tolist()
    print("SIGINT: output times every 1000 up to T:",
          t == list(range(0, T // 1000 * 1000 + 1, 1000)),
          "more than one:", len(t) > 1)
    m = long_run.metrics()
    print("  metrics count every step:", m["steps"] == T and m["end"] == T
          and m["begin"] == 0)
watchdog.cancel()

# -- A RunError ends an output run: the outputs reached come with it ----------

blow = sim.Scene("blow", range=4, dt=0.5)


@blow.buffer
def Y(i):
    return sim.f32(1.0)


@blow.component(writes=Y)
def Grow(i, n, dt):
    return Y[i] * 1e10


blow.observe(Y)
blown = sim.compile(blow, strategies=["simple"]).session(
    "simple", "cpu", check_finite=True)
try:
    blown.run(100, output_every=2)
except sim.RunError as error:
    print("RunError: output t", error.output.t.tolist(), "finite:",
          bool(np.isfinite(error.output.buffers["Y"]).all()))

# -- threads= on the reference backend ----------------------------------------


def show(call):
    try:
        print("  ok:", call())
    except (TypeError, ValueError, sim.RunError) as error:
        print(f"  {type(error).__name__}: {error}")


print("threads:")
show(lambda: bundle.session("simple", "reference", threads=2))
show(lambda: bundle.session("simple", "reference", threads=0).device)
switch = bundle.session("simple", "cpu", threads=2)
show(lambda: switch.run(1, backend="reference"))
print("  nothing ran, still on:", switch.time, switch.backend)
show(lambda: bundle.session("simple", "cpu", device=1))
