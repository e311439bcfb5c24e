#!/usr/bin/env python3
"""Checks a backend against the reference executor over a matrix of runs.

For every scene, strategy, range and setting variant it runs

    sim-run BUNDLE --backend B --strategy S --steps N --set range=R
            [--set K=V]... --group-size G --check --json OUT.json

`sim-run --check` runs the scene on backend B and on the reference executor
(docs/Reference.md) side by side and fails when a buffer differs by more than
the tolerance or when the evaluation counts or big-step sizes differ. Every
case prints one line; the last line is a summary. Exits with 1 when a case
disagrees (after running them all, so that a planted bug shows its extent).

Usage:
  crosscheck.py SIM_RUN OUTDIR --scene NAME BUNDLE VARIANTS [--scene ...]
                [--ranges 1,20,101] [--strategies simple,traditional,...]
                [--steps N] [--group-size G] [--backend cpu|cuda]
                [--tolerance X] [--jobs J]

VARIANTS is a `;`-separated list of settings, each a `,`-separated list of
K=V (`dist=0;dist=1` runs every case twice; `as-is` is the scene as it is).
Standard library only.
"""

import argparse
import concurrent.futures
import json
import os
import subprocess
import sys

STRATEGIES = ["simple", "traditional", "hip", "hip-cache"]


def parse_args():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sim_run")
    parser.add_argument("outdir")
    parser.add_argument("--scene", nargs=3, action="append", required=True,
                        metavar=("NAME", "BUNDLE", "VARIANTS"))
    parser.add_argument("--ranges", default="1,20,101")
    parser.add_argument("--strategies", default=",".join(STRATEGIES))
    parser.add_argument("--steps", type=int, default=24)
    parser.add_argument("--group-size", type=int, default=32)
    parser.add_argument("--backend", default="cpu")
    parser.add_argument("--tolerance")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    return parser.parse_args()


def cases(args):
    for name, bundle, variants in args.scene:
        for strategy in args.strategies.split(","):
            for range_ in args.ranges.split(","):
                for variant in variants.split(";"):
                    sets = [] if variant == "as-is" else variant.split(",")
                    yield name, bundle, strategy, int(range_), sets


def run_case(args, case):
    name, bundle, strategy, range_, sets = case
    tag = "%s.%s.r%d.%s" % (name, strategy, range_,
                            "_".join(s.replace("=", "") for s in sets) or "as-is")
    out = os.path.join(args.outdir, tag + ".json")
    command = [args.sim_run, bundle, "--backend", args.backend, "--strategy",
               strategy, "--steps", str(args.steps), "--set",
               "range=%d" % range_, "--group-size", str(args.group_size),
               "--check", "--json", out]
    for s in sets:
        command += ["--set", s]
    if args.tolerance:
        command += ["--check-tolerance", args.tolerance]
    try:
        result = subprocess.run(command, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, timeout=300)
        output, status = result.stdout.decode(errors="replace"), result.returncode
    except subprocess.TimeoutExpired:
        output, status = "timed out after 300 s", -1
    label = "%s %s range %d %s" % (name, strategy, range_,
                                   " ".join(sets) or "as-is")
    worst = None
    if status in (0, 1) and os.path.exists(out):
        check = json.load(open(out)).get("check") or {}
        for buffer in check.get("buffers", {}).values():
            # JSON has no NaN: sim-run writes null for a NaN difference.
            if buffer["max_abs"] is None or buffer["max_reference"] is None:
                ratio = float("nan")
            else:
                ratio = buffer["max_abs"] / max(1.0, buffer["max_reference"])
            worst = ratio if worst is None or ratio != ratio else max(
                worst, ratio)
    return label, status, output, worst, " ".join(command)


def main():
    args = parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    all_cases = list(cases(args))
    failures = 0
    worst = 0.0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for label, status, output, case_worst, command in pool.map(
                lambda case: run_case(args, case), all_cases):
            if status == 0:
                worst = max(worst, case_worst or 0.0)
                print("agree: %s (largest difference %.3g of max(1, |ref|))"
                      % (label, case_worst or 0.0))
            else:
                failures += 1
                print("DISAGREE: %s (exit %d)\n  $ %s\n%s" % (
                    label, status, command,
                    "\n".join("  | " + line for line in output.splitlines())))
    print("crosscheck %s: %d cases, %d agree, %d disagree; largest agreeing "
          "difference %.3g" % (args.backend, len(all_cases),
                               len(all_cases) - failures, failures, worst))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
