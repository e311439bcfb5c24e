"""Running bundles from Python with numpy: bundles, sessions, outputs.

    bundle = sim.compile(scene)                  # or sim.Bundle("scene.simb")
    session = bundle.session(strategy="hip", backend="cpu")
    session.set(range=4096, k=0.5)               # range, dt, parameters
    session["T"] = np.linspace(0, 1, 4096)       # the initial state
    out = session.run(1000, output_every=100, errors=True)
    out.save("rod.npz")                          # t, time, buffer/T, total/...
    T = session["T"]                             # float32 [4096], a copy
    print(session.metrics()["big_steps"])

Buffers come back as numpy arrays of the buffer's scalar type (float32 or
float64, from the bundle's buffer info), shaped [range] or [range, lanes].
The runtime is libsim_runtime.so through python/simrt.py (ctypes); a failed
call raises `sim.RunError` with the runtime's message: a `sim.SimError`
(as TraceError and CompileError are) and a `simrt.Error` (a RuntimeError).
"""

from __future__ import annotations

import ctypes
import numbers
import os
import signal
import sys
import threading
import warnings
from collections.abc import Mapping
from typing import Callable, NamedTuple

import numpy as np

from .errors import NonFiniteWarning, SimError
from .output import Output, error_norms
from .types import F32_TINY, round_f32

try:
    import simrt
except ImportError:  # the sim package without python/ on sys.path
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(
        __file__))))
    import simrt

__all__ = ["Bundle", "Session", "BufferInfo", "RunError"]


class RunError(simrt.Error, SimError):
    """A failed runtime call (a bundle that does not open, a value the
    runtime refuses, a run stopped by check_finite): the runtime's message,
    `status` its sim_status code. A `sim.SimError` without a source
    location, and a `simrt.Error`: simrt raises this class once the sim
    package is loaded."""

    def __init__(self, status, message):
        self.status = status
        SimError.__init__(self, message)


simrt.set_error_class(RunError)


class BufferInfo(NamedTuple):
    """What the bundle says about a buffer."""

    name: str
    element_type: str      # "f32", "vector<2xf64>", ...
    dtype: np.dtype        # float32 or float64
    lanes: int | None      # None for a scalar element
    interp: str
    boundary: str
    observed: bool
    exact: bool

    def shape(self, range_: int) -> tuple:
        """The shape of the buffer's host array at `range_` items."""
        return (range_,) if self.lanes is None else (range_, self.lanes)


class Bundle:
    """A scene bundle (`.simb`): what it holds, and sessions that run it."""

    def __init__(self, path, library: str | None = None):
        self.path = os.fspath(path)
        self._rt = simrt.Bundle(self.path, library)
        self.compile_seconds: float | None = None
        self.mlir: str | None = None
        self.messages: list = []
        self.command: list | None = None
        self._tmp = None
        self.buffers: dict[str, BufferInfo] = {}
        for b in self._rt.buffers():
            lanes = b["lanes"] if b["element_type"].startswith("vector") \
                else None
            self.buffers[b["name"]] = BufferInfo(
                b["name"], b["element_type"],
                np.dtype(np.float32 if b["scalar_bytes"] == 4 else np.float64),
                lanes, b["interp"], b["boundary"], b["observed"], b["exact"])
        self.params = {p["name"]: p for p in self._rt.params()}

    @property
    def name(self) -> str:
        return self._rt.name

    @property
    def range(self) -> int:
        return self._rt.range

    @property
    def dt(self) -> float:
        return self._rt.dt

    @property
    def dt_type(self) -> str:
        return self._rt.dt_type

    @property
    def max_steps(self) -> int:
        return self._rt.max_steps

    @property
    def flushes_subnormals(self) -> bool:
        """Whether the bundle runs with subnormals flushed to zero on every
        backend (compiled with `ftz=True`); False: IEEE."""
        return self._rt.flushes_subnormals

    @property
    def strategies(self) -> list[str]:
        """The strategies the bundle holds plans for."""
        return [s for s in simrt.strategies() if self._rt.has_strategy(s)]

    @property
    def observed(self) -> list[str]:
        return [b.name for b in self.buffers.values() if b.observed]

    def session(self, /, strategy: str = "hip", backend: str = "auto", *,
                params: dict | None = None, **options) -> "Session":
        """A new Session of this bundle (see Session for the options, the
        values and `params`)."""
        return Session(self, strategy, backend, params=params, **options)

    def close(self):
        self._rt.close()
        if self._tmp is not None:
            self._tmp.cleanup()
            self._tmp = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:  # at interpreter exit the library may be gone
            pass

    def __repr__(self):
        if not self._rt._raw:
            return f"<sim.Bundle (closed) {self.path}>"
        return (f"<sim.Bundle {self.name} ({', '.join(self.strategies)}) "
                f"{self.path}>")


class Session:
    """A bundle's state, run with one strategy on one backend.

    Options, as keyword arguments: `group_size` (0: the plan's), `threads`
    (CPU backend threads, 0: all; refused on the reference backend, which
    runs on one), `check_finite`, `max_memory` (bytes the session
    may allocate, 0: the runtime's default share, as sim-run
    --max-memory) and `warn_nonfinite`. Scene values (`range`, `dt`,
    parameters) as `params={name: value}`, which always means values, or
    as the other keyword arguments. A keyword that names an option and a
    parameter of the scene too is refused as ambiguous unless `params` is
    given (then it is the option, and the parameter goes in `params`);
    parameters named `strategy`, `backend` or `params` are set through
    `params` only. The strategy and backend can still be changed by `run`
    until the first run, while the bundle is open (the session keeps what
    its own strategy needs of the bundle, no more); after the first run a
    session's state belongs to them.

    With `warn_nonfinite` (the default; also the attribute of that name)
    every run ends by reading the state and the totals back and warns with
    `sim.NonFiniteWarning` when they hold NaN or infinity, as sim-run
    warns (and exits with status 3); False skips that copy of the state.
    """

    def __init__(self, bundle: Bundle, /, strategy: str = "hip",
                 backend: str = "auto", *, params: dict | None = None,
                 **keywords):
        # The thread whose run() is in progress, or None: a progress
        # callback (or another thread) must not change the session under
        # the running loop (see _check_not_running).
        self._running: int | None = None
        if not isinstance(bundle, Bundle):
            raise TypeError(f"a Session runs a sim.Bundle (sim.compile(scene) "
                            f"or sim.Bundle(path)), not {bundle!r}")
        options = dict(_OPTIONS)
        values = {}
        for name, value in keywords.items():
            if name not in _OPTIONS:
                values[name] = value
                continue
            # A keyword is an option unless the scene has a parameter of
            # that name and nothing says which is meant: taking it for
            # either would quietly ignore the other.
            if params is None and name in bundle.params:
                raise TypeError(
                    f"{name}= is ambiguous: scene {bundle.name} has a "
                    f"parameter {name!r}, and {name} is a Session option; "
                    f"pass the parameter as params={{{name!r}: ...}} (with "
                    f"params= given, {name}= is the option)")
            options[name] = value
        values = _merge_values(params, values, bundle)
        for what, value in (("strategy", strategy), ("backend", backend)):
            if not isinstance(value, str):
                raise TypeError(f"{what} must be a name (str), not "
                                f"{value!r}")
        for what, ctype in (("group_size", "int64"), ("threads", "int32"),
                            ("max_memory", "int64")):
            _check_count(what, options[what], 0, ctype,
                         " (0: the default)")
        for what in ("check_finite", "warn_nonfinite"):
            if not isinstance(options[what], (bool, np.bool_)):
                raise TypeError(f"{what} must be True or False, not "
                                f"{options[what]!r}")
        self.bundle = bundle
        # What runs need of the bundle, read now: the bundle may be closed
        # before the session runs (docs/Runtime.md), and a run must not fail
        # after it has advanced the state.
        self._scene = bundle.name
        self._max_steps = bundle.max_steps
        self._dt_type = bundle.dt_type
        self.warn_nonfinite = bool(options["warn_nonfinite"])
        self.strategy = strategy
        self._backend_request = backend
        self._options = dict(group_size=int(options["group_size"]),
                             cpu_threads=int(options["threads"]),
                             check_finite=bool(options["check_finite"]),
                             max_memory=int(options["max_memory"]))
        self._values: dict[str, str] = {}
        # Buffers set before the first run, which a switch of strategy in
        # run() puts into the new session, and every buffer set since the
        # state last started over (a new range warns that it drops them).
        self._initial: dict[str, np.ndarray] = {}
        self._set_buffers: set[str] = set()
        self._ran = False
        self._metrics = None
        self._rt, self._plan = self._create(strategy, backend)
        if values:
            self.set(params=values)

    # -- Setup ------------------------------------------------------------------

    def _create(self, strategy, backend):
        """A runtime session of `strategy` on `backend` with the values and
        the buffers set so far, and the names of the buffers its plan
        holds."""
        # The reference executor runs on one thread: a thread count for it
        # is a mistake, not a setting to ignore (sim-run refuses --threads
        # with --backend reference too).
        threads = self._options["cpu_threads"]
        if backend == "reference" and threads != 0:
            raise ValueError(
                f"threads={threads} sets the CPU backend's threads; the "
                f"reference executor runs on one (a session on backend "
                f"'reference' takes no threads)")
        rt = simrt.Session(self.bundle._rt, strategy, backend, **self._options)
        try:
            for name, value in self._values.items():
                rt.set(name, value)
            plan = _plan_buffers(rt, self.bundle)
            for name, data in self._initial.items():
                # A buffer this plan pruned is one no output needs.
                if name in plan:
                    _put(rt, name, data)
        except BaseException:
            rt.close()
            raise
        return rt, plan

    def set(self, /, params: dict | None = None, **values):
        """Sets `range`, `dt` or parameters (like `sim-run --set`), from
        `params={name: value}` (which always means values: a parameter
        named `params` goes there) or keyword arguments.

        A range other than the current one discards the state: the session
        starts over from the init bodies at time 0, and buffers set before
        are lost (a warning names them; set them after the range). Setting
        the current range keeps the state."""
        self._check_not_running("Session.set()")
        values = _merge_values(params, values, self.bundle)
        for name, value in values.items():
            text = _value_literal(value)
            if name == "dt":
                self._check_dt(text)
            before = self.range if name == "range" else None
            self._rt.set(name, text)
            self._values[name] = text
            if name == "range" and self.range != before:
                if self._set_buffers:
                    names = ", ".join(sorted(self._set_buffers))
                    warnings.warn(
                        f"range {before} -> {self.range} discards the "
                        f"session's state, with the buffers set before "
                        f"({names}): the state starts over from the init "
                        f"bodies at time 0 (set the buffers after the "
                        f"range)", stacklevel=2)
                self._initial.clear()
                self._set_buffers.clear()

    def _check_not_running(self, what: str, verb: str = "called"):
        """Refuses (RunError) a call that changes the session while its
        run() is in progress, from a progress callback or another thread:
        the runtime would free or resize the state under the running loop.
        Reading the state (buffers, totals, time) stays allowed."""
        running = getattr(self, "_running", None)  # __init__ may have failed
        if running is None:
            return
        if running == threading.get_ident():
            where = ("from a progress callback): the callback may read the "
                     "session, not change it (to stop the run, raise an "
                     "exception in it)")
        else:
            where = "from another thread): wait for the run to end"
        raise RunError(
            simrt._INVALID_ARGUMENT,
            f"{what} cannot be {verb} while Session.run() is in progress "
            f"({where}")

    def _check_dt(self, text: str):
        """Refuses a dt that rounds to 0 in an f32 bundle, saying what to
        do: the runtime says only that it underflows."""
        try:
            value = float(text)
        except ValueError:  # the runtime's message for what it cannot read
            return
        if self._dt_type == "f32" and value > 0 and round_f32(value) == 0:
            raise RunError(
                simrt._INVALID_ARGUMENT,
                f"dt: {text} underflows f32 to 0 (the smallest positive f32 "
                f"is {F32_TINY!r}); compile the scene with "
                f"precision=sim.f64 for a smaller dt")

    def get(self, name: str) -> str:
        """The current value of `range`, `dt` or a parameter, as text."""
        if not isinstance(name, str):
            raise TypeError(f"get takes the name (str) of range, dt or a "
                            f"parameter, not {name!r}")
        buffer = ctypes.create_string_buffer(256)
        simrt._check(simrt.load_library().sim_session_get(
            self._rt._handle, name.encode(), buffer, len(buffer)))
        return buffer.value.decode()

    def init(self, /, **buffers):
        """Starts over from the initial state (time 0), then replaces the
        state of the buffers given (arrays, see `__setitem__`; any buffer
        name, `self` too)."""
        self._check_not_running("Session.init()")
        self._rt.init()
        self._initial.clear()
        self._set_buffers.clear()
        for name, data in buffers.items():
            self[name] = data

    @property
    def range(self) -> int:
        return simrt.load_library().sim_session_range(self._rt._handle)

    @property
    def dt(self) -> float:
        """The current dt, exactly (an f32 dt as the double of its f32)."""
        value = float(self.get("dt"))
        if self._dt_type == "f32":
            value = float(np.float32(value))
        return value

    @property
    def time(self) -> int:
        """The current base step T."""
        return self._rt.time

    @property
    def device(self) -> str:
        return self._rt.device

    @property
    def backend(self) -> str:
        """The backend that runs the session (cpu, cuda or reference)."""
        lib = simrt.load_library()
        return lib.sim_backend_name(
            lib.sim_session_backend(self._rt._handle)).decode()

    @property
    def group_size(self) -> int:
        return simrt.load_library().sim_session_group_size(self._rt._handle)

    # -- State ---------------------------------------------------------------------

    def info(self, name: str) -> BufferInfo:
        try:
            return self.bundle.buffers[name]
        except KeyError:
            raise KeyError(f"scene {self._scene} has no buffer "
                           f"{name!r}") from None

    @property
    def plan_buffers(self) -> list[str]:
        """The buffers whose state the session holds: the scene's, less
        those its strategy's plan pruned (no observed buffer or total
        needs them; `--sim-prune`)."""
        return list(self._plan)

    def _state_info(self, name: str) -> BufferInfo:
        """The info of a buffer whose state the session holds."""
        info = self.info(name)
        if name not in self._plan:
            raise KeyError(
                f"buffer {name!r} of scene {self._scene} is not in the plan "
                f"of strategy {self.strategy!r}: no observed buffer or total "
                f"needs it, so the compiler pruned it and the session holds "
                f"no state of it (it holds "
                f"{', '.join(self._plan) or 'none'})")
        return info

    def __getitem__(self, name: str) -> np.ndarray:
        """The buffer's current state: a new array of its scalar type,
        [range] or [range, lanes]."""
        info = self._state_info(name)
        data = np.empty(info.shape(self.range), dtype=info.dtype)
        simrt._check(simrt.load_library().sim_session_get_buffer(
            self._rt._handle, name.encode(), data.ctypes.data, data.nbytes))
        return data

    def __setitem__(self, name: str, values):
        """Replaces the buffer's current state with `values` (anything numpy
        broadcasts to [range] or [range, lanes]; converted to the buffer's
        scalar type; anything that is no real numbers, such as None or
        complex numbers, is a TypeError)."""
        self._check_not_running(f"Setting buffer {name!r} (session[{name!r}] "
                                f"= ...)", "done")
        info = self._state_info(name)
        shape = info.shape(self.range)
        array = _real_array(name, info, values)
        try:
            data = np.ascontiguousarray(np.broadcast_to(array, shape))
        except ValueError:
            raise ValueError(f"buffer {name} ({info.element_type}) holds an "
                             f"array of shape {shape}; an array of shape "
                             f"{array.shape} does not broadcast to it") from None
        _put(self._rt, name, data)
        self._set_buffers.add(name)
        if not self._ran and self.time == 0:
            self._initial[name] = data

    def buffers(self, names=None) -> dict[str, np.ndarray]:
        """The state of the observed buffers (or of `names`: a list, or
        one name)."""
        if isinstance(names, str):
            names = [names]
        return {n: self[n] for n in (names or self.bundle.observed)}

    def exact(self, name: str) -> np.ndarray:
        """The scene's exact solution of the buffer at the current time."""
        info = self._state_info(name)
        lib = simrt.load_library()
        if not lib.sim_session_has_exact(self._rt._handle, name.encode()):
            raise KeyError(f"buffer {name} has no exact solution")
        data = np.empty(info.shape(self.range), dtype=info.dtype)
        simrt._check(lib.sim_session_exact(self._rt._handle, name.encode(),
                                           data.ctypes.data, data.nbytes))
        return data

    def totals(self) -> dict[str, float]:
        """The scene's totals at the current time."""
        return self._rt.totals()

    # -- Running -------------------------------------------------------------------

    def _switch(self, strategy, backend):
        strategy = strategy or self.strategy
        backend = backend or self._backend_request
        if strategy == self.strategy and backend == self._backend_request:
            return
        if self._ran or self.time != 0:
            raise ValueError(
                f"this session ran with {self.strategy} on "
                f"{self._backend_request}; its state belongs to them (make "
                f"a new session for {strategy} on {backend})")
        # The runtime session keeps what its own plan needs of the bundle,
        # not the other strategies' plans: a new one is made from the
        # bundle.
        if not self.bundle._rt._raw:
            raise RunError(
                simrt._INVALID_ARGUMENT,
                f"the bundle is closed: this session runs on with "
                f"{self.strategy} on {self._backend_request}, but a switch "
                f"to {strategy} on {backend} makes a new session of the "
                f"bundle (switch before bundle.close(), or make the session "
                f"with bundle.session({strategy!r}, {backend!r}))")
        old = self._rt
        self._rt, self._plan = self._create(strategy, backend)
        old.close()
        self.strategy = strategy
        self._backend_request = backend

    def run(self, steps: int, *, strategy: str | None = None,
            backend: str | None = None,
            progress: Callable[[int, int], None] | None = None,
            output_every: int | None = None, errors: bool = False,
            record: list[str] | None = None) -> Output | None:
        """Runs `steps` base steps from the current state; the run ends
        exactly at T + steps.

        `progress(done, total)` is called after each host synchronisation
        with the base steps done; an exception it raises stops the run at
        the next one and is raised here. With `output_every=N` the run goes
        in chunks of N base steps and returns an `Output` with the observed
        buffers (or `record`, a list or one name) and the totals at T,
        T+N, ..., and the end; with `errors=True` also the exact solutions
        of the buffers that have one and the errors against them. Without
        it, returns None. A run that ends with NaN or infinity in the state
        or the totals warns (sim.NonFiniteWarning; see `warn_nonfinite`).

        A run that `progress` or Ctrl-C (KeyboardInterrupt) stops keeps
        the state of the big-step boundary it reached, and `metrics()`
        counts every base step it ran. With `output_every`, the exception
        that ends a run (a RunError too) carries the `Output` of the output
        times it reached as its `output` attribute (sim-run writes those
        when a signal stops it).

        The progress callback may read the session (buffers, totals, time)
        but not change it: run, set, init, close and setting a buffer are
        refused with a RunError while the run is in progress.
        """
        self._check_not_running("Session.run()")
        self._running = threading.get_ident()
        try:
            return self._run(steps, strategy, backend, progress,
                             output_every, errors, record)
        finally:
            # Also when the run ends by an exception or Ctrl-C.
            self._running = None

    def _run(self, steps, strategy, backend, progress, output_every, errors,
             record):
        """run(), while `_running` says it is in progress."""
        # numpy's integers too; True is not a number of steps.
        steps = _check_count("steps", steps, 0, "int64")
        # Checked before the run: a callback that cannot be called would
        # stop it at its first host synchronisation, after steps ran.
        if progress is not None and not callable(progress):
            raise TypeError(f"progress must be a function (done, total), "
                            f"not {progress!r}")
        if isinstance(record, str):
            record = [record]
        self._switch(strategy, backend)
        if output_every is None:
            self._metrics = None
            self._chunk(steps, progress, 0, steps)
            self._ran = True
            self._check_nonfinite()
            return None
        if not _is_count(output_every, 1):
            raise ValueError(f"output_every must be an int >= 1, not "
                             f"{output_every!r}")
        names = list(record or self.bundle.observed)
        exact = [n for n in names if errors and self.info(n).exact]
        frames = []

        def snapshot():
            frame = {"t": self.time, "buffers": self.buffers(names),
                     "totals": self.totals(), "exact": {}}
            for n in exact:
                frame["exact"][n] = self.exact(n)
            frames.append(frame)

        snapshot()
        self._metrics = None
        # The output time the run is heading for, to record it when an
        # exception comes after the run reached it.
        reached = self.time
        try:
            if steps == 0:
                # No chunk to run, but the metrics of a run of 0 steps.
                self._chunk(0, progress, 0, 0)
                self._ran = True
            done = 0
            while done < steps:
                chunk = min(output_every, steps - done)
                reached = self.time + chunk
                self._chunk(chunk, progress, done, steps)
                self._ran = True
                done += chunk
                snapshot()
        except BaseException as error:
            # The output times reached are not lost (sim-run writes them
            # when a signal stops it): they go with the exception. A chunk
            # that ended before it (its last progress call raised, Ctrl-C
            # came between chunks) gives its frame too; a run stopped
            # inside a chunk, or inside a big step, is at no output time.
            if self.time == reached and frames[-1]["t"] != reached:
                snapshot()
            error.output = self._output(frames, names, exact)
            raise
        output = self._output(frames, names, exact)
        self._check_nonfinite(frames[-1])
        return output

    def _chunk(self, steps, progress, offset, total):
        lib = simrt.load_library()
        failure = []
        handle = self._rt._handle
        # Ctrl-C: Python runs its signal handlers only between bytecodes,
        # never inside the C run. In the main thread with Python's default
        # SIGINT handler, a handler of ours asks the session to stop, and a
        # progress callback (a no-op one when none was given) gives Python
        # control at every host synchronisation, where that handler runs;
        # the run stops at the next one and KeyboardInterrupt is raised here.
        watch = (threading.current_thread() is threading.main_thread()
                 and signal.getsignal(signal.SIGINT)
                 is signal.default_int_handler)
        previous = None
        if watch:
            def on_sigint(signum, frame):
                failure.append(KeyboardInterrupt())
                lib.sim_session_interrupt(handle)
            previous = signal.signal(signal.SIGINT, on_sigint)
        callback = None
        # The steps done that progress was last told of: the runtime may
        # report the end of the chunk itself, which is said once.
        told = [None]
        if progress is not None or watch:
            def call(user, done, _):
                if progress is None:
                    return
                try:
                    told[0] = done
                    progress(offset + done, total)
                except BaseException as error:  # also KeyboardInterrupt
                    failure.append(error)
                    lib.sim_session_interrupt(handle)
            callback = simrt.ProgressFunction(call)
            lib.sim_session_set_progress(handle, callback, None)
        try:
            self._rt.run(steps)
        except simrt.Error as error:
            if failure:
                lib.sim_session_resume(handle)
                # Stopped on the big-step boundary it reached: the runtime's
                # metrics are those of the steps done.
                if error.status == _INTERRUPTED:
                    self._accumulate()
                raise failure[0] from None
            raise
        else:
            # The steps ran: count them before raising what stopped them too
            # late (the run ended first) and before the callback, which may
            # raise, while Ctrl-C cannot cut the count short.
            self._accumulate()
        finally:
            if callback is not None:
                lib.sim_session_set_progress(handle,
                                             simrt.ProgressFunction(), None)
            if watch:
                signal.signal(signal.SIGINT, previous)
        if failure:
            lib.sim_session_resume(handle)
            raise failure[0]
        if progress is not None and told[0] != steps:
            progress(offset + steps, total)

    def _accumulate(self):
        m = self._rt.metrics()
        m["evaluations"] = self._rt.evaluations()
        m["histogram"] = self._rt.histogram(self._max_steps)
        m["kernels"] = self._rt.kernels()
        if self._metrics is None:
            self._metrics = m
            return
        total = self._metrics
        for key in ("steps", "wall_seconds", "kernel_seconds", "launches",
                    "graph_launches", "host_syncs", "big_steps"):
            total[key] += m[key]
        total["end"] = m["end"]
        for key in ("evaluations", "histogram"):
            for name, count in m[key].items():
                total[key][name] = total[key].get(name, 0) + count
        for name, kernel in m["kernels"].items():
            kept = total["kernels"].setdefault(
                name, {"launches": 0, "seconds": 0.0})
            kept["launches"] += kernel["launches"]
            kept["seconds"] = (None if kernel["seconds"] is None
                               or kept["seconds"] is None
                               else kept["seconds"] + kernel["seconds"])

    def _check_nonfinite(self, frame: dict | None = None):
        """Warns (sim.NonFiniteWarning) when the state or the totals hold
        NaN or infinity at the end of a run, naming what sim-run's warnings
        name (docs/Runtime.md, "NaN and infinity after the run"). `frame`:
        the buffers and totals an output run read at the end already."""
        if not self.warn_nonfinite:
            return
        known = frame["buffers"] if frame else {}
        totals = frame["totals"] if frame else self.totals()
        counts, parts = {}, []
        # The buffers of this strategy's plan only: the others (pruned, as
        # no output needs them) have no state, as in sim-run's check.
        for name in self._plan:
            info = self.bundle.buffers[name]
            data = known[name] if name in known else self[name]
            bad = ~np.isfinite(data)
            count = int(np.count_nonzero(bad))
            if not count:
                continue
            counts[name] = count
            first = int(np.argmax(bad.ravel()))
            lanes = info.lanes or 1
            where = f"item {first // lanes}" + (
                f", lane {first % lanes}" if lanes > 1 else "")
            plural = "value" if count == 1 else "values"
            parts.append(f"buffer '{name}' holds {count} NaN or infinite "
                         f"{plural} (the first: "
                         f"{_value_text(data.ravel()[first])} at {where})")
        bad_totals = [n for n, v in totals.items() if not np.isfinite(v)]
        parts += [f"total '{n}' is not finite ({_value_text(totals[n])})"
                  for n in bad_totals]
        if parts:
            # stacklevel: the user's call of run() (through _run).
            warnings.warn(NonFiniteWarning(
                f"the run ended at T = {self.time} with NaN or infinite "
                f"values: {'; '.join(parts)} (check_finite=True stops at "
                f"the first and says where it appeared)", counts, bad_totals),
                stacklevel=4)

    def metrics(self) -> dict:
        """What the last run measured (all chunks of an output run
        together): steps, begin, end, wall_seconds, kernel_seconds,
        launches, graph_launches, host_syncs, big_steps, evaluations (per
        component), histogram (big steps per size), kernels (per kernel of
        the plan: launches, and seconds where the backend times every
        launch, the CPU, else None; empty on the reference executor), and
        the strategy, backend, device and group size."""
        base = dict(self._metrics or {})
        base.update(strategy=self.strategy, backend=self.backend,
                    device=self.device, group_size=self.group_size)
        return base

    def _output(self, frames, names, exact) -> Output:
        t = np.array([f["t"] for f in frames], dtype=np.int64)
        buffers = {n: np.stack([f["buffers"][n] for f in frames])
                   for n in names}
        total_names = list(frames[0]["totals"])
        totals = {n: np.array([f["totals"][n] for f in frames],
                              dtype=np.float64) for n in total_names}
        exact_arrays = {n: np.stack([f["exact"][n] for f in frames])
                        for n in exact}
        errors = {}
        for n in exact:
            norms = [error_norms(f["buffers"][n], f["exact"][n])
                     for f in frames]
            errors[n] = {"max_abs": np.array([a for a, _ in norms]),
                         "rms_rel": np.array([r for _, r in norms])}
        meta = {"scene": self._scene, "strategy": self.strategy,
                "backend": self.backend}
        return Output(t, t.astype(np.float64) * self.dt, buffers, totals,
                      errors, exact_arrays, meta)

    def close(self):
        self._check_not_running("Session.close()")
        self._rt.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:  # at interpreter exit the library may be gone
            pass

    def __repr__(self):
        if not self._rt._raw:
            return f"<sim.Session {self.strategy} (closed)>"
        return (f"<sim.Session {self._scene} {self.strategy} on "
                f"{self.backend}, T={self.time}>")


# sim_status's SIM_ERROR_INTERRUPTED (sim_runtime.h): a run that
# sim_session_interrupt stopped on a big-step boundary.
_INTERRUPTED = 9

# The options of a Session and their defaults (see Session).
_OPTIONS = {"group_size": 0, "threads": 0, "check_finite": False,
            "max_memory": 0, "warn_nonfinite": True}

# The largest value of the C types of the runtime's integer arguments:
# ctypes would wrap a larger Python int silently (2**64 + 10 steps ran 10).
_C_MAX = {"int32": 2**31 - 1, "int64": 2**63 - 1}


def _is_count(value, least: int) -> bool:
    """Whether `value` is an integer (Python's or numpy's, not a bool) of
    at least `least`."""
    return (not isinstance(value, bool) and
            isinstance(value, numbers.Integral) and value >= least)


def _check_count(what: str, value, least: int, ctype: str,
                 note: str = "") -> int:
    """`value` as an int, or a ValueError naming `what` unless it is an
    integer from `least` to the largest of the C type `ctype`."""
    if not _is_count(value, least):
        raise ValueError(f"{what} must be an int >= {least}{note}, not "
                         f"{value!r}")
    if value > _C_MAX[ctype]:
        exponent = 31 if ctype == "int32" else 63
        raise ValueError(f"{what} must be at most 2^{exponent} - 1 (the "
                         f"runtime's {ctype}), not {value}")
    return int(value)


def _merge_values(params, values: dict, bundle: Bundle) -> dict:
    """The values of `params` (a dict by name) and of the keyword
    arguments `values` together; a name in both is refused."""
    if params is None:
        return dict(values)
    if not isinstance(params, Mapping) or \
            not all(isinstance(name, str) for name in params):
        hint = (f" (for the parameter named params: "
                f"params={{'params': {params!r}}})"
                if "params" in bundle.params else "")
        raise TypeError(f"params is a dict of values by name (range, dt, "
                        f"parameters), not {params!r}{hint}")
    twice = [name for name in params if name in values]
    if twice:
        raise TypeError(f"{twice[0]} is given twice: in params and as a "
                        f"keyword argument")
    return {**params, **values}


def _plan_buffers(rt, bundle: Bundle) -> list[str]:
    """The buffers of the bundle (in its order) that the plan of the
    runtime session `rt` holds: those sim_session_buffer_bytes knows, as
    sim-run's check of the state asks."""
    lib = simrt.load_library()
    size = ctypes.c_size_t()
    return [name for name in bundle.buffers
            if lib.sim_session_buffer_bytes(rt._handle, name.encode(),
                                            ctypes.byref(size)) == 0]


def _value_literal(value) -> str:
    """The text `sim_session_set` parses to exactly `value`. numpy's
    scalars print their shortest round trip in their own type (str of
    np.float32(0.1) is "0.1", whose double is not the float32's value),
    so numbers go through Python's int or float (np.float32 is exact in
    a double) and its repr; bools and text stay as they are."""
    if isinstance(value, (bool, np.bool_)):
        return str(value)
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return str(value)


def _value_text(value) -> str:
    """nan, inf or -inf, as sim-run writes them."""
    return "nan" if np.isnan(value) else "inf" if value > 0 else "-inf"


def _not_real(value) -> bool:
    """Whether an element of an object array is no real number (None, text,
    a complex number, a container...). numbers.Real, and the numbers that
    are not complex ones (Decimal) but convert to a float."""
    if isinstance(value, (bool, np.bool_)):
        return False
    if isinstance(value, numbers.Real):
        return False
    return (not isinstance(value, numbers.Number) or
            isinstance(value, numbers.Complex))


def _short(value) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _one(value) -> str:
    """`value` in a message: None, or its type and (short) repr."""
    if value is None:
        return "None"
    return f"the {type(value).__name__} {_short(value)}"


def _container(values) -> str:
    """What holds the values given: a list, a tuple, an array..."""
    if isinstance(values, np.ndarray):
        return "an array"
    name = type(values).__name__
    return f"{'an' if name[:1] in 'aeiou' else 'a'} {name}"


def _real_array(name: str, info: BufferInfo, values) -> np.ndarray:
    """`values` as an array of the buffer's scalar type, or a TypeError
    naming the buffer when they are no real numbers: numpy would make NaN
    of None (np.asarray(None, float)), drop the imaginary part of complex
    numbers with only a warning, and parse text."""
    what = (f"buffer {name} ({info.element_type}) takes real numbers "
            f"(converted to {info.dtype})")
    try:
        given = np.asarray(values)
    except ValueError as error:
        # Nested sequences of different lengths.
        raise ValueError(f"{what}; {_short(values)} is no array of "
                         f"numbers ({error})") from None
    kind = given.dtype.kind
    if kind == "c":
        raise TypeError(f"{what}, not complex numbers ({given.dtype}; "
                        f"pass their real part, .real, to drop the "
                        f"imaginary part)")
    if kind == "O":
        bad = next(((index, item) for index, item in np.ndenumerate(given)
                    if _not_real(item)), None)
        if bad is not None:
            index, item = bad
            where = "" if given.ndim == 0 else \
                f" at index {list(index) if len(index) > 1 else index[0]}"
            given_text = (_one(values) if given.ndim == 0 else
                          f"{_container(values)} holding "
                          f"{_one(item)}{where}")
            raise TypeError(f"{what}, not {given_text}")
    elif kind not in "biuf":
        # Text, bytes, dates, structured arrays.
        text = (f"text ({given.dtype})" if kind in "US" else
                f"{given.dtype} values")
        given_text = (_one(values) if given.ndim == 0 else
                      f"{_container(values)} of {text}")
        raise TypeError(f"{what}, not {given_text}")
    try:
        return np.asarray(given, dtype=info.dtype)
    except (TypeError, ValueError) as error:
        # An object that says it is a number but does not convert.
        raise TypeError(f"{what}; {_short(values)} does not convert "
                        f"({error})") from None


def _put(rt, name, data: np.ndarray):
    simrt._check(simrt.load_library().sim_session_set_buffer(
        rt._handle, name.encode(), data.ctypes.data, data.nbytes))
