"""Python binding of the sim runtime (ctypes over libsim_runtime.so).

Runs scene bundles (`sim-translate scene.mlir --sim-to-bundle`) from Python
with the standard library only:

    import simrt
    with simrt.Bundle("gravity.simb") as bundle:
        with simrt.Session(bundle, strategy="hip", backend="cpu") as session:
            session.set("range", 4096)
            session.run(100)
            b2 = session.get("B2")          # array('f') or ('d') by the buffer's type
            print(session.metrics()["big_steps"], session.evaluations())

The library is found through $SIM_RUNTIME_LIB, next to this file's checkout
(build/lib/libsim_runtime.so), or on the loader's path. Every failing call
raises simrt.Error with the runtime's message (or the subclass of it that
set_error_class installs: sim.RunError once the sim package is loaded).
docs/Runtime.md documents the C API this wraps.
"""

import array
import ctypes
import os

__all__ = ["Error", "Bundle", "Session", "load_library", "strategies",
           "ProgressFunction", "set_error_class"]


# sim_status's SIM_ERROR_INVALID_ARGUMENT (sim_runtime.h).
_INVALID_ARGUMENT = 1


class Error(RuntimeError):
    """A failed runtime call: `status` is the sim_status code."""

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status


# The class of the errors this module raises: Error, or the subclass of it
# that set_error_class installed (the sim package's sim.RunError, which is
# a sim.SimError too).
_error_class = Error


def set_error_class(cls):
    """Makes failed calls raise `cls(status, message)`, a subclass of
    Error (so `except simrt.Error` still catches them)."""
    global _error_class
    if not (isinstance(cls, type) and issubclass(cls, Error)):
        raise TypeError("the error class must be a subclass of simrt.Error, "
                        "not %r" % (cls,))
    _error_class = cls


def _error(status, message):
    return _error_class(status, message)


class _Options(ctypes.Structure):
    _fields_ = [("strategy", ctypes.c_int), ("backend", ctypes.c_int),
                ("group_size", ctypes.c_int64), ("cpu_threads", ctypes.c_int32),
                ("cuda_device", ctypes.c_int32), ("cuda_graph", ctypes.c_int32),
                ("check_finite", ctypes.c_int32), ("max_memory", ctypes.c_int64),
                # A sim_communicator *: Python sessions run on one process.
                ("communicator", ctypes.c_void_p)]


class _Metrics(ctypes.Structure):
    _fields_ = [("steps", ctypes.c_int64), ("begin", ctypes.c_int64),
                ("end", ctypes.c_int64), ("wall_seconds", ctypes.c_double),
                ("kernel_seconds", ctypes.c_double),
                ("launches", ctypes.c_int64), ("graph_launches", ctypes.c_int64),
                ("host_syncs", ctypes.c_int64), ("big_steps", ctypes.c_int64),
                ("halo_exchanges", ctypes.c_int64),
                ("exchanged_bytes", ctypes.c_int64),
                ("allreduces", ctypes.c_int64)]


_DISTRIBUTED_METRICS = ("halo_exchanges", "exchanged_bytes", "allreduces")


class _KernelProfile(ctypes.Structure):
    _fields_ = [("name", ctypes.c_char_p), ("launches", ctypes.c_int64),
                ("seconds", ctypes.c_double)]


class _BufferInfo(ctypes.Structure):
    _fields_ = [("name", ctypes.c_char_p), ("element_type", ctypes.c_char_p),
                ("scalar_type", ctypes.c_char_p),
                ("scalar_bytes", ctypes.c_int32), ("lanes", ctypes.c_int32),
                ("interp", ctypes.c_char_p), ("boundary", ctypes.c_char_p),
                ("observed", ctypes.c_int32), ("exact", ctypes.c_int32),
                ("precision_bytes", ctypes.c_int32)]


class _ParamInfo(ctypes.Structure):
    _fields_ = [("name", ctypes.c_char_p), ("type", ctypes.c_char_p),
                ("default_value", ctypes.c_char_p)]


# void (*)(void *user, int64_t done, int64_t total)
ProgressFunction = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int64,
                                    ctypes.c_int64)

_lib = None


def load_library(path=None):
    """Loads libsim_runtime.so once (see the module docstring for where)."""
    global _lib
    if _lib is not None:
        return _lib
    # A library asked for by path (the argument or $SIM_RUNTIME_LIB) is
    # that library: failing to load it is an error, not a reason to load
    # another build's.
    asked = path or os.environ.get("SIM_RUNTIME_LIB")
    if asked:
        try:
            _lib = ctypes.CDLL(asked)
        except OSError as error:
            raise OSError(f"cannot load the runtime library {asked!r}"
                          f"{'' if path else ' ($SIM_RUNTIME_LIB)'}: "
                          f"{error}") from None
        _declare(_lib)
        return _lib
    candidates = [os.path.join(os.path.dirname(os.path.abspath(__file__)),
                               "..", "build", "lib", "libsim_runtime.so"),
                  "libsim_runtime.so"]
    errors = []
    for candidate in candidates:
        if not candidate:
            continue
        try:
            _lib = ctypes.CDLL(candidate)
            break
        except OSError as error:
            errors.append(str(error))
    if _lib is None:
        raise OSError("cannot load libsim_runtime.so (set SIM_RUNTIME_LIB): " +
                      "; ".join(errors))
    _declare(_lib)
    return _lib


def _declare(lib):
    c = ctypes
    p = c.c_void_p
    sigs = {
        "sim_last_error": (c.c_char_p, []),
        "sim_strategy_name": (c.c_char_p, [c.c_int]),
        "sim_strategy_parse": (c.c_int, [c.c_char_p, c.POINTER(c.c_int)]),
        "sim_backend_parse": (c.c_int, [c.c_char_p, c.POINTER(c.c_int)]),
        "sim_bundle_open": (c.c_int, [c.c_char_p, c.POINTER(p)]),
        "sim_bundle_close": (None, [p]),
        "sim_bundle_scene_name": (c.c_char_p, [p]),
        "sim_bundle_range": (c.c_int64, [p]),
        "sim_bundle_dt": (c.c_double, [p]),
        "sim_bundle_max_steps": (c.c_int64, [p]),
        "sim_bundle_flushes_subnormals": (c.c_int, [p]),
        "sim_bundle_dt_type": (c.c_char_p, [p]),
        "sim_bundle_has_strategy": (c.c_int, [p, c.c_int]),
        "sim_bundle_num_buffers": (c.c_int32, [p]),
        "sim_bundle_buffer": (c.c_int, [p, c.c_int32,
                                        c.POINTER(_BufferInfo)]),
        "sim_bundle_num_params": (c.c_int32, [p]),
        "sim_bundle_param": (c.c_int, [p, c.c_int32, c.POINTER(_ParamInfo)]),
        "sim_backend_name": (c.c_char_p, [c.c_int]),
        "sim_session_options_init": (None, [c.POINTER(_Options)]),
        "sim_session_create": (c.c_int, [p, c.POINTER(_Options), c.POINTER(p)]),
        "sim_session_destroy": (None, [p]),
        "sim_session_device": (c.c_char_p, [p]),
        "sim_session_backend": (c.c_int, [p]),
        "sim_session_backend_note": (c.c_char_p, [p]),
        "sim_session_group_size": (c.c_int64, [p]),
        "sim_session_set": (c.c_int, [p, c.c_char_p, c.c_char_p]),
        "sim_session_get": (c.c_int, [p, c.c_char_p, c.c_char_p, c.c_size_t]),
        "sim_session_range": (c.c_int64, [p]),
        "sim_session_has_exact": (c.c_int, [p, c.c_char_p]),
        "sim_session_exact": (c.c_int, [p, c.c_char_p, p, c.c_size_t]),
        "sim_session_set_progress": (None, [p, ProgressFunction, p]),
        "sim_session_interrupt": (None, [p]),
        "sim_session_resume": (None, [p]),
        "sim_session_init": (c.c_int, [p]),
        "sim_session_time": (c.c_int64, [p]),
        "sim_session_buffer_bytes": (c.c_int, [p, c.c_char_p,
                                               c.POINTER(c.c_size_t)]),
        "sim_session_get_buffer": (c.c_int, [p, c.c_char_p, p, c.c_size_t]),
        "sim_session_set_buffer": (c.c_int, [p, c.c_char_p, p, c.c_size_t]),
        "sim_session_run": (c.c_int, [p, c.c_int64]),
        "sim_session_metrics": (c.c_int, [p, c.POINTER(_Metrics)]),
        "sim_session_num_components": (c.c_int32, [p]),
        "sim_session_component": (c.c_char_p, [p, c.c_int32]),
        "sim_session_evaluations": (c.c_int64, [p, c.c_int32]),
        "sim_session_histogram": (c.c_int64, [p, c.c_int64]),
        "sim_session_num_kernels": (c.c_int32, [p]),
        "sim_session_kernel_profile": (c.c_int, [p, c.c_int32,
                                                 c.POINTER(_KernelProfile)]),
        "sim_session_num_totals": (c.c_int32, [p]),
        "sim_session_total_name": (c.c_char_p, [p, c.c_int32]),
        "sim_session_total": (c.c_int, [p, c.c_char_p,
                                        c.POINTER(c.c_double)]),
    }
    for name, (restype, argtypes) in sigs.items():
        function = getattr(lib, name)
        function.restype = restype
        function.argtypes = argtypes


def _check(status):
    if status != 0:
        raise _error(status, load_library().sim_last_error().decode())


def _c_int(what, value, bits):
    """`value`, or a ValueError naming `what` when it is outside a C
    integer of `bits` bits: ctypes would wrap it silently (2**64 + 10
    steps would run 10)."""
    low, high = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    if isinstance(value, int) and not low <= value <= high:
        raise ValueError("%s must be from -2^%d to 2^%d - 1 (an int%d), "
                         "not %d" % (what, bits - 1, bits - 1, bits, value))
    return value


def _parse(parse, name):
    """A strategy's or backend's value, as the runtime names them (its
    message for an unknown name)."""
    value = ctypes.c_int()
    _check(parse(name.encode(), ctypes.byref(value)))
    return value.value


def strategies():
    """The strategies the runtime knows, in the order of their values
    (python/simlists.py holds the same list for scripts that do not load
    the library; test/Python/strategies.test compares them)."""
    lib = load_library()
    names = []
    while True:
        name = lib.sim_strategy_name(len(names)).decode()
        if name == "unknown":
            return names
        names.append(name)


class Bundle:
    """An opened scene bundle."""

    def __init__(self, path, library=None):
        lib = load_library(library)
        self._raw = ctypes.c_void_p()
        _check(lib.sim_bundle_open(os.fsencode(path), ctypes.byref(self._raw)))

    @property
    def _handle(self):
        # A closed bundle would answer with empty values (the C API takes a
        # null handle as none): say so instead.
        if not self._raw:
            raise _error(_INVALID_ARGUMENT, "the bundle is closed")
        return self._raw

    @property
    def name(self):
        return load_library().sim_bundle_scene_name(self._handle).decode()

    @property
    def range(self):
        return load_library().sim_bundle_range(self._handle)

    @property
    def dt(self):
        return load_library().sim_bundle_dt(self._handle)

    @property
    def max_steps(self):
        return load_library().sim_bundle_max_steps(self._handle)

    @property
    def flushes_subnormals(self):
        """Whether the bundle runs with subnormals flushed to zero
        (sim-translate --sim-ftz)."""
        return bool(load_library().sim_bundle_flushes_subnormals(
            self._handle))

    @property
    def dt_type(self):
        """"f32" or "f64": the type of dt and the scene's precision."""
        return load_library().sim_bundle_dt_type(self._handle).decode()

    def buffers(self):
        """Every buffer of the scene, in declaration order: a dict per
        buffer with name, element_type, scalar_type ("f32"/"f64"),
        scalar_bytes, lanes, interp, boundary, observed, exact and
        precision_bytes (of the narrowest float its values derive from)."""
        lib = load_library()
        result = []
        for index in range(lib.sim_bundle_num_buffers(self._handle)):
            info = _BufferInfo()
            _check(lib.sim_bundle_buffer(self._handle, index,
                                         ctypes.byref(info)))
            result.append({name: (value.decode() if isinstance(value, bytes)
                                  else value)
                           for name, value in ((n, getattr(info, n))
                                               for n, _ in info._fields_)})
        for buffer in result:
            buffer["observed"] = bool(buffer["observed"])
            buffer["exact"] = bool(buffer["exact"])
        return result

    def buffer(self, name):
        """The info of buffer `name` (see buffers()); KeyError if none."""
        for buffer in self.buffers():
            if buffer["name"] == name:
                return buffer
        raise KeyError("scene %s has no buffer %r" % (self.name, name))

    def params(self):
        """The scene's parameters: a dict per parameter with name, type and
        default_value (text)."""
        lib = load_library()
        result = []
        for index in range(lib.sim_bundle_num_params(self._handle)):
            info = _ParamInfo()
            _check(lib.sim_bundle_param(self._handle, index,
                                        ctypes.byref(info)))
            result.append({"name": info.name.decode(),
                           "type": info.type.decode(),
                           "default_value": info.default_value.decode()})
        return result

    def has_strategy(self, strategy):
        lib = load_library()
        return bool(lib.sim_bundle_has_strategy(
            self._handle, _parse(lib.sim_strategy_parse, strategy)))

    def close(self):
        if self._raw:
            load_library().sim_bundle_close(self._raw)
            self._raw = ctypes.c_void_p()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


class Session:
    """One strategy of a bundle on one backend, with its state."""

    def __init__(self, bundle, strategy="hip", backend="auto", group_size=0,
                 check_finite=False, cpu_threads=0, max_memory=0):
        lib = load_library()
        options = _Options()
        lib.sim_session_options_init(ctypes.byref(options))
        options.strategy = _parse(lib.sim_strategy_parse, strategy)
        options.backend = _parse(lib.sim_backend_parse, backend)
        options.group_size = _c_int("group_size", group_size, 64)
        options.check_finite = int(check_finite)
        options.cpu_threads = _c_int("cpu_threads", cpu_threads, 32)
        # Bytes of device (or host) memory the session may use; 0: the
        # runtime's default share (sim-run --max-memory).
        options.max_memory = _c_int("max_memory", max_memory, 64)
        self._bundle = bundle  # keeps the bundle open as long as the session
        self._buffers = {b["name"]: b for b in bundle.buffers()}
        self._raw = ctypes.c_void_p()
        _check(lib.sim_session_create(bundle._handle, ctypes.byref(options),
                                      ctypes.byref(self._raw)))

    @property
    def _handle(self):
        if not self._raw:
            raise _error(_INVALID_ARGUMENT, "the session is closed")
        return self._raw

    @property
    def device(self):
        return load_library().sim_session_device(self._handle).decode()

    @property
    def time(self):
        """The current base step T."""
        return load_library().sim_session_time(self._handle)

    def set(self, name, value):
        """Sets `range`, `dt` or a parameter (like sim-run --set)."""
        _check(load_library().sim_session_set(self._handle, name.encode(),
                                              str(value).encode()))

    def init(self):
        _check(load_library().sim_session_init(self._handle))

    def run(self, steps):
        """Runs `steps` base steps; the run ends exactly at T + steps."""
        _check(load_library().sim_session_run(self._handle,
                                              _c_int("steps", steps, 64)))

    def _bytes(self, buffer):
        size = ctypes.c_size_t()
        _check(load_library().sim_session_buffer_bytes(
            self._handle, buffer.encode(), ctypes.byref(size)))
        return size.value

    def _typecode(self, buffer, typecode):
        """The array typecode of a buffer's scalars, from the bundle's buffer
        info; a `typecode` that does not match them is an error (it would
        reinterpret the bytes)."""
        info = self._buffers.get(buffer)
        if info is None:
            raise _error(1, "unknown buffer '%s'" % buffer)
        expected = {4: "f", 8: "d"}[info["scalar_bytes"]]
        # The float typecode of the same size only: an integer array of the
        # right size would still have its bits read as floats.
        if typecode is not None and typecode != expected:
            raise ValueError("buffer %s holds %s scalars; typecode %r does "
                             "not match (use %r or leave it out)"
                             % (buffer, info["scalar_type"], typecode,
                                expected))
        return typecode or expected

    def get(self, buffer, typecode=None):
        """The buffer's current state as array.array, item-major with vector
        lanes packed: 'f' for f32 buffers, 'd' for f64 ones (from the
        bundle's buffer info; a `typecode` given must match it)."""
        typecode = self._typecode(buffer, typecode)
        data = array.array(typecode, bytes(self._bytes(buffer)))
        address, _ = data.buffer_info()
        _check(load_library().sim_session_get_buffer(
            self._handle, buffer.encode(), address,
            len(data) * data.itemsize))
        return data

    def put(self, buffer, data):
        """Replaces the buffer's current state with an array.array of the
        buffer's scalar type."""
        self._typecode(buffer, data.typecode)
        address, _ = data.buffer_info()
        _check(load_library().sim_session_set_buffer(
            self._handle, buffer.encode(), address,
            len(data) * data.itemsize))

    def metrics(self):
        metrics = _Metrics()
        _check(load_library().sim_session_metrics(self._handle,
                                                  ctypes.byref(metrics)))
        # The distributed counters are always 0 here: Python sessions run
        # on one process.
        return {name: getattr(metrics, name) for name, _ in _Metrics._fields_
                if name not in _DISTRIBUTED_METRICS}

    def evaluations(self):
        """Item evaluations per component during the last run."""
        lib = load_library()
        return {lib.sim_session_component(self._handle, index).decode():
                lib.sim_session_evaluations(self._handle, index)
                for index in range(lib.sim_session_num_components(self._handle))}

    def kernels(self):
        """The plan's kernels in the last run, by name: launches, and their
        kernel time in seconds where the backend times every launch (the
        CPU), else None. Empty for the reference executor."""
        lib = load_library()
        result = {}
        for index in range(lib.sim_session_num_kernels(self._handle)):
            profile = _KernelProfile()
            _check(lib.sim_session_kernel_profile(self._handle, index,
                                                  ctypes.byref(profile)))
            result[profile.name.decode()] = {
                "launches": profile.launches,
                "seconds": profile.seconds if profile.seconds >= 0 else None}
        return result

    def totals(self):
        """The scene's totals at the current time, by name (declaration
        order): per-item values from the device, summed on the host in item
        order in double."""
        lib = load_library()
        result = {}
        for index in range(lib.sim_session_num_totals(self._handle)):
            name = lib.sim_session_total_name(self._handle, index)
            value = ctypes.c_double()
            _check(lib.sim_session_total(self._handle, name,
                                         ctypes.byref(value)))
            result[name.decode()] = value.value
        return result

    def histogram(self, max_steps):
        """Big steps taken of each size 1..max_steps in the last run."""
        lib = load_library()
        return {size: lib.sim_session_histogram(self._handle, size)
                for size in range(1, max_steps + 1)}

    def close(self):
        if self._raw:
            load_library().sim_session_destroy(self._raw)
            self._raw = ctypes.c_void_p()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
