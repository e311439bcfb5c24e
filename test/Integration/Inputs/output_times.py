"""sim-run --output-every N --output FILE, read back with NumPy.

Usage: output_times.py SIM_RUN BUNDLE OUT_DIR --steps S --every N
           --strategy STRATEGY [--reference exact|simple] [--set NAME=VALUE]

Runs once with --output, --dump and --json and checks the .npz against
what docs/Runtime.md ("Output times") promises: exactly its keys, t and
time, every buffer's dtype and shape, the last row equal to the --dump of
the final state bit for bit, every row equal bit for bit to the final state
of a run that ends at that output time (which stops at the same output
times before it, so it cuts the same big steps), the totals equal to the
JSON's, and the errors equal to those NumPy computes from the rows and the
reference: the exact solution's rows, or the rows of the simple strategy's
own --output. Prints one line per check for FileCheck.
"""

import argparse
import json
import os
import subprocess
import sys
import zipfile

import numpy as np


def sim_run(path, args):
    run = subprocess.run([path] + args, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"sim-run {' '.join(args)} failed ({run.returncode}):\n"
                 f"{run.stdout}{run.stderr}")
    return run.stdout


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("sim_run")
    parser.add_argument("bundle")
    parser.add_argument("out")
    parser.add_argument("--steps", type=int, required=True)
    parser.add_argument("--every", type=int, required=True)
    parser.add_argument("--strategy", required=True)
    parser.add_argument("--reference")
    parser.add_argument("--set", action="append", default=[])
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    sets = [a for s in args.set for a in ("--set", s)]
    common = [args.bundle, "--backend", "cpu", "--strategy", args.strategy,
              "--output-every", str(args.every)] + sets
    reference = ["--reference", args.reference] if args.reference else []
    npz = os.path.join(args.out, "series.npz")
    dump = os.path.join(args.out, "final")
    report = os.path.join(args.out, "run.json")
    table = sim_run(args.sim_run, common + reference + [
        "--steps", str(args.steps), "--output", npz, "--dump", dump,
        "--json", report])
    run = json.load(open(report))
    data = np.load(npz)
    observed = sorted(f[:-len(".npy")] for f in os.listdir(dump)
                      if not f.endswith(".reference.npy"))
    totals = sorted(run["totals"])

    expected = {"t", "time", "meta/scene", "meta/strategy", "meta/backend"}
    expected |= {"buffer/" + name for name in observed}
    expected |= {"total/" + name for name in totals}
    if args.reference:
        has_reference = [name for name in observed
                         if args.reference == "simple" or
                         os.path.exists(os.path.join(
                             dump, name + ".reference.npy"))]
        expected |= {f"error/{name}/{norm}" for name in has_reference
                     for norm in ("max_abs", "rms_rel")}
        if args.reference == "exact":
            expected |= {"exact/" + name for name in has_reference}
    print("keys as documented:", set(data.files) == expected,
          sorted(set(data.files) ^ expected))
    # Stored, like numpy.savez.
    with zipfile.ZipFile(npz) as archive:
        print("stored:", all(i.compress_type == zipfile.ZIP_STORED
                             for i in archive.infolist()))

    times = list(range(0, args.steps, args.every)) + [args.steps]
    t = data["t"]
    print("t:", t.dtype == np.int64 and list(t) == times)
    dt = run["dt"]
    print("time:", data["time"].dtype == np.float64 and
          bool(np.array_equal(data["time"], t * dt)))
    print("meta:", str(data["meta/scene"]) == run["scene"],
          str(data["meta/strategy"]) == args.strategy,
          str(data["meta/backend"]) == "cpu", data["meta/scene"].shape == ())

    shapes, last = True, True
    for name in observed:
        final = np.load(os.path.join(dump, name + ".npy"))
        rows = data["buffer/" + name]
        shapes &= (rows.dtype == final.dtype and
                   rows.shape == (len(times),) + final.shape)
        last &= rows[-1].tobytes() == final.tobytes()
    print("buffers: dtype and shape", shapes, "last row is --dump", last)

    # Every row is the state at its output time.
    rows_ok = True
    for k, at in enumerate(times[1:-1], start=1):
        part = os.path.join(args.out, f"to-{at}")
        sim_run(args.sim_run, common + reference + [
            "--steps", str(at), "--dump", part])
        for name in observed:
            state = np.load(os.path.join(part, name + ".npy"))
            rows_ok &= data["buffer/" + name][k].tobytes() == state.tobytes()
            if args.reference == "exact" and name in has_reference:
                exact = np.load(os.path.join(part, name + ".reference.npy"))
                rows_ok &= (data["exact/" + name][k].tobytes() ==
                            exact.tobytes())
    print("every row is the state at its time:", rows_ok)

    series = run["totals_per_output_time"]
    totals_ok = [point["T"] for point in series] == times
    for name in totals:
        column = data["total/" + name]
        totals_ok &= column.dtype == np.float64
        totals_ok &= list(column) == [point[name] for point in series]
        totals_ok &= column[-1] == run["totals"][name]
    print("totals equal the JSON's:", totals_ok)

    if args.reference:
        if args.reference == "simple":
            theirs = os.path.join(args.out, "simple.npz")
            sim_run(args.sim_run, [args.bundle, "--backend", "cpu",
                                   "--strategy", "simple", "--output-every",
                                   str(args.every), "--steps",
                                   str(args.steps), "--output", theirs] + sets)
            source = np.load(theirs)
            refs = {name: source["buffer/" + name] for name in has_reference}
        else:
            refs = {name: data["exact/" + name] for name in has_reference}
        errors_ok = True
        for name in has_reference:
            ours = data["buffer/" + name].astype(np.float64)
            ref = refs[name].astype(np.float64)
            diff = (ours - ref).reshape(len(times), -1)
            max_abs = np.abs(diff).max(axis=1)
            norm = np.sqrt((ref.reshape(len(times), -1) ** 2).sum(axis=1))
            with np.errstate(divide="ignore", invalid="ignore"):
                rms = np.where(norm > 0, np.sqrt((diff ** 2).sum(axis=1)) /
                               norm, 0.0)
            errors_ok &= bool(np.array_equal(data[f"error/{name}/max_abs"],
                                             max_abs))
            errors_ok &= bool(np.allclose(data[f"error/{name}/rms_rel"], rms,
                                          rtol=1e-12, atol=0))
            final = run["error"][name]
            errors_ok &= data[f"error/{name}/max_abs"][-1] == final["max_abs"]
        print("errors equal NumPy's:", errors_ok,
              "max-abs at the end", run["error"][has_reference[0]]["max_abs"]
              > 0)

    # The table printed each output time as the run went.
    print("table rows:", sum(1 for line in table.splitlines()
                             if line.strip().split(" ")[0].isdigit()) ==
          len(times))
    print("json output:", run["output"]["times"] == times,
          run["output"]["every"] == args.every,
          run["output"]["file"] == npz)


if __name__ == "__main__":
    main()
