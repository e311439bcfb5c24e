"""Runs a scene with totals under every strategy on the CPU backend.

Usage: totals.py SIM_RUN BUNDLE OUT_DIR --steps N --every K --energy-bound B

For each strategy: sim-run --backend cpu --check --report-every K --json,
then checks that the JSON has the totals at every output time, that --check
passed (totals equal to the reference executor's within its tolerance), and
that the energy stays within B (relative) of its initial value. Prints one
line per strategy for FileCheck.
"""

import argparse
import json
import os
import subprocess
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "python"))
from simlists import STRATEGIES  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("sim_run")
    parser.add_argument("bundle")
    parser.add_argument("out")
    parser.add_argument("--steps", type=int, required=True)
    parser.add_argument("--every", type=int, required=True)
    parser.add_argument("--energy-bound", type=float, required=True)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    failed = False
    for strategy in STRATEGIES:
        path = os.path.join(args.out, strategy + ".json")
        run = subprocess.run(
            [args.sim_run, args.bundle, "--backend", "cpu", "--strategy",
             strategy, "--steps", str(args.steps), "--report-every",
             str(args.every), "--check", "--json", path],
            capture_output=True, text=True)
        if run.returncode != 0:
            print(f"{strategy}: sim-run failed ({run.returncode}):\n"
                  f"{run.stdout}{run.stderr}")
            failed = True
            continue
        with open(path) as f:
            report = json.load(f)
        series = report["totals_per_output_time"]
        times = [point["T"] for point in series]
        expected = list(range(0, args.steps, args.every)) + [args.steps]
        energy0 = series[0]["Energy"]
        drift = max(abs(point["Energy"] - energy0) for point in series)
        drift /= abs(energy0)
        final = report["totals"]
        check = report["check"]
        print(f"{strategy}: output times {times == expected}, "
              f"totals {sorted(final)}, check "
              f"{'pass' if check['pass'] else 'FAIL'}, totals checked "
              f"{sorted(check['totals'])}, energy drift "
              f"{'within' if drift <= args.energy_bound else 'BEYOND'} "
              f"{args.energy_bound}")
        print(f"  ({strategy}: relative energy drift {drift:.3e}, "
              f"E(0) {energy0:.9e}, final {final})", file=sys.stderr)
        failed |= times != expected or not check["pass"] or \
            drift > args.energy_bound
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
