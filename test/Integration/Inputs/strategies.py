#!/usr/bin/env python3
"""Runs one bundle with every strategy on the CPU backend and checks the runs.

For each strategy (python/simlists.py) it runs
`sim-run BUNDLE --backend cpu --strategy S --steps N --json --dump` and checks
that the histogram of big steps adds up to N base steps and that every dumped
buffer is finite. Then:

  --force NAME=VALUE  (repeatable) runs every strategy again with these
                      settings, which must make every num_steps 1: every big
                      step must be 1 and every dumped buffer must have the
                      same bytes as simple's (with --forced-bundle B, these
                      runs use bundle B: a scene without a back-edge reader
                      needs max_steps 1, which only the compiler sets);
  --tol BUF=ATOL      (repeatable) the unforced run of every strategy must
                      stay within ATOL (max-abs) of simple for BUF;
  --expect BUF=EXPR   (repeatable) every strategy's unforced BUF must equal,
                      item by item, the Python expression EXPR of `i` (the
                      item), `R` (the range) and `lane` (within --expect-tol).

Prints one line per check (for FileCheck) and exits with 1 at the first
failure. Standard library only.

Usage: strategies.py SIM_RUN BUNDLE OUTDIR --steps N [--set K=V]...
         [--group-size G] [--force K=V]... [--forced-bundle B] [--tol BUF=ATOL]...
         [--expect BUF=EXPR]... [--expect-tol ATOL] [--check-finite]
"""

import argparse
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "python"))
from simlists import STRATEGIES  # noqa: E402
from simnpy import read_npy  # noqa: E402


def fail(message):
    print("error: " + message)
    sys.exit(1)


def run(args, strategy, sets, tag, bundle=None):
    out = os.path.join(args.outdir, "%s.%s" % (tag, strategy))
    command = [args.sim_run, bundle or args.bundle, "--backend", "cpu", "--strategy",
               strategy, "--steps", str(args.steps), "--json", out + ".json",
               "--dump", out]
    for s in sets:
        command += ["--set", s]
    if args.group_size:
        command += ["--group-size", str(args.group_size)]
    if args.check_finite:
        command += ["--check-finite"]
    try:
        result = subprocess.run(command, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, timeout=60)
    except subprocess.TimeoutExpired:
        fail("%s %s: sim-run did not finish in 60 s (hang?)" % (tag, strategy))
    if result.returncode != 0:
        fail("%s %s: sim-run exited with %d:\n%s" %
             (tag, strategy, result.returncode,
              result.stdout.decode(errors="replace")))
    report = json.load(open(out + ".json"))
    histogram = {int(m): c for m, c in report["big_step_histogram"].items()}
    covered = sum(m * c for m, c in histogram.items())
    taken = sum(histogram.values())
    if covered != args.steps or taken != report["big_steps"]:
        fail("%s %s: histogram %s covers %d base steps in %d big steps, "
             "asked for %d (report says %d big steps)" %
             (tag, strategy, histogram, covered, taken, args.steps,
              report["big_steps"]))
    buffers = {}
    for name in sorted(os.listdir(out)):
        if not name.endswith(".npy") or name.endswith(".reference.npy"):
            continue
        shape, values, body = read_npy(os.path.join(out, name), with_bytes=True)
        bad = [k for k, v in enumerate(values) if not math.isfinite(v)]
        if bad:
            fail("%s %s: %s has %d non-finite values, the first at %d" %
                 (tag, strategy, name, len(bad), bad[0]))
        buffers[name[:-4]] = (shape, values, body)
    if not buffers:
        fail("%s %s: nothing dumped" % (tag, strategy))
    sizes = " ".join("%d:%d" % (m, histogram[m]) for m in sorted(histogram)
                     if histogram[m])
    print("%s %s: %d base steps, big steps %s, finite" %
          (tag, strategy, covered, sizes))
    return histogram, buffers


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("sim_run")
    parser.add_argument("bundle")
    parser.add_argument("outdir")
    parser.add_argument("--steps", type=int, required=True)
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--group-size", type=int, default=0)
    parser.add_argument("--force", action="append", default=[])
    parser.add_argument("--forced-bundle")
    parser.add_argument("--tol", action="append", default=[])
    parser.add_argument("--expect", action="append", default=[])
    parser.add_argument("--expect-tol", type=float, default=1e-4)
    parser.add_argument("--check-finite", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)

    runs = {s: run(args, s, args.set, "run") for s in STRATEGIES}
    simple = runs["simple"][1]

    for spec in args.expect:
        name, expr = spec.split("=", 1)
        for s in STRATEGIES:
            shape, values, _ = runs[s][1][name]
            lanes = shape[1] if len(shape) > 1 else 1
            R = shape[0]
            worst = 0.0
            for i in range(R):
                for lane in range(lanes):
                    want = eval(expr, {"math": math, "i": i, "R": R,
                                       "lane": lane})
                    got = values[i * lanes + lane]
                    worst = max(worst, abs(got - want))
                    if not abs(got - want) <= args.expect_tol:
                        fail("%s %s[%d] lane %d is %r, expected %r" %
                             (s, name, i, lane, got, want))
            print("%s %s as expected" % (s, name))

    tolerances = dict(t.split("=", 1) for t in args.tol)
    for name, tol in sorted(tolerances.items()):
        tol = float(tol)
        for s in STRATEGIES[1:]:
            a = runs[s][1][name][1]
            b = simple[name][1]
            err = max(abs(x - y) for x, y in zip(a, b))
            if not err <= tol:
                fail("%s %s differs from simple by %.3e > %.1e" %
                     (s, name, err, tol))
            print("%s %s within %.0e of simple" % (s, name, tol))

    if args.force:
        forced = {s: run(args, s, args.set + args.force, "forced",
                         args.forced_bundle)
                  for s in STRATEGIES}
        for s in STRATEGIES:
            if {m for m, c in forced[s][0].items() if c} != {1}:
                fail("forced %s took big steps %s, not only 1" %
                     (s, forced[s][0]))
        for s in STRATEGIES[1:]:
            for name, (_, _, body) in sorted(forced["simple"][1].items()):
                other = forced[s][1][name][2]
                if other != body:
                    a = forced[s][1][name][1]
                    b = forced["simple"][1][name][1]
                    k = next(k for k in range(len(a)) if a[k] != b[k]
                             and not (a[k] != a[k] and b[k] != b[k]))
                    fail("forced %s %s differs from simple at %d: %r vs %r" %
                         (s, name, k, a[k], b[k]))
            print("forced %s equals simple bit for bit" % s)


if __name__ == "__main__":
    main()
