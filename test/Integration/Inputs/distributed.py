#!/usr/bin/env python3
"""Runs one bundle on one process and on N ranks (sim-run --distributed)
and checks that they agree bit for bit.

For each strategy it runs `sim-run BUNDLE --backend B --strategy S
--steps N --dump --json` once on one process and once per rank count with
`MPIRUN -n RANKS sim-run ... --distributed`, then compares every dumped
buffer's bytes, the evaluation counters, big steps, the histogram of big
steps, cut big steps and the totals. Prints one line per run for FileCheck:

  same: S ranks R (big steps B, halo exchanges E = K per big step, ...)
  DIFFERS: S ranks R: what

and exits with 1 if any run differs or fails. Standard library only.

Usage: distributed.py --sim-run SIM_RUN --mpirun 'CMD' --bundle B --out DIR
         --steps N [--set K=V]... [--group-size G] [--ranks 2 3]
         [--strategies simple hip ...]
"""

import argparse
import json
import os
import shlex
import subprocess
import sys


def run(command, log):
    with open(log, "w") as out:
        status = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT,
                                timeout=600).returncode
    if status != 0:
        with open(log) as text:
            sys.stdout.write(text.read())
    return status


def dumps(folder):
    files = {}
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), "rb") as data:
            files[name] = data.read()
    return files


COMPARED = ["evaluations", "big_steps", "big_step_histogram", "cut_big_steps",
            "totals", "steps_done"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sim-run", required=True)
    parser.add_argument("--mpirun", required=True)
    parser.add_argument("--bundle", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--steps", type=int, required=True)
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--group-size", type=int, default=0)
    parser.add_argument("--backend", default="cpu",
                        help="the backend of both the one-process run and "
                        "the ranks (cpu or cuda)")
    parser.add_argument("--ranks", type=int, nargs="+", default=[2, 3])
    parser.add_argument("--strategies", nargs="+",
                        default=["simple", "traditional", "hip", "hip-cache"])
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    failed = False
    for strategy in args.strategies:
        common = [args.bundle, "--strategy", strategy, "--steps",
                  str(args.steps), "--threads", "1", "--no-init-check"]
        for setting in args.set:
            common += ["--set", setting]
        if args.group_size:
            common += ["--group-size", str(args.group_size)]

        def part(name, prefix, extra):
            folder = os.path.join(args.out, "%s-%s" % (strategy, name))
            command = prefix + [args.sim_run] + common + extra + [
                "--dump", folder, "--json", folder + ".json"]
            if run(command, folder + ".log") != 0:
                return None
            with open(folder + ".json") as report:
                return dumps(folder), json.load(report)

        one = part("one", [], ["--backend", args.backend])
        if one is None:
            print("DIFFERS: %s one process failed" % strategy)
            failed = True
            continue
        for ranks in args.ranks:
            many = part("ranks%d" % ranks,
                        shlex.split(args.mpirun) + ["-n", str(ranks)],
                        ["--distributed", "--backend", args.backend])
            if many is None:
                print("DIFFERS: %s ranks %d failed" % (strategy, ranks))
                failed = True
                continue
            what = []
            if many[0].keys() != one[0].keys():
                what.append("dumped files %s vs %s" %
                            (sorted(many[0]), sorted(one[0])))
            for name in sorted(one[0]):
                if name in many[0] and many[0][name] != one[0][name]:
                    what.append("%s bytes" % name)
            for key in COMPARED:
                if many[1].get(key) != one[1].get(key):
                    what.append("%s %r vs %r" %
                                (key, many[1].get(key), one[1].get(key)))
            if what:
                print("DIFFERS: %s ranks %d: %s" %
                      (strategy, ranks, "; ".join(what)))
                failed = True
                continue
            big = many[1]["big_steps"]
            exchanges = many[1].get("halo_exchanges", 0)
            per = ("%d per big step" % (exchanges // big)
                   if big and exchanges % big == 0 else "not a multiple")
            print("same: %s ranks %d (big steps %d, halo exchanges %d = %s, "
                  "all-reduces %d)" % (strategy, ranks, big, exchanges, per,
                                       many[1].get("allreduces", 0)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
