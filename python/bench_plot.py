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
faster), with the target's 1/1.25 drawn.

Noise is marked, not reported, by bench/run's rule (docs/benchmarks.md): a
speedup above its evaluation-count ceiling, or a ratio of two times either
of which spreads (max - min over median of its runs) by more than 10%. The
JSON's reasons ("noise", "sim_vs_baseline_noise") decide, and the spreads
and the ceiling where a JSON lacks them. Noise is drawn hollow (a point) or
hatched (a bar), with a legend entry, and listed on stdout.

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

# bench/run's NOISE_SPREAD: above this spread of a time's runs (max - min
# over median), a ratio that uses the time is noise.
NOISE_SPREAD = 0.10
NOISE_LABEL = "noise (above the ceiling, or a spread > %d%%)" % round(
    100 * NOISE_SPREAD)


class Parser(argparse.ArgumentParser):
    """argparse whose usage errors are one line (and status 2)."""

    def error(self, message):
        self.exit(2, "%s: error: %s (see %s --help)\n" % (self.prog, message,
                                                          self.prog))


def fail(message):
    sys.exit("bench_plot.py: error: %s" % message)


def read_study(path):
    """The JSON of a bench/run study (an error naming the file otherwise)."""
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError) as error:
        fail("cannot read %s: %s" % (path, getattr(error, "strerror", None)
                                     or error))
    if not isinstance(data, dict) or not isinstance(data.get("runs"), list) \
            or not isinstance(data.get("meta"), dict):
        fail("%s is not a bench.json of bench/run (no \"meta\" and \"runs\")"
             % path)
    return data


def spread_reasons(named):
    """bench/run's spread rule on (name, summary) pairs: the reasons."""
    return ["%s spread %.0f%%" % (name, 100 * summary["kernel_spread"])
            for name, summary in named
            if summary and (summary.get("kernel_spread") or 0) > NOISE_SPREAD]


def speedup_noise(run, simple):
    """Why `run`'s speedup over simple is noise ([] when it is a result):
    the JSON's reasons, or bench/run's rule on the ceiling and the
    spreads."""
    if run.get("noise"):
        return list(run["noise"])
    reasons = []
    if run["speedup_over_simple"] > run["ceiling"]:
        reasons.append("above its ceiling %.2fx" % run["ceiling"])
    return reasons + spread_reasons(
        [("its", run)] + ([("simple's", simple)] if simple is not run else []))


def versus_noise(run):
    """Why `run`'s sim-vs-hand-written ratio is noise ([] when it is a
    result)."""
    if run.get("sim_vs_baseline_noise"):
        return list(run["sim_vs_baseline_noise"])
    return spread_reasons([("sim's", run),
                           ("hand-written's", run.get("baseline"))])


def main():
    parser = Parser(
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
        fail("matplotlib is missing (apt-get install python3-matplotlib, "
             "then run with /usr/bin/python3)")
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    if args.versus_baseline:
        return plot_versus_baseline(args, plt, Patch)
    if len(args.results) != 1:
        fail("one bench.json at a time (or --versus-baseline)")
    data = read_study(args.results[0])
    runs = [r for r in data["runs"] if r["interp"] == args.interp]
    if not runs:
        fail("no run with the %s interpolation in %s (--interp: %s)" % (
            args.interp, args.results[0], ", ".join(sorted(
                {r["interp"] for r in data["runs"]})) or "none"))
    load = args.load if args.load is not None else max(r["load"] for r in runs)
    if not any(r["load"] == load for r in runs):
        fail("no run with L = %d in %s (--load: %s)" % (
            load, args.results[0], ", ".join(
                str(x) for x in sorted({r["load"] for r in runs}))))
    runs = [r for r in runs if r["load"] == load]
    simple_of = {(r["scenario"], r["size"], r["dist"]): r for r in runs
                 if r["algorithm"] == "simple"}
    noisy = []
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
            panel_noisy, handles = False, []
            for k, algorithm in enumerate(algorithms):
                points = sorted(
                    (r["size"], r["speedup_over_simple"], r["ceiling"],
                     speedup_noise(r, simple_of.get(
                         (scenario, r["size"], dist), r)))
                    for r in runs if r["scenario"] == scenario and
                    r["dist"] == dist and r["algorithm"] == algorithm)
                if not points:
                    continue
                sizes = [p[0] for p in points]
                color = "C%d" % k
                ax.plot(sizes, [p[1] for p in points], "-", color=color)
                # Results filled, noise hollow.
                for hollow in (False, True):
                    chosen = [p for p in points if bool(p[3]) == hollow]
                    if chosen:
                        ax.plot([p[0] for p in chosen], [p[1] for p in chosen],
                                "o", color=color, linestyle="none",
                                markerfacecolor="none" if hollow else color)
                ax.plot(sizes, [p[2] for p in points], "x--", color=color,
                        alpha=0.5)
                handles.append(Line2D([], [], color=color, marker="o",
                                      label=algorithm))
                noisy += ["%s dist %d |R| %d %s %.2fx: %s" % (
                    scenario, dist, p[0], algorithm, p[1], "; ".join(p[3]))
                    for p in points if p[3]]
                panel_noisy = panel_noisy or any(p[3] for p in points)
            ax.axhline(1.0, color="grey", linewidth=0.8)
            ax.set_xscale("log", base=2)
            ax.set_title("%s, dist %d (%s)" % (scenario, dist,
                                               names.get(dist, "?")), fontsize=9)
            ax.set_xlabel("|R|")
            ax.set_ylabel("speedup over simple")
            if panel_noisy:
                handles.append(Line2D([], [], color="grey", marker="o",
                                      linestyle="none",
                                      markerfacecolor="none",
                                      label=NOISE_LABEL))
            ax.legend(handles=handles, fontsize=7)
    meta = data["meta"]
    fig.suptitle("%s, %s interpolation, L = %d\n(dashed: ceiling; hollow: "
                 "noise)" % (meta.get("device"), args.interp, load),
                 fontsize=10)
    fig.tight_layout()
    output = args.output or os.path.join(os.path.dirname(args.results[0]),
                                         "bench.png")
    save(fig, output)
    for line in noisy:
        print("noise (hollow):", line)
    print("wrote", output)


def save(fig, output):
    try:
        fig.savefig(output, dpi=120)
    except (OSError, ValueError) as error:
        fail("cannot write %s: %s" % (output, getattr(error, "strerror", None)
                                      or error))


def plot_versus_baseline(args, plt, Patch):
    rows = []
    devices = set()
    for path in args.results:
        data = read_study(path)
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
                             noise=versus_noise(run)))
    if not rows:
        fail("no run with a timed hand-written baseline in %s"
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
        if any(r["noise"] for r in mine):
            handles.append(Patch(facecolor="none", edgecolor="grey",
                                 hatch="//", label="noise (a spread > %d%%)" %
                                 round(100 * NOISE_SPREAD)))
        handles += ax.get_legend_handles_labels()[0]
        ax.legend(handles=handles, fontsize=7, ncol=len(algorithms) + 1,
                  loc="upper right")
    fig.suptitle("sim against the hand-written code on %s (above 1: sim is "
                 "faster; hatched: noise)" % " / ".join(sorted(devices)),
                 fontsize=10)
    fig.tight_layout()
    output = args.output or os.path.join(os.path.dirname(args.results[0]),
                                         "bench-baseline.png")
    save(fig, output)
    for r in rows:
        if r["noise"]:
            print("noise (hatched): %s |R| %s L %d %s %d thr dist %d %s "
                  "%.3fx: %s" % (r["scenario"], size_name(r["size"]),
                                 r["load"], r["mode"], r["threads"],
                                 r["dist"], r["algorithm"], r["ratio"],
                                 "; ".join(r["noise"])))
    print("wrote", output)


if __name__ == "__main__":
    main()
