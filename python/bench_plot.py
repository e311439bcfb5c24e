#!/usr/bin/env python3
"""Plots bench/run's results: speedup over simple per algorithm.

One panel per scenario and step-count distribution; x is |R| (log), y the
speedup of each algorithm over simple measured in the same study, with the
ceiling (simple's evaluations over the algorithm's) dashed in the same
colour. Interpolation and load are taken from --interp and --load.

With --versus-baseline (studies run with a hand-written baseline, several
bench.json files at once: an IEEE and a flush-to-zero study, say), one
panel per scenario instead: a bar per configuration (|R|, L, mode, threads)
and algorithm, the hand-written code's time over sim's (above 1: sim is
faster), with the target's 1/1.25 drawn; rows whose runs were noise are
hatched.

Usage: python3 python/bench_plot.py OUT/bench.json [--interp linear]
       [--load 1024] [-o OUT/bench.png]
       python3 python/bench_plot.py A/bench.json B/bench.json
       --versus-baseline -o docs/bench-cpu.png

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
    parser.add_argument("results", nargs="+")
    parser.add_argument("--interp", default="linear")
    parser.add_argument("--load", type=int)
    parser.add_argument("--versus-baseline", action="store_true",
                        help="plot sim against the hand-written baseline")
    parser.add_argument("-o", "--output")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("error: matplotlib is missing (apt-get install "
                 "python3-matplotlib, then run with /usr/bin/python3)")
    if args.versus_baseline:
        from matplotlib.patches import Patch
        return plot_versus_baseline(args, plt, Patch)
    if len(args.results) != 1:
        sys.exit("error: one bench.json at a time (or --versus-baseline)")
    data = json.load(open(args.results[0]))
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
    output = args.output or os.path.join(os.path.dirname(args.results[0]),
                                         "bench.png")
    fig.savefig(output, dpi=120)
    print("wrote", output)


def plot_versus_baseline(args, plt, Patch):
    rows = []
    devices = set()
    for path in args.results:
        data = json.load(open(path))
        meta = data["meta"]
        devices.add(meta["device"])
        mode = "FTZ" if meta.get("ftz") else "IEEE"
        threads = meta.get("threads") or 0
        for run in data["runs"]:
            baseline = run.get("baseline")
            if not baseline or not baseline.get("timed") or \
                    run.get("sim_vs_baseline") is None:
                continue
            rows.append(dict(scenario=run["scenario"], size=run["size"],
                             load=run["load"], dist=run["dist"],
                             mode=mode, threads=threads,
                             algorithm=run["algorithm"],
                             ratio=run["sim_vs_baseline"],
                             noise=bool(run.get("sim_vs_baseline_noise"))))
    if not rows:
        sys.exit("error: no run with a timed hand-written baseline in %s"
                 % ", ".join(args.results))
    scenarios = sorted({r["scenario"] for r in rows})
    algorithms = [a for a in STRATEGIES
                  if any(r["algorithm"] == a for r in rows)]

    def size_name(size):
        return "%dM" % (size >> 20) if size >= 1 << 20 and size % (1 << 20) == 0 \
            else str(size)

    def config(r):
        return (r["size"], r["load"], r["mode"], r["threads"], r["dist"])

    fig, axes = plt.subplots(len(scenarios), 1, squeeze=False,
                             figsize=(10, 3.4 * len(scenarios)))
    width = 0.8 / max(1, len(algorithms))
    for row, scenario in enumerate(scenarios):
        ax = axes[row][0]
        mine = [r for r in rows if r["scenario"] == scenario]
        configs = sorted({config(r) for r in mine})
        for k, algorithm in enumerate(algorithms):
            for x, c in enumerate(configs):
                match = [r for r in mine
                         if config(r) == c and r["algorithm"] == algorithm]
                if not match:
                    continue
                r = match[0]
                ax.bar(x + (k - (len(algorithms) - 1) / 2) * width, r["ratio"],
                       width, color="C%d" % k,
                       hatch="//" if r["noise"] else None)
        ax.axhline(1.0, color="grey", linewidth=0.8)
        ax.axhline(0.8, color="red", linewidth=0.8, linestyle="--",
                   label="target (within 1.25x)")
        ax.set_xticks(range(len(configs)))
        ax.set_xticklabels(
            ["|R| %s\nL %d %s\n%d thr%s" % (size_name(c[0]), c[1], c[2], c[3],
                                             ", dist %d" % c[4] if c[4] else "")
             for c in configs], fontsize=7)
        ax.set_ylim(0, max(1.3, 1.2 * max(r["ratio"] for r in mine)))
        ax.set_ylabel("hand-written time / sim time")
        ax.set_title(scenario, fontsize=9)
        # The legend from plain patches: a noisy first bar would lend its
        # hatch to its algorithm's entry.
        handles = [Patch(color="C%d" % k, label=algorithm)
                   for k, algorithm in enumerate(algorithms)]
        handles += ax.get_legend_handles_labels()[0]
        ax.legend(handles=handles, fontsize=7, ncol=len(algorithms) + 1,
                  loc="upper right")
    fig.suptitle("sim against the hand-written code on %s (above 1: sim is "
                 "faster; hatched: noise)" % " / ".join(sorted(devices)),
                 fontsize=10)
    fig.tight_layout()
    output = args.output or os.path.join(os.path.dirname(args.results[0]),
                                         "bench-baseline.png")
    fig.savefig(output, dpi=120)
    print("wrote", output)


if __name__ == "__main__":
    main()
