"""Checkpoints and restarts of a time-dependent scene, bit for bit.

Usage: checkpoint.py SIM_RUN LIBSIM_RUNTIME BUNDLE OUT_DIR --backend B
           [--every N] [--more M]

For every strategy on backend B:

1. sim-run --steps 10^9 --checkpoint-every N --checkpoint CK, killed with
   SIGKILL once CK exists: CK holds a periodic checkpoint, written on the
   first big-step boundary at or after a multiple of N (no big step cut).
2. Its base step Tc, read with the C API (ctypes: sim_session_restart,
   sim_session_time).
3. sim-run --restart CK --steps Tc + M against an uninterrupted
   sim-run --steps Tc + M: the dumps (.npy bytes), the totals (JSON, which
   reads back exactly) and the big steps after Tc must be equal. The
   uninterrupted run passes Tc on the same boundary: the big steps before
   the end do not depend on the end.
4. The issue's symptom, through the C API: the buffers at Tc given to a
   fresh session without the clock end with another energy.

With --sigint, also for hip: SIGINT instead of SIGKILL, which makes
sim-run write the checkpoint where the run stopped (JSON "steps_done").

Prints one line per strategy for FileCheck; details go to stderr.
"""

import argparse
import ctypes
import json
import os
import signal
import subprocess
import sys
import time

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "python"))
from simlists import STRATEGIES  # noqa: E402


class Runtime:
    """The few C API calls this test needs."""

    def __init__(self, path):
        lib = ctypes.CDLL(path)
        p, i64 = ctypes.c_void_p, ctypes.c_int64
        lib.sim_last_error.restype = ctypes.c_char_p
        lib.sim_bundle_open.argtypes = [ctypes.c_char_p, ctypes.POINTER(p)]
        lib.sim_bundle_close.argtypes = [p]
        lib.sim_session_create.argtypes = [p, p, ctypes.POINTER(p)]
        lib.sim_session_destroy.argtypes = [p]
        lib.sim_session_restart.argtypes = [p, ctypes.c_char_p]
        lib.sim_session_time.argtypes = [p]
        lib.sim_session_time.restype = i64
        lib.sim_session_run.argtypes = [p, i64]
        lib.sim_session_init.argtypes = [p]
        lib.sim_session_total.argtypes = [p, ctypes.c_char_p,
                                          ctypes.POINTER(ctypes.c_double)]
        lib.sim_session_buffer_bytes.argtypes = [
            p, ctypes.c_char_p, ctypes.POINTER(ctypes.c_size_t)]
        lib.sim_session_get_buffer.argtypes = [p, ctypes.c_char_p, p,
                                               ctypes.c_size_t]
        lib.sim_session_set_buffer.argtypes = [p, ctypes.c_char_p, p,
                                               ctypes.c_size_t]
        lib.sim_strategy_parse.argtypes = [ctypes.c_char_p,
                                           ctypes.POINTER(ctypes.c_int)]
        lib.sim_backend_parse.argtypes = [ctypes.c_char_p,
                                          ctypes.POINTER(ctypes.c_int)]
        self.lib = lib

    def check(self, status):
        if status != 0:
            raise RuntimeError(self.lib.sim_last_error().decode())

    def session(self, bundle_path, strategy, backend):
        """A session (options: strategy, backend; the rest default)."""
        lib = self.lib
        bundle = ctypes.c_void_p()
        self.check(lib.sim_bundle_open(bundle_path.encode(),
                                       ctypes.byref(bundle)))

        class Options(ctypes.Structure):
            _fields_ = [("strategy", ctypes.c_int), ("backend", ctypes.c_int),
                        ("group_size", ctypes.c_int64),
                        ("cpu_threads", ctypes.c_int32),
                        ("cuda_device", ctypes.c_int32),
                        ("cuda_graph", ctypes.c_int32),
                        ("check_finite", ctypes.c_int32),
                        ("max_memory", ctypes.c_int64),
                        # sim_runtime.h's full struct: without this field
                        # the runtime reads whatever follows it.
                        ("communicator", ctypes.c_void_p)]
        options = Options()
        value = ctypes.c_int()
        self.check(lib.sim_strategy_parse(strategy.encode(),
                                          ctypes.byref(value)))
        options.strategy = value.value
        self.check(lib.sim_backend_parse(backend.encode(),
                                         ctypes.byref(value)))
        options.backend = value.value
        session = ctypes.c_void_p()
        self.check(lib.sim_session_create(bundle, ctypes.byref(options),
                                          ctypes.byref(session)))
        lib.sim_bundle_close(bundle)
        return session

    def buffer(self, session, name):
        size = ctypes.c_size_t()
        self.check(self.lib.sim_session_buffer_bytes(
            session, name.encode(), ctypes.byref(size)))
        data = ctypes.create_string_buffer(size.value)
        self.check(self.lib.sim_session_get_buffer(session, name.encode(),
                                                   data, size))
        return data

    def total(self, session, name):
        value = ctypes.c_double()
        self.check(self.lib.sim_session_total(session, name.encode(),
                                              ctypes.byref(value)))
        return value.value


def sim_run(args, sim_run_path):
    run = subprocess.run([sim_run_path] + args, capture_output=True,
                         text=True)
    if run.returncode != 0:
        raise RuntimeError(f"sim-run {' '.join(args)} failed "
                           f"({run.returncode}):\n{run.stdout}{run.stderr}")
    return run


def interrupted_run(sim_run_path, args, checkpoint, sig):
    """Starts a long run, waits for its first checkpoint, sends `sig`."""
    def defaults():
        # lit's workers ignore SIGINT, and sim-run keeps a signal ignored
        # that was ignored when it started.
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        signal.signal(signal.SIGTERM, signal.SIG_DFL)

    process = subprocess.Popen([sim_run_path] + args,
                               stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL,
                               preexec_fn=defaults)
    deadline = time.time() + 120
    while not os.path.exists(checkpoint):
        if process.poll() is not None or time.time() > deadline:
            process.kill()
            raise RuntimeError("no checkpoint appeared")
        time.sleep(0.01)
    process.send_signal(sig)
    try:
        return process.wait(timeout=120)
    except subprocess.TimeoutExpired:
        process.kill()
        raise RuntimeError(f"sim-run did not stop on signal {sig}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("sim_run")
    parser.add_argument("runtime")
    parser.add_argument("bundle")
    parser.add_argument("out")
    parser.add_argument("--backend", required=True)
    parser.add_argument("--every", type=int, default=200)
    parser.add_argument("--more", type=int, default=300)
    parser.add_argument("--sigint", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rt = Runtime(args.runtime)
    failed = False

    def compare(tag, strategy, restart, reference, steps_at):
        """The restarted run against the uninterrupted one."""
        a, b = (json.load(open(path)) for path in (restart, reference))
        same_dump = all(
            open(os.path.join(restart[:-5], name), "rb").read() ==
            open(os.path.join(reference[:-5], name), "rb").read()
            for name in os.listdir(reference[:-5]))
        same_totals = a["totals"] == b["totals"]
        print(f"  ({tag} {strategy}: restart at {steps_at}, totals "
              f"{a['totals']} vs {b['totals']}, big steps after the restart "
              f"{a['big_steps']})", file=sys.stderr)
        return same_dump, same_totals

    common = ["--backend", args.backend]
    for strategy in STRATEGIES:
        base = os.path.join(args.out, f"{args.backend}-{strategy}")
        checkpoint = base + ".simc"
        for path in (checkpoint,):
            if os.path.exists(path):
                os.remove(path)
        status = interrupted_run(
            args.sim_run,
            [args.bundle, "--strategy", strategy, "--steps", "1000000000",
             "--checkpoint", checkpoint, "--checkpoint-every",
             str(args.every)] + common,
            checkpoint, signal.SIGKILL)
        session = rt.session(args.bundle, strategy, args.backend)
        rt.check(rt.lib.sim_session_restart(session, checkpoint.encode()))
        at = rt.lib.sim_session_time(session)
        end = at + args.more
        sim_run([args.bundle, "--strategy", strategy, "--steps", str(end),
                 "--restart", checkpoint, "--dump", base + "-restart",
                 "--json", base + "-restart.json"] + common, args.sim_run)
        sim_run([args.bundle, "--strategy", strategy, "--steps", str(end),
                 "--dump", base + "-whole", "--json", base + "-whole.json"]
                + common, args.sim_run)
        same_dump, same_totals = compare(
            "periodic", strategy, base + "-restart.json", base + "-whole.json",
            at)

        # The symptom: the state at Tc without its clock.
        rt.check(rt.lib.sim_session_run(session, end - at))
        restarted = rt.total(session, "Energy")
        buffers_only = rt.session(args.bundle, strategy, args.backend)
        rt.check(rt.lib.sim_session_init(buffers_only))
        source = rt.session(args.bundle, strategy, args.backend)
        rt.check(rt.lib.sim_session_restart(source, checkpoint.encode()))
        for name in ("Q", "T"):
            data = rt.buffer(source, name)
            rt.check(rt.lib.sim_session_set_buffer(
                buffers_only, name.encode(), data, len(data)))
        rt.check(rt.lib.sim_session_run(buffers_only, end - at))
        lost = rt.total(buffers_only, "Energy")
        whole = json.load(open(base + "-whole.json"))["totals"]["Energy"]
        print(f"  ({strategy}: energy at {end}: uninterrupted {whole}, "
              f"restarted {restarted}, buffers without the clock {lost})",
              file=sys.stderr)
        for handle in (session, buffers_only, source):
            rt.lib.sim_session_destroy(handle)
        ok = (same_dump and same_totals and restarted == whole and
              lost != whole and status == -signal.SIGKILL and at >= args.every)
        failed |= not ok
        print(f"{args.backend} {strategy}: periodic checkpoint restarts bit "
              f"for bit {same_dump and same_totals}, C API energy equal "
              f"{restarted == whole}, buffers alone differ {lost != whole}")

    if args.sigint:
        base = os.path.join(args.out, f"{args.backend}-sigint")
        checkpoint = base + ".simc"
        if os.path.exists(checkpoint):
            os.remove(checkpoint)
        status = interrupted_run(
            args.sim_run,
            [args.bundle, "--strategy", "hip", "--steps", "1000000000",
             "--checkpoint", checkpoint, "--checkpoint-every",
             str(args.every), "--json", base + ".json"] + common,
            checkpoint, signal.SIGINT)
        report = json.load(open(base + ".json"))
        at = report["steps_done"]
        end = at + args.more
        sim_run([args.bundle, "--strategy", "hip", "--steps", str(end),
                 "--restart", checkpoint, "--dump", base + "-restart",
                 "--json", base + "-restart.json"] + common, args.sim_run)
        sim_run([args.bundle, "--strategy", "hip", "--steps", str(end),
                 "--dump", base + "-whole", "--json", base + "-whole.json"]
                + common, args.sim_run)
        same_dump, same_totals = compare(
            "sigint", "hip", base + "-restart.json", base + "-whole.json", at)
        ok = (status == 130 and report["checkpoint"]["base_step"] == at and
              same_dump and same_totals)
        failed |= not ok
        print(f"{args.backend} sigint: exit {status}, checkpoint at the base "
              f"step reached {report['checkpoint']['base_step'] == at}, "
              f"restarts bit for bit {same_dump and same_totals}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
