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


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
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

    text = open(args.scene).read()
    marked = [line for line in text.split("\n") if "// study-interp" in line]
    if len(marked) != 1:
        sys.exit("error: %s needs exactly one line marked // study-interp" %
                 args.scene)
    expect = dict((k, float(v)) for k, v in
                  (item.split("=") for item in args.expect.split(",") if item))
    workdir = tempfile.mkdtemp(prefix="sim-convergence-")
    failures = 0
    for interp in args.interps.split(","):
        variant = re.sub(r"interp\((?:[^()]|\([^()]*\))*\)",
                         "interp(%s)" % INTERPS[interp], marked[0], count=1)
        source = os.path.join(workdir, "%s.mlir" % interp)
        with open(source, "w") as f:
            f.write(text.replace(marked[0], variant))
        dts, errors = [], []
        for dt_text in args.dts.split(","):
            dt = float(dt_text)
            steps = round(args.time / dt)
            out = os.path.join(workdir, "%s-%s" % (interp, dt_text))
            result = subprocess.run(
                [args.sim_run, source, "--backend", args.backend, "--strategy",
                 args.strategy, "--steps", str(steps), "--set",
                 "dt=%s" % dt_text, "--dump", out],
                stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
            if result.returncode != 0:
                sys.exit("error: sim-run failed:\n" +
                         result.stdout.decode(errors="replace"))
            error = read_npy_max(os.path.join(out, args.buffer + ".npy"))
            print("run %s dt %s steps %d: max %s %.3e" % (
                interp, dt_text, steps, args.buffer, error))
            dts.append(dt)
            errors.append(error)
        order = fit_slope(dts, errors)
        verdict = ""
        if interp in expect:
            ok = abs(order - expect[interp]) <= args.tolerance
            failures += not ok
            verdict = " (expected %g +- %g: %s)" % (
                expect[interp], args.tolerance, "ok" if ok else "WRONG")
        print("order %s %.2f%s" % (interp, order, verdict))
    shutil.rmtree(workdir, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
