#!/usr/bin/env python3
"""Checks the hand-written baseline (bench/cuda) against sim, case by case.

For every scene, interpolation, strategy, range and @dist it runs

    sim-run BUNDLE --backend cpu --strategy S --steps N --set range=R
            --set dist=D --group-size G --dump DIR --json FILE
    sim-baseline-host --scene SCENE --interp I (the same settings)

and requires the observed buffer to be equal bit for bit, and the
evaluations per component, the big steps and their sizes to be equal. sim's
CPU kernels and the host build of the baseline do the same IEEE operations
in the same order (no contraction; libm's tanhf), so any difference is a
difference of algorithm. One line per case, a summary last; exit status 1
when a case differs (after running them all).

Usage:
  baseline_check.py SIM_RUN SIM_TRANSLATE BASELINE OUTDIR [--ranges 1,101]
                    [--dists 0,1,2,3,4] [--steps N] [--group-size G]
Standard library only.
"""

import argparse
import concurrent.futures
import json
import os
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(ROOT, "python"))
from simnpy import read_npy  # noqa: E402

SCENES = {"gravity_like": "B2", "pbd_like": "B6"}
STRATEGIES = ["simple", "traditional", "hip", "hip-cache"]


def parse_args():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    for name in ["sim_run", "sim_translate", "baseline", "outdir"]:
        parser.add_argument(name)
    parser.add_argument("--ranges", default="1,101")
    parser.add_argument("--dists", default="0,1,2,3,4")
    parser.add_argument("--interps", default="linear,cubic")
    parser.add_argument("--steps", type=int, default=12)
    parser.add_argument("--group-size", type=int, default=32)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    return parser.parse_args()


def bundle(args, scene, interp):
    """The scene as bench/run compiles it: cubic replaces every #sim.linear."""
    text = open(os.path.join(ROOT, "examples", "paper", scene + ".mlir")).read()
    if interp == "cubic":
        text = text.replace("#sim.linear", "#sim.cubic")
    source = os.path.join(args.outdir, "%s-%s.mlir" % (scene, interp))
    with open(source, "w") as f:
        f.write(text)
    out = source[:-len(".mlir")] + ".simb"
    subprocess.run([args.sim_translate, source, "--sim-to-bundle",
                    "--sim-group-size=%d" % args.group_size, "-o", out],
                   check=True)
    return out


def run(command, out):
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT)
    if result.returncode != 0:
        return None, result.stdout.decode(errors="replace")
    return json.load(open(out)), ""


def bits(values):
    return struct.pack("<%df" % len(values), *values)


def check(args, bundles, case):
    scene, interp, strategy, range_, dist = case
    tag = "%s-%s-%s-%d-%d" % (scene, interp, strategy, range_, dist)
    settings = ["--strategy", strategy, "--steps", str(args.steps), "--set",
                "range=%d" % range_, "--set", "dist=%d" % dist,
                "--group-size", str(args.group_size)]
    ours_dir = os.path.join(args.outdir, tag + ".sim")
    theirs_dir = os.path.join(args.outdir, tag + ".baseline")
    os.makedirs(theirs_dir, exist_ok=True)
    ours, log = run([args.sim_run, bundles[(scene, interp)], "--backend",
                     "cpu"] + settings + ["--dump", ours_dir, "--json",
                                          ours_dir + ".json"],
                    ours_dir + ".json")
    if ours is None:
        return case, ["sim-run failed:\n" + log]
    theirs, log = run([args.baseline, "--scene", scene, "--interp", interp] +
                      settings + ["--dump", theirs_dir, "--json",
                                  theirs_dir + ".json"],
                      theirs_dir + ".json")
    if theirs is None:
        return case, ["the baseline failed:\n" + log]
    problems = []
    buffer = SCENES[scene] + ".npy"
    shape_a, a = read_npy(os.path.join(ours_dir, buffer))
    shape_b, b = read_npy(os.path.join(theirs_dir, buffer))
    if tuple(shape_a) != tuple(shape_b) or bits(a) != bits(b):
        differ = sum(1 for x, y in zip(a, b) if bits([x]) != bits([y]))
        worst = max((abs(x - y) for x, y in zip(a, b)), default=0.0)
        problems.append("state: %d of %d values differ (max-abs %.3e)" %
                        (differ, len(a), worst))
    for key in ["evaluations", "big_steps", "big_step_histogram"]:
        if ours[key] != theirs[key]:
            problems.append("%s: sim %s, baseline %s" % (key, ours[key],
                                                         theirs[key]))
    return case, problems


def main():
    args = parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    interps = args.interps.split(",")
    bundles = {(s, i): bundle(args, s, i) for s in SCENES for i in interps}
    cases = [(s, i, st, int(r), int(d)) for s in SCENES for i in interps
             for st in STRATEGIES for r in args.ranges.split(",")
             for d in args.dists.split(",")]
    failed = 0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for case, problems in pool.map(lambda c: check(args, bundles, c),
                                       cases):
            name = "%s %s %s range %d dist=%d" % case
            if problems:
                failed += 1
                print("DIFFER: %s\n  | %s" % (name, "\n  | ".join(problems)))
            else:
                print("equal: %s" % name)
    print("baseline check: %d cases, %d equal, %d differ" % (
        len(cases), len(cases) - failed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
