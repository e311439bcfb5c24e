#!/usr/bin/env python3
"""Plots bench/run's results: speedup over simple per algorithm.

One panel per scenario and step-count distribution; x is |R| (log), y the
speedup of each algorithm over simple measured in the same study, with the
ceiling (simple's evaluations over the algorithm's) dashed in the same
colour. Interpolation and load are taken from --interp and --load.

Usage: python3 python/bench_plot.py OUT/bench.json [--interp linear]
       [--load 1024] [-o OUT/bench.png]

Needs Debian's python3-matplotlib (run with /usr/bin/python3).
"""

import argparse
import json
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from simlists import STRATEGIES  # noqa: E402


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results")
    parser.add_argument("--interp", default="linear")
    parser.add_argument("--load", type=int)
    parser.add_argument("-o", "--output")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("error: matplotlib is missing (apt-get install "
                 "python3-matplotlib, then run with /usr/bin/python3)")
    data = json.load(open(args.results))
    runs = [r for r in data["runs"] if r["interp"] == args.interp]
    load = args.load or max(r["load"] for r in runs)
    runs = [r for r in runs if r["load"] == load]
    scenarios = sorted({r["scenario"] for r in runs})
    dists = sorted({r["dist"] for r in runs})
    algorithms = [a for a in STRATEGIES if a != "simple" and
                  any(r["algorithm"] == a for r in runs)]
    names = {0: "per component", 1: "per group", 2: "per item"}
    fig, axes = plt.subplots(len(scenarios), len(dists), squeeze=False,
                             figsize=(4 * len(dists), 3.2 * len(scenarios)))
    for row, scenario in enumerate(scenarios):
        for col, dist in enumerate(dists):
            ax = axes[row][col]
            for k, algorithm in enumerate(algorithms):
                points = sorted((r["size"], r["speedup_over_simple"],
                                 r["ceiling"]) for r in runs
                                if r["scenario"] == scenario and
                                r["dist"] == dist and r["algorithm"] == algorithm)
                if not points:
                    continue
                sizes = [p[0] for p in points]
                color = "C%d" % k
                ax.plot(sizes, [p[1] for p in points], "o-", color=color,
                        label=algorithm)
                ax.plot(sizes, [p[2] for p in points], "x--", color=color,
                        alpha=0.5)
            ax.axhline(1.0, color="grey", linewidth=0.8)
            ax.set_xscale("log", base=2)
            ax.set_title("%s, dist %d (%s)" % (scenario, dist,
                                               names.get(dist, "?")), fontsize=9)
            ax.set_xlabel("|R|")
            ax.set_ylabel("speedup over simple")
            ax.legend(fontsize=7)
    meta = data["meta"]
    fig.suptitle("%s, %s interpolation, L = %d (dashed: ceiling)" % (
        meta["device"], args.interp, load), fontsize=10)
    fig.tight_layout()
    output = args.output or os.path.join(os.path.dirname(args.results),
                                         "bench.png")
    fig.savefig(output, dpi=120)
    print("wrote", output)


if __name__ == "__main__":
    main()
