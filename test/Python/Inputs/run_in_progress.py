"""A progress callback may read its session, not change it
(sim-session-in-run.test).

While Session.run() is in progress, a progress callback that closes the
session, sets its range, dt or parameters, runs it, starts it over
(init) or sets a buffer would have the runtime free or resize the state
under the running loop (a segmentation fault): each is refused with a
sim.RunError that says so, which stops the run as any exception of the
callback does; the session runs on afterwards. A callback that catches
the refusal lets the run go on to its end. Another thread is refused the
same way. Reading the state (buffers, totals, time, values, metrics) from
the callback works. The refusal ends with the run, also when the run
ends by an exception or KeyboardInterrupt.
"""
import threading

import numpy as np

import sim

# Decay with big steps of 4 base steps (max_steps 4).
s = sim.Scene("decay", range=16, dt=0.01, max_steps=4)
rate = s.param("rate", 1.0)


@s.buffer
def X(i):
    return sim.f32(1.0) + sim.f32(i)


@s.component(writes=X)
def Decay(i, n, dt):
    return X[i] - rate * sim.f32(n) * dt * X[i]


@Decay.num_steps
def Decay(i, t):
    return sim.i32(4)


@s.total
def Sum(i):
    return sim.f64(X[i])


s.observe(X)
bundle = sim.compile(s, strategies=["hip"])
STEPS = 400

changes = {
    "close": lambda session: session.close(),
    "set range": lambda session: session.set(range=64),
    "set rate": lambda session: session.set(rate=2.0),
    "run": lambda session: session.run(5),
    "init": lambda session: session.init(),
    "set buffer": lambda session: session.__setitem__("X", 0.0),
    "init buffer": lambda session: session.init(X=0.0),
}


def acting(session, change, catch=False):
    """A progress callback that tries `change` at its first call."""
    calls = []

    def progress(done, total):
        calls.append(done)
        if len(calls) == 1:
            try:
                change(session)
            except sim.RunError as error:
                if not catch:
                    raise
                print("  caught:", error)
    return progress


for what, change in changes.items():
    session = bundle.session("hip", "cpu")
    try:
        session.run(STEPS, progress=acting(session, change))
        print(f"{what}: ran to {session.time}")
    except sim.RunError as error:
        print(f"{what}: {type(error).__name__}: {error}")
    stopped = 0 < session.time < STEPS
    # The session is as the stop left it and runs on.
    range_, T = session.range, session.time
    session.run(8)
    print(f"  stopped inside the run: {stopped} range {range_}; runs on: "
          f"{session.time == T + 8}")
    session.close()

# The refusal caught: the run goes on to its end.
session = bundle.session("hip", "cpu")
session.run(STEPS, progress=acting(session, changes["close"], catch=True))
print("caught, ran to", session.time)

# With output_every the refusal carries the output times reached.
session = bundle.session("hip", "cpu")
try:
    session.run(STEPS, output_every=100,
                progress=lambda done, total: done >= 150 and session.close())
except sim.RunError as error:
    print("output run:", type(error).__name__, "output t",
          error.output.t.tolist())
session.close()

# Another thread, while the run is in progress.
session = bundle.session("hip", "cpu")
seen = []


def other_thread(done, total):
    if not seen:
        def close():
            try:
                session.close()
            except sim.RunError as error:
                seen.append(str(error))
        thread = threading.Thread(target=close)
        thread.start()
        thread.join()


session.run(STEPS, progress=other_thread)
print("other thread:", seen[0])
print("  ran to", session.time)

# Reading from the callback works.
reads = []


def read(done, total):
    x = session["X"]
    reads.append((session.time, x.dtype.name, x.shape,
                  bool(np.isfinite(x).all()), sorted(session.totals()),
                  session.get("range"), session.range, session.dt > 0,
                  session.buffers()["X"].shape,
                  session.metrics()["strategy"]))


session.run(STEPS, progress=read)
print("reads:", len(reads) > 1, reads[0][1:])
print("  times grow:", all(a[0] < b[0] for a, b in zip(reads, reads[1:])))

# The refusal ends with the run, also one that an exception or Ctrl-C
# (KeyboardInterrupt) ended.
for error in (ValueError("stop"), KeyboardInterrupt()):
    def stop(done, total, error=error):
        raise error
    try:
        session.run(STEPS, progress=stop)
    except (ValueError, KeyboardInterrupt) as raised:
        print("stopped by", type(raised).__name__, end="")
    session.set(range=32)
    session["X"] = np.arange(32)
    session.init(X=1.0)
    session.run(8)
    print("; then set, init, run:", session.range, session.time)
session.close()
print("closed:", session)
