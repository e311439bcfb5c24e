#!/usr/bin/env python3
"""Measures the order of accuracy of interpolation functions on a scene.

For each interpolation it substitutes into the line of SCENE marked
`// study-interp` (as python/accuracy_study.py does), runs the scene with
`sim-run --strategy S --set dt=DT --steps TIME/DT --dump` for every base
step DT (each half the one before, so the big step halves with it), takes
the largest value of the observed error buffer, and fits the slope of
log(error) against log(DT) by least squares: the interpolation's order.

Usage:
  interp_convergence.py SCENE [--buffer E] [--interps linear,cubic,hermite]
      [--dts 0.04,0.02,0.01,0.005] [--time 3.2] [--strategy hip]
      [--backend cpu] [--sim-run PATH] [--expect linear=2,cubic=1,hermite=4]
      [--tolerance 0.25]

Prints one line per run and one `order` line per interpolation; with
--expect, exits with 1 when a fitted order is off by more than --tolerance.
Standard library only.
"""

import argparse
import atexit
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import ast

INTERPS = {"linear": "#sim.linear", "cubic": "#sim.cubic",
           "hermite": "#sim.hermite<@V>"}


def read_npy_max(path):
    data = open(path, "rb").read()
    (length,) = struct.unpack("<H", data[8:10])
    header = ast.literal_eval(data[10:10 + length].decode("latin1"))
    code = {"<f4": "f", "<f8": "d"}[header["descr"]]
    body = data[10 + length:]
    values = struct.unpack("<%d%s" % (len(body) // struct.calcsize(code), code),
                           body)
    return max(abs(v) for v in values)


def fit_slope(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    num = sum((a - mx) * (b - my) for a, b in zip(lx, ly))
    den = sum((a - mx) ** 2 for a in lx)
    return num / den


PROG = "interp_convergence.py"


class Parser(argparse.ArgumentParser):
    """argparse whose usage errors are one line (and status 2), as the sim
    tools print theirs."""

    def error(self, message):
        self.exit(2, "%s: error: %s (see %s --help)\n" % (self.prog, message,
                                                          self.prog))


def fail(message):
    sys.exit("%s: error: %s" % (PROG, message))


def positive_numbers(parser, option, text):
    """The finite numbers > 0 of a comma-separated list, as written and as
    floats."""
    items = [item.strip() for item in text.split(",")]
    try:
        values = [float(item) for item in items]
    except ValueError:
        values = []
    if not values or not all(0 < v < float("inf") for v in values):
        parser.error("--%s takes finite numbers > 0 separated by commas, "
                     "not %r" % (option, text))
    return items, values


def main():
    parser = Parser(
        prog=PROG, description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("--buffer", default="E")
    parser.add_argument("--interps", default="linear,cubic,hermite")
    parser.add_argument("--dts", default="0.04,0.02,0.01,0.005")
    parser.add_argument("--time", type=float, default=3.2)
    parser.add_argument("--strategy", default="hip")
    parser.add_argument("--backend", default="cpu")
    parser.add_argument("--sim-run", default=shutil.which("sim-run") or "sim-run")
    parser.add_argument("--expect", default="")
    parser.add_argument("--tolerance", type=float, default=0.25)
    args = parser.parse_args()

    interps = [name.strip() for name in args.interps.split(",")]
    unknown = [name for name in interps if name not in INTERPS]
    if unknown:
        parser.error("unknown interpolation %r in --interps (known: %s)" % (
            unknown[0], ", ".join(INTERPS)))
    dt_texts, dt_values = positive_numbers(parser, "dts", args.dts)
    if len(dt_values) < 2:
        parser.error("--dts takes at least two base steps to fit an order, "
                     "not %r" % args.dts)
    if not 0 < args.time < float("inf"):
        parser.error("--time takes a finite number > 0, not %s" % args.time)
    if not 0 <= args.tolerance < float("inf"):
        parser.error("--tolerance takes a finite number >= 0, not %s" %
                     args.tolerance)
    expect = {}
    for item in (i.strip() for i in args.expect.split(",") if i.strip()):
        name, _, value = item.partition("=")
        try:
            expect[name] = float(value)
        except ValueError:
            parser.error("--expect takes INTERP=ORDER pairs separated by "
                         "commas, not %r" % item)
        if name not in INTERPS:
            parser.error("unknown interpolation %r in --expect (known: %s)"
                         % (name, ", ".join(INTERPS)))
    if os.path.isdir(args.scene):
        parser.error("the scene %s is a folder, not a .mlir file" %
                     args.scene)
    try:
        with open(args.scene) as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as error:
        parser.error("cannot read the scene %s: %s" % (
            args.scene, getattr(error, "strerror", None) or error))
    sim_run = (args.sim_run if os.sep in args.sim_run else
               shutil.which(args.sim_run) or args.sim_run)
    if not (os.path.isfile(sim_run) and os.access(sim_run, os.X_OK)):
        parser.error("--sim-run %s is not an executable file (build sim-run "
                     "and put it on PATH, or pass its path)" % args.sim_run)
    marked = [line for line in text.split("\n") if "// study-interp" in line]
    if len(marked) != 1:
        parser.error("%s needs exactly one line marked // study-interp" %
                     args.scene)
    workdir = tempfile.mkdtemp(prefix="sim-convergence-")
    atexit.register(shutil.rmtree, workdir, ignore_errors=True)
    failures = 0
    for interp in interps:
        variant = re.sub(r"interp\((?:[^()]|\([^()]*\))*\)",
                         "interp(%s)" % INTERPS[interp], marked[0], count=1)
        source = os.path.join(workdir, "%s.mlir" % interp)
        with open(source, "w") as f:
            f.write(text.replace(marked[0], variant))
        dts, errors = [], []
        for dt_text, dt in zip(dt_texts, dt_values):
            steps = round(args.time / dt)
            out = os.path.join(workdir, "%s-%s" % (interp, dt_text))
            result = subprocess.run(
                [sim_run, source, "--backend", args.backend, "--strategy",
                 args.strategy, "--steps", str(steps), "--set",
                 "dt=%s" % dt_text, "--dump", out],
                stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
            if result.returncode != 0:
                fail("sim-run failed:\n" +
                     result.stdout.decode(errors="replace").rstrip())
            dump = os.path.join(out, args.buffer + ".npy")
            if not os.path.isfile(dump):
                have = sorted(f[:-4] for f in os.listdir(out)
                              if f.endswith(".npy"))
                fail("the scene observes no buffer %s (--buffer; it "
                     "observes %s)" % (args.buffer, ", ".join(have) or
                                       "none"))
            error = read_npy_max(dump)
            print("run %s dt %s steps %d: max %s %.3e" % (
                interp, dt_text, steps, args.buffer, error))
            dts.append(dt)
            errors.append(error)
        if not all(0 < e < float("inf") for e in errors):
            fail("the largest |%s| under %s is %s: it must be finite and "
                 "> 0 at every base step to fit an order" % (
                     args.buffer, interp, ", ".join("%g" % e for e in errors)))
        order = fit_slope(dts, errors)
        verdict = ""
        if interp in expect:
            ok = abs(order - expect[interp]) <= args.tolerance
            failures += not ok
            verdict = " (expected %g +- %g: %s)" % (
                expect[interp], args.tolerance, "ok" if ok else "WRONG")
        print("order %s %.2f%s" % (interp, order, verdict))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
