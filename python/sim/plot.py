"""Plots of a run's outputs over time (matplotlib, Agg: PNG files).

    python3 -m sim.plot rod.npz                       # rod-T.png, rod-totals.png, ...
    python3 -m sim.plot rod.npz --times 0,-1 --out plots/
    python3 -m sim.plot kepler.npz --buffer X --lane 0

or from Python: `sim.plot.plot("rod.npz", out_dir="plots")` (or an Output).
The input is the `.npz` of `Output.save` or `sim-run --output-every N
--output FILE.npz` (sim.output describes the layout). For each observed
buffer: its profile over the items at the chosen output times (one panel
per lane, the exact solution dashed when the file has it); the totals over
time; the errors against the exact solution over time (log scale).
"""

from __future__ import annotations

import argparse
import numbers
import os
import sys

import numpy as np

from .output import Output

__all__ = ["plot", "main", "choose_times"]


def choose_times(count: int, times=None, most: int = 5) -> list[int]:
    """Indices of output times: `times` (ints, negative from the end), or
    up to `most` evenly spaced ones including the first and the last."""
    if count == 0:
        return []
    if times:
        chosen = []
        for k in times:
            if not -count <= k < count:
                raise ValueError(f"output time {k} out of range (the file "
                                 f"has {count})")
            chosen.append(k % count)
        return chosen
    if count <= most:
        return list(range(count))
    return sorted({round(x) for x in np.linspace(0, count - 1, most)})


_EXPECTED = ("the .npz of sim-run --output-every N --output FILE.npz or "
             "Output.save")


def _load_output(path) -> Output:
    """The Output in the file `path`, or a ValueError that names the file
    and says what it is instead of an output (.npz) file."""
    path = os.fspath(path)
    if not os.path.exists(path):
        raise ValueError(f"{path}: no such file (expected {_EXPECTED})")
    if os.path.isdir(path):
        raise ValueError(f"{path} is a folder, not an output file (expected "
                         f"{_EXPECTED})")
    with open(path, "rb") as f:
        head = f.read(8)
    if not head:
        raise ValueError(f"{path} is empty, not an output file (expected "
                         f"{_EXPECTED})")
    if head.startswith(b"\x93NUMPY"):
        raise ValueError(f"{path} is one .npy array, not an output file "
                         f"(expected {_EXPECTED})")
    if not head.startswith(b"PK"):
        raise ValueError(f"{path} is not a .npz file (a zip archive of .npy "
                         f"arrays; expected {_EXPECTED})")
    return Output.load(path)


def _lanes(values: np.ndarray) -> int:
    return 1 if values.ndim == 2 else values.shape[2]


def plot(source, out_dir: str | None = None, *, times=None, buffers=None,
         lanes=None, prefix: str | None = None) -> list[str]:
    """Writes the PNGs of an output file (or Output); returns their paths.

    `times`: indices of output times for the profiles (default: up to five
    spread over the run); `buffers`: which buffers (default all); `lanes`:
    which vector lanes (default all); each a list, or one index or name.
    `prefix`: the start of the file names (default: the input's stem, or
    the scene's name).
    """
    # One name or index for a list of them: a str would be iterated by
    # characters, an int not at all, and times=0 would read as no choice.
    if isinstance(buffers, str):
        buffers = [buffers]
    if isinstance(times, numbers.Integral):
        times = [times]
    if isinstance(lanes, numbers.Integral):
        lanes = [lanes]
    if isinstance(source, Output):
        out = source
        stem = prefix or out.meta.get("scene", "output")
        out_dir = out_dir or ""
    else:
        out = _load_output(source)
        stem = prefix or os.path.splitext(os.path.basename(str(source)))[0]
        if out_dir is None:
            out_dir = os.path.dirname(str(source))  # '' for the current one
    if out_dir:
        os.makedirs(out_dir, exist_ok=True)
    title = " ".join(v for v in (out.meta.get("scene"),
                                 out.meta.get("strategy"),
                                 out.meta.get("backend")) if v)
    chosen = choose_times(len(out), times)
    names = list(buffers or out.buffers)
    for name in names:
        if name not in out.buffers:
            raise KeyError(f"the output has no buffer {name!r} (it has "
                           f"{', '.join(out.buffers) or 'none'})")
        if lanes is not None:
            have = _lanes(out.buffers[name])
            bad = [lane for lane in lanes if not 0 <= lane < have]
            if bad:
                raise ValueError(f"buffer {name!r} has {have} lane"
                                 f"{'' if have == 1 else 's'} (0 to "
                                 f"{have - 1}), not {bad[0]}")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    written = []

    for name in names:
        values = out.buffers[name]
        exact = out.exact.get(name)
        lane_list = list(lanes) if lanes is not None else \
            list(range(_lanes(values)))
        columns = min(len(lane_list), 4)
        rows = (len(lane_list) + columns - 1) // columns
        fig, axes = plt.subplots(rows, columns, squeeze=False,
                                 figsize=(4.5 * columns + 1, 3.2 * rows + 0.6))
        items = np.arange(values.shape[1])
        colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
        for slot, lane in enumerate(lane_list):
            ax = axes[slot // columns][slot % columns]
            for n, k in enumerate(chosen):
                color = colors[n % len(colors)]
                v = values[k] if values.ndim == 2 else values[k][:, lane]
                ax.plot(items, v, color=color, lw=1.2,
                        label=f"t = {out.time[k]:.4g} (T = {out.t[k]})")
                if exact is not None:
                    e = exact[k] if exact.ndim == 2 else exact[k][:, lane]
                    ax.plot(items, e, color=color, lw=0.8, ls="--")
            ax.set_xlabel("item")
            ax.set_ylabel(name if values.ndim == 2 else f"{name}[{lane}]")
            ax.grid(alpha=0.3)
        for slot in range(len(lane_list), rows * columns):
            axes[slot // columns][slot % columns].set_visible(False)
        axes[0][0].legend(fontsize=7, title="exact dashed" if exact is not None
                          else None, title_fontsize=7)
        fig.suptitle(f"{title}: {name}" if title else name)
        fig.tight_layout()
        path = os.path.join(out_dir, f"{stem}-{name}.png")
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)

    if out.totals:
        names = list(out.totals)
        fig, axes = plt.subplots(len(names), 1, squeeze=False,
                                 figsize=(6, 2.4 * len(names) + 0.6))
        for ax, name in zip(axes[:, 0], names):
            ax.plot(out.time, out.totals[name], marker=".", lw=1)
            ax.set_ylabel(name)
            ax.grid(alpha=0.3)
            ax.ticklabel_format(useOffset=False, axis="y", style="plain")
        axes[-1][0].set_xlabel("time")
        fig.suptitle(f"{title}: totals" if title else "totals")
        fig.tight_layout()
        path = os.path.join(out_dir, f"{stem}-totals.png")
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)

    if out.errors:
        fig, axes = plt.subplots(1, 2, squeeze=False, figsize=(10, 3.6))
        for col, norm in enumerate(("max_abs", "rms_rel")):
            ax = axes[0][col]
            for name, norms in out.errors.items():
                if norm in norms:
                    # Zero errors (at t = 0) cannot be shown on a log scale.
                    values = np.where(norms[norm] > 0, norms[norm], np.nan)
                    ax.plot(out.time, values, marker=".", lw=1, label=name)
            ax.set_yscale("log")
            ax.set_xlabel("time")
            ax.set_ylabel({"max_abs": "max-abs error",
                           "rms_rel": "RMS-relative error"}[norm])
            ax.grid(alpha=0.3, which="both")
            ax.legend(fontsize=8)
        fig.suptitle(f"{title}: error against the exact solution" if title
                     else "error against the exact solution")
        fig.tight_layout()
        path = os.path.join(out_dir, f"{stem}-errors.png")
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)
    return written


def _ints(text: str) -> list[int]:
    return [int(x) for x in text.split(",") if x.strip()]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(
        prog="python3 -m sim.plot",
        description="Plot the outputs of a run (Output.save, or sim-run "
                    "--output-every N --output FILE.npz) as PNG files: "
                    "buffer profiles at chosen output times, totals and "
                    "errors over time.")
    parser.add_argument("file", help="the .npz output file")
    parser.add_argument("--out", metavar="DIR",
                        help="where the PNGs go (default: next to the file)")
    parser.add_argument("--times", type=_ints, metavar="K,K,...",
                        help="indices of the output times to profile "
                             "(negative: from the end; default: up to 5 "
                             "spread over the run)")
    parser.add_argument("--buffer", action="append", metavar="NAME",
                        help="only this buffer (repeatable)")
    parser.add_argument("--lane", type=_ints, metavar="L,L,...",
                        help="only these vector lanes")
    parser.add_argument("--prefix", help="file name prefix (default: the "
                                         "input's stem)")
    args = parser.parse_args(argv)
    try:
        paths = plot(args.file, args.out, times=args.times,
                     buffers=args.buffer, lanes=args.lane, prefix=args.prefix)
    except (KeyError, ValueError) as error:
        # A KeyError's str() is its message in quotes: print the message.
        message = error.args[0] if isinstance(error, KeyError) and \
            error.args else error
        print(f"sim.plot: error: {message}", file=sys.stderr)
        return 2
    except OSError as error:
        print("sim.plot: error: " + (f"{error.filename}: {error.strerror}"
                                     if error.filename and error.strerror
                                     else str(error)), file=sys.stderr)
        return 1
    for path in paths:
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
