#!/usr/bin/env python3
"""Speed against error on the physics scenes of examples/physics.

For every scene, interpolation variant, setting variant and strategy
(python/simlists.py) it runs

    sim-run BUNDLE --backend B --strategy S --steps N --group-size G
            --json FILE --dump DIR [--reference exact] [--set ...]

and collects the wall time, the evaluations per component, the big steps and
the error against the scene's reference:

  * scenes with `exact` bodies (harmonic, kpr, kepler): sim-run's error
    against the exact solution at the final time;
  * springs, nbody, heat_rod, heat_rod_flux, wave_rod, wave_staggered and
    particle_chain:
    the dumped state against `simple` run at
    dt / 8 for 8 times the steps (the same end time), computed here;
  * pbd: against `simple` at the same dt (position-based dynamics has no
    small-step limit to compare with: its stiffness depends on the step).

Per observed buffer the error is the max-abs difference and
||a - b||_2 / ||b||_2 (rms-rel); a configuration's error (plotted) is the largest
rms-rel over its observed buffers, except for harmonic: there the error of
@Y, the resonator that reads the interpolated driver. The wall time is the
fastest of the --repeat runs (the least disturbed by other load). kepler
also gets the drift of energy and angular momentum per orbit, nbody the
drift of the total energy, computed from the dumped state (per orbit for
kepler, which the scene's device-side totals cannot show: a sum over the
orbits lets their drifts cancel; see docs/accuracy.md, "Totals").

Interpolation variants: in a scene, the buffer line marked `// study-interp`
has its `interp(...)` replaced by #sim.linear, #sim.cubic or
#sim.hermite<@V> (hermite only where the scene has the derivative buffer);
the variants are written next to the bundles in --out.

Convergence mode (on by default, --no-convergence to skip): the harmonic
scene under hip for every interpolation of @X, the base step halved several
times at a fixed end time with @c scaled with dt (so every big step and
sub-step keeps its number of base steps); prints the error of @Y (the
resonator, which reads the interpolated driver) per dt and the least-squares
slope of log(error) against log(dt). With heat_rod (wave_rod,
wave_staggered) among the scenes, or --convergence-only, the same for lts on
both heat rods (the wave rod, the staggered wave): the error of @U against simple at dt / FINE, dt and @cfl halved
together, its slope and its largest ratio to simple's error.

Writes OUT/results.json, OUT/results.md and OUT/accuracy.png (matplotlib,
Agg; skipped with a note when matplotlib is missing). Progress goes to
stderr; stdout gets one `run ...` line per configuration (for FileCheck) and
the convergence slopes. Standard library only (plus matplotlib for the
plot).
"""

import argparse
import itertools
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from simlists import STRATEGIES  # noqa: E402
from simnpy import compare, read_npy  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
INTERPS = {
    "linear": "#sim.linear",
    "cubic": "#sim.cubic",
    "hermite": "#sim.hermite<@V>",
}
FINE = 8  # the fine reference runs simple at dt / FINE

# steps/range: full study; quick_*: CI. interps: variants of the marked
# buffer (the first is the scene's own). sets: setting variants (dicts).
SCENES = {
    "harmonic": dict(ref="exact", steps=4000, quick_steps=400, focus="Y",
                     quick_range=64, interps=["hermite", "linear", "cubic"],
                     sets=[{}]),
    "kpr": dict(ref="exact", steps=10000, quick_steps=400, quick_range=32,
                interps=["linear", "cubic"],
                sets=[{}, {"m_slow": "20"}]),
    "kepler": dict(ref="exact", steps=6283, quick_steps=400,
                   quick_range=256, interps=[None], sets=[{}]),
    "springs": dict(ref="fine", steps=2000, quick_steps=200,
                    quick_range=256, interps=["linear", "cubic"],
                    sets=[{}]),
    "nbody": dict(ref="fine", steps=1000, quick_steps=50, quick_range=64,
                  interps=[None], sets=[{}]),
    "pbd": dict(ref="simple", steps=1000, quick_steps=100, quick_range=64,
                interps=[None], sets=[{}]),
    # Its stiffness scales with range^2: at the quick range every item
    # takes max_steps and lts has nothing to gain (a smoke run).
    "heat_rod": dict(ref="fine", steps=4096, quick_steps=256,
                     quick_range=256, interps=[None], sets=[{}]),
    # The same rod in flux form (a flux pair under lts).
    "heat_rod_flux": dict(ref="fine", steps=4096, quick_steps=256,
                          quick_range=256, interps=[None], sets=[{}]),
    # lts_sets run under lts only: at smaller CFL fractions the outer parts
    # take 4 and 2 base steps instead of 8, trading evaluations for error
    # (the other strategies do not depend on @cfl).
    "wave_rod": dict(ref="fine", steps=10000, quick_steps=400,
                     quick_range=256, interps=[None], sets=[{}],
                     lts_sets=[{"cfl": "0.25"}, {"cfl": "0.125"}]),
    # The same wave in staggered (Yee) form: two components, an item pair.
    "wave_staggered": dict(ref="fine", steps=10000, quick_steps=400,
                           quick_range=256, interps=[None], sets=[{}]),
    # Particles that read their neighbours (FPU-beta ring, light segment).
    "particle_chain": dict(ref="fine", steps=4000, quick_steps=200,
                           quick_range=256, interps=[None], sets=[{}]),
}


PROG = "accuracy_study.py"


def log(message):
    print(message, file=sys.stderr, flush=True)


def fail(message, status=1):
    """Ends the study with one line, `accuracy_study.py: error: MESSAGE`."""
    print("%s: error: %s" % (PROG, message), file=sys.stderr, flush=True)
    sys.exit(status)


class Parser(argparse.ArgumentParser):
    """argparse whose usage errors are one line (and status 2), as the sim
    tools print theirs."""

    def error(self, message):
        self.exit(2, "%s: error: %s (see %s --help)\n" % (self.prog, message,
                                                          self.prog))


def find_tool(name, given):
    if given:
        found = given if os.sep in given else shutil.which(given) or given
        if not (os.path.isfile(found) and os.access(found, os.X_OK)):
            fail("--%s %s is not an executable file" % (name, given), 2)
        return found
    found = shutil.which(name)
    if found:
        return found
    for build in ["build", "../main/build"]:
        path = os.path.join(ROOT, build, "bin", name)
        if os.path.isfile(path):
            return path
    fail("%s not found (put it on PATH or pass --%s)" % (name, name), 2)


def make_out_folder(folder):
    """Makes --out, a usage error unless it is (or can be made) a folder the
    study can write to."""
    if os.path.exists(folder) and not os.path.isdir(folder):
        fail("--out %s is not a folder" % folder, 2)
    try:
        os.makedirs(folder, exist_ok=True)
        # os.access says yes to root on a read-only file system: write.
        tempfile.TemporaryFile(dir=folder).close()
    except OSError as error:
        fail("--out %s is not a folder it can write to (%s)" % (
            folder, error.strerror or error), 2)


def read_results(path):
    """The rows of a results.json of this study (--replot)."""
    if os.path.isdir(path):
        fail("--replot %s is a folder, not a results.json" % path, 2)
    try:
        with open(path) as f:
            data = json.load(f)
    except OSError as error:
        fail("--replot %s: %s" % (path, error.strerror or error), 2)
    except ValueError as error:
        fail("--replot %s is not JSON (%s)" % (path, error), 2)
    if not isinstance(data, dict) or not isinstance(data.get("results"),
                                                    list):
        fail("--replot %s is not a results.json of accuracy_study.py (no "
             "\"results\" list)" % path, 2)
    if not data["results"]:
        fail("--replot %s has no results to plot" % path, 2)
    return data["results"]


# --- bundles ---------------------------------------------------------------

def variant_text(text, interp):
    if interp is None:
        return text
    lines = text.split("\n")
    marked = [k for k, line in enumerate(lines) if "// study-interp" in line]
    if len(marked) != 1:
        fail("a scene with interpolation variants needs exactly one line "
             "marked // study-interp")
    k = marked[0]
    lines[k] = re.sub(r"interp\((?:[^()]|\([^()]*\))*\)",
                      "interp(%s)" % INTERPS[interp], lines[k], count=1)
    return "\n".join(lines)


def build_bundle(args, scene, interp):
    src = os.path.join(args.scenes_dir, scene + ".mlir")
    text = variant_text(open(src).read(), interp)
    tag = scene + ("-" + interp if interp else "")
    mlir = os.path.join(args.out, "scenes", tag + ".mlir")
    simb = os.path.join(args.out, "scenes", tag + ".simb")
    os.makedirs(os.path.dirname(mlir), exist_ok=True)
    with open(mlir, "w") as f:
        f.write(text)
    log("compiling %s" % tag)
    # The bundle runs here only: CPU kernels for this machine's level.
    if subprocess.run([args.sim_translate, mlir, "--sim-to-bundle",
                       "--sim-cpu-isas=host", "-o", simb]).returncode != 0:
        fail("compiling %s failed (sim-translate's errors above)" % mlir)
    return simb


# --- .npy ------------------------------------------------------------------

def rows(path):
    shape, flat = read_npy(path)
    lanes = shape[1] if len(shape) > 1 else 1
    return [flat[k * lanes:(k + 1) * lanes] for k in range(shape[0])]


# --- physics diagnostics from the dumped state ------------------------------

def kepler_drift(dump, ecc):
    """Largest relative drift of energy and angular momentum over the orbits."""
    xs, vs = rows(os.path.join(dump, "X.npy")), rows(os.path.join(dump, "V.npy"))
    e0, l0 = -0.5, math.sqrt(1 - ecc * ecc)
    de = dl = 0.0
    for x, v in zip(xs, vs):
        energy = 0.5 * (v[0] ** 2 + v[1] ** 2) - 1 / math.hypot(x[0], x[1])
        ang = x[0] * v[1] - x[1] * v[0]
        de = max(de, abs(energy - e0) / abs(e0))
        dl = max(dl, abs(ang - l0) / l0)
    return {"energy_drift": de, "angular_momentum_drift": dl}


def nbody_energy(dump, eps):
    xs, vs = rows(os.path.join(dump, "X.npy")), rows(os.path.join(dump, "V.npy"))
    n = len(xs)
    m = 1.0 / n
    kinetic = sum(0.5 * m * sum(c * c for c in v) for v in vs)
    potential = 0.0
    for i in range(n):
        xi = xs[i]
        for j in range(i + 1, n):
            xj = xs[j]
            d2 = ((xi[0] - xj[0]) ** 2 + (xi[1] - xj[1]) ** 2 +
                  (xi[2] - xj[2]) ** 2 + eps * eps)
            potential -= m * m / math.sqrt(d2)
    return kinetic + potential, kinetic, potential


# --- runs ------------------------------------------------------------------

def sim_run(args, simb, strategy, steps, sets, dump, reference=None):
    json_path = dump + ".json"
    command = [args.sim_run, simb, "--backend", args.backend, "--strategy",
               strategy, "--steps", str(steps), "--group-size",
               str(args.group_size), "--json", json_path, "--dump", dump]
    if args.repeat > 1:
        command += ["--repeat", str(args.repeat)]
    if args.check_finite:
        command.append("--check-finite")
    if reference:
        command += ["--reference", reference]
    for name, value in sets.items():
        command += ["--set", "%s=%s" % (name, value)]
    shutil.rmtree(dump, ignore_errors=True)
    os.makedirs(os.path.dirname(dump), exist_ok=True)
    proc = subprocess.run(command, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True)
    # Status 3: the run ended with NaN or infinity; the row says so
    # ("finite").
    if proc.returncode not in (0, 3):
        fail("%s failed:\n%s%s" % (" ".join(command), proc.stdout,
                                   proc.stderr))
    with open(json_path) as f:
        return json.load(f)


def all_finite(dump, buffers):
    for name in buffers:
        path = os.path.join(dump, name + ".npy")
        if any(not math.isfinite(x) for x in read_npy(path)[1]):
            return False
    return True


def study(args, results):
    for scene in args.scenes:
        spec = SCENES[scene]
        steps = spec["quick_steps"] if args.quick else spec["steps"]
        base_sets = {"range": str(spec["quick_range"])} if args.quick else {}
        fine = None
        for interp in spec["interps"]:
            simb = build_bundle(args, scene, interp)
            meta = None
            # Settings that only lts depends on need no run of the others
            # (and no simple of their own: only with a fine or exact
            # reference).
            assert not spec.get("lts_sets") or spec["ref"] != "simple"
            runs = [(extra, STRATEGIES) for extra in spec["sets"]]
            runs += [(extra, ["lts"]) for extra in spec.get("lts_sets", [])]
            for extra, strategies in runs:
                sets = dict(base_sets, **extra)
                if spec["ref"] == "fine" and fine is None:
                    # simple has every big step of one base step: every
                    # interpolation gives the same numbers, one run will do.
                    first = sim_run(args, simb, "simple", 0, sets,
                                    os.path.join(args.out, "runs",
                                                 scene + "-probe"))
                    dt = first["dt"]
                    fine_sets = dict(sets, dt=repr(dt / FINE))
                    log("%s: reference simple at dt %g, %d steps" %
                        (scene, dt / FINE, steps * FINE))
                    fine_dump = os.path.join(args.out, "runs", scene + "-fine")
                    sim_run(args, simb, "simple", steps * FINE, fine_sets,
                            fine_dump)
                    fine = fine_dump
                if scene == "nbody" and meta is None:
                    init_dump = os.path.join(args.out, "runs", scene + "-init")
                    meta = sim_run(args, simb, "simple", 0, sets, init_dump)
                    meta["energy0"] = nbody_energy(init_dump, 0.05)
                for strategy in strategies:
                    tag = "-".join(x for x in [scene, interp, strategy] +
                                   ["%s%s" % kv for kv in extra.items()] if x)
                    dump = os.path.join(args.out, "runs", tag)
                    log("running %s (%d steps)" % (tag, steps))
                    run = sim_run(args, simb, strategy, steps, sets, dump,
                                  "exact" if spec["ref"] == "exact" else None)
                    buffers = sorted(run["error"]) if run.get("error") else [
                        f[:-4] for f in sorted(os.listdir(dump))
                        if f.endswith(".npy") and ".reference" not in f]
                    if strategy == "simple":
                        simple_dump = dump
                    if spec["ref"] in ("fine", "simple"):
                        against = fine if spec["ref"] == "fine" else simple_dump
                        error = {}
                        for name in buffers:
                            a = read_npy(os.path.join(dump, name + ".npy"))[1]
                            b = read_npy(os.path.join(against,
                                                      name + ".npy"))[1]
                            error[name] = compare(a, b)
                    else:
                        error = run["error"]
                    row = {
                        "scene": scene, "interp": interp or "-",
                        "strategy": strategy, "settings": extra,
                        "steps": steps, "range": run["range"], "dt": run["dt"],
                        # The fastest of the --repeat runs: the least
                        # disturbed by other load on the machine.
                        "wall_seconds": min(run["wall_seconds_runs"]),
                        "wall_seconds_median": run["wall_seconds"],
                        "evaluations": run["evaluations"],
                        "big_steps": run["big_steps"],
                        "reference": {"exact": "exact",
                                      "fine": "simple at dt/%d" % FINE,
                                      "simple": "simple at the same dt"}[
                                          spec["ref"]],
                        "error": error,
                        "rms_rel": (error[spec["focus"]]["rms_rel"]
                                    if "focus" in spec else
                                    max(e["rms_rel"] for e in error.values())),
                        "error_of": spec.get("focus", "max over buffers"),
                        "max_abs": max(e["max_abs"] for e in error.values()),
                        "finite": all_finite(dump, buffers),
                    }
                    if scene == "kepler":
                        row.update(kepler_drift(dump, 0.6))
                    if scene == "nbody":
                        energy = nbody_energy(dump, 0.05)[0]
                        e0 = meta["energy0"][0]
                        row["energy_drift"] = abs(energy - e0) / abs(e0)
                    results.append(row)
                    print("run %s %s %s%s: %d big steps, %s, rms-rel %.3e" % (
                        scene, row["interp"], strategy,
                        "".join(" %s=%s" % kv for kv in extra.items()),
                        row["big_steps"],
                        "finite" if row["finite"] else "NOT FINITE",
                        row["rms_rel"]), flush=True)


def convergence(args):
    levels = 3 if args.quick else 5
    end = 0.25 if args.quick else 1.0
    dt0, c0 = 1.0e-3, 4.0e-2
    sets0 = {"range": "64"} if args.quick else {}
    out = {}
    for interp in ["linear", "cubic", "hermite"]:
        simb = build_bundle(args, "harmonic", interp)
        points = []
        for level in range(levels):
            dt = dt0 / 2 ** level
            steps = int(round(end / dt))
            sets = dict(sets0, dt=repr(dt), c=repr(c0 * dt / dt0))
            dump = os.path.join(args.out, "runs",
                                "convergence-%s-%d" % (interp, level))
            log("convergence %s dt %g" % (interp, dt))
            run = sim_run(args, simb, "hip", steps, sets, dump, "exact")
            points.append({"dt": dt, "steps": steps,
                           "error_Y": run["error"]["Y"]["max_abs"],
                           "error_X": run["error"]["X"]["max_abs"]})
        xs = [math.log(p["dt"]) for p in points]
        ys = [math.log(max(p["error_Y"], 1e-300)) for p in points]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        slope = (sum((x - mx) * (y - my) for x, y in zip(xs, ys)) /
                 sum((x - mx) ** 2 for x in xs))
        out[interp] = {"points": points, "slope": slope}
        print("convergence harmonic hip %s: slope %.2f (error of Y %s)" % (
            interp, slope, ", ".join("%.2e" % p["error_Y"] for p in points)),
            flush=True)
    return out


# The lts convergence runs: the first dt, the base steps there, the --set
# values and the CFL fraction @cfl at the first dt, full and --quick.
LTS_CONVERGENCE = {
    # 1024 cells at the quick dt 4e-7: the stiff half takes 1 base step.
    "heat_rod": dict(full=(2.0e-8, 1024, {}, 0.4),
                     quick=(4.0e-7, 128, {"range": "1024"}, 0.4)),
    "heat_rod_flux": dict(full=(2.0e-8, 1024, {}, 0.4),
                          quick=(4.0e-7, 128, {"range": "1024"}, 0.4)),
    # The default 1024 cells: the stiff middle takes 1 base step, the rest 8.
    "wave_rod": dict(full=(6.0e-5, 1000, {}, 0.5),
                     quick=(6.0e-5, 100, {}, 0.5)),
    "wave_staggered": dict(full=(6.0e-5, 1000, {}, 0.5),
                           quick=(6.0e-5, 100, {}, 0.5)),
}


def lts_convergence(args, scenes):
    """The order of lts on `scenes` (forward Euler on the heat rods and
    symplectic Euler on the wave rods: 1, Model.md "Accuracy and stability
    we expect"), and its error against simple's at each dt. dt and the CFL
    fraction halve together, so every block keeps its sub-step in base
    steps (1 in the stiff region, max_steps elsewhere) and every physical
    step halves; the reference is simple at the finest dt / FINE, at the
    same end time."""
    levels = 3 if args.quick else 4
    out = {}
    for scene in scenes:
        dt0, steps0, sets0, cfl0 = LTS_CONVERGENCE[scene][
            "quick" if args.quick else "full"]
        simb = build_bundle(args, scene, None)
        finest = dt0 / 2 ** (levels - 1)
        fine = os.path.join(args.out, "runs", "lts-convergence-%s-fine" % scene)
        log("lts convergence %s: reference simple at dt %g" %
            (scene, finest / FINE))
        sim_run(args, simb, "simple", steps0 * 2 ** (levels - 1) * FINE,
                dict(sets0, dt=repr(finest / FINE)), fine)
        reference = read_npy(os.path.join(fine, "U.npy"))[1]
        points = []
        for level in range(levels):
            dt = dt0 / 2 ** level
            steps = steps0 * 2 ** level
            sets = dict(sets0, dt=repr(dt), cfl=repr(cfl0 / 2 ** level))
            point = {"dt": dt, "steps": steps}
            for strategy in ["simple", "lts"]:
                dump = os.path.join(args.out, "runs", "lts-convergence-%s-%s-%d"
                                    % (scene, strategy, level))
                log("lts convergence %s %s dt %g" % (scene, strategy, dt))
                run = sim_run(args, simb, strategy, steps, sets, dump)
                u = read_npy(os.path.join(dump, "U.npy"))[1]
                point["error_" + strategy] = compare(u, reference)["max_abs"]
                point["evaluations_" + strategy] = sum(
                    run["evaluations"].values())
            points.append(point)
        xs = [math.log(p["dt"]) for p in points]
        ys = [math.log(max(p["error_lts"], 1e-300)) for p in points]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        slope = (sum((x - mx) * (y - my) for x, y in zip(xs, ys)) /
                 sum((x - mx) ** 2 for x in xs))
        ratio = max(p["error_lts"] / p["error_simple"] for p in points)
        fewer = min(p["evaluations_simple"] / p["evaluations_lts"]
                    for p in points)
        out[scene] = {"points": points, "slope": slope,
                      "largest_error_ratio": ratio}
        print("convergence %s lts: slope %.2f, error at most %.2fx simple's, "
              "%.2fx fewer evaluations (error %s)" % (
                  scene, slope, ratio, fewer,
                  ", ".join("%.2e" % p["error_lts"] for p in points)),
              flush=True)
    return out


def lts_convergence_scenes(args):
    """The scenes of the lts convergence study: the heat rods with heat_rod,
    the wave rod with wave_rod, the staggered wave with wave_staggered, all
    with --convergence-only."""
    scenes = []
    if args.convergence_only or "heat_rod" in args.scenes:
        scenes += ["heat_rod", "heat_rod_flux"]
    if args.convergence_only or "wave_rod" in args.scenes:
        scenes.append("wave_rod")
    if args.convergence_only or "wave_staggered" in args.scenes:
        scenes.append("wave_staggered")
    return scenes


# --- output ----------------------------------------------------------------

def fmt(x):
    return "%.2e" % x


def markdown(results, conv, command, lts_conv=None):
    lines = ["# Accuracy study", "", "Command: `%s`" % command, ""]
    for scene in dict.fromkeys(r["scene"] for r in results):
        rs = [r for r in results if r["scene"] == scene]
        extra = [k for k in ["energy_drift", "angular_momentum_drift"]
                 if k in rs[0]]
        lines += ["## %s (error against %s, %d items, %d base steps of %g)" % (
            scene, rs[0]["reference"], rs[0]["range"], rs[0]["steps"],
            rs[0]["dt"]), ""]
        head = ["interp", "strategy", "settings", "wall ms", "evaluations",
                "big steps", "max-abs", "rms-rel per buffer"] + [
                    k.replace("_", " ") for k in extra]
        lines.append("| " + " | ".join(head) + " |")
        lines.append("|" + " --- |" * len(head))
        for r in rs:
            cells = [r["interp"], r["strategy"],
                     " ".join("%s=%s" % kv for kv in r["settings"].items())
                     or "-",
                     "%.2f" % (1e3 * r["wall_seconds"]),
                     " ".join("%s %d" % kv for kv in r["evaluations"].items()),
                     str(r["big_steps"]), fmt(r["max_abs"]),
                     " ".join("%s %s" % (name, fmt(e["rms_rel"]))
                              for name, e in sorted(r["error"].items()))] + [
                         fmt(r[k]) for k in extra]
            if not r["finite"]:
                cells[1] += " (NOT FINITE)"
            lines.append("| " + " | ".join(cells) + " |")
        lines.append("")
    if conv:
        lines += ["## Convergence (harmonic, hip, error of @Y against exact)",
                  "", "| interp | " + " | ".join(
                      "dt %g" % p["dt"] for p in next(iter(conv.values()))[
                          "points"]) + " | slope |",
                  "|" + " --- |" * (2 + len(next(iter(conv.values()))[
                      "points"]))]
        for interp, c in conv.items():
            lines.append("| %s | %s | %.2f |" % (interp, " | ".join(
                fmt(p["error_Y"]) for p in c["points"]), c["slope"]))
        lines.append("")
    if lts_conv:
        first = next(iter(lts_conv.values()))["points"]
        lines += ["## Convergence of lts (max-abs error of @U against "
                  "simple at dt/%d, dt and cfl halved together)" % FINE, "",
                  "| scene | strategy | dt0 | " + " | ".join(
                      "dt0 / %d" % 2 ** k if k else "error at dt0"
                      for k in range(len(first))) + " | slope |",
                  "|" + " --- |" * (4 + len(first))]
        for scene, c in lts_conv.items():
            for strategy in ["simple", "lts"]:
                lines.append("| %s | %s | %g | %s | %s |" % (
                    scene, strategy, c["points"][0]["dt"], " | ".join(
                        fmt(p["error_" + strategy]) for p in c["points"]),
                    "%.2f" % c["slope"] if strategy == "lts" else "-"))
        lines.append("")
    return "\n".join(lines)


def plot(results, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        log("matplotlib is not installed: no plot")
        return False
    scenes = list(dict.fromkeys(r["scene"] for r in results))
    cols = min(3, len(scenes))
    nrows = (len(scenes) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(5 * cols, 4 * nrows),
                             squeeze=False)
    markers = dict(zip(STRATEGIES, itertools.cycle("os^vDp")))
    for k, scene in enumerate(scenes):
        ax = axes[k // cols][k % cols]
        for r in (r for r in results if r["scene"] == scene):
            if r["rms_rel"] <= 0:
                continue  # the reference itself (pbd's simple)
            label = r["strategy"] + ("" if r["interp"] == "-" else
                                     " " + r["interp"]) + "".join(
                " %s=%s" % kv for kv in r["settings"].items())
            ax.loglog(r["rms_rel"], 1e3 * r["wall_seconds"],
                      markers[r["strategy"]], label=label, alpha=0.8)
        first = next(r for r in results if r["scene"] == scene)
        ax.set_title("%s (vs %s)" % (scene, first["reference"]))
        ax.set_xlabel("error (rms-rel, %s)" % (
            "@" + first["error_of"] if first["error_of"] in first["error"]
            else first["error_of"]))
        ax.tick_params(axis="x", which="minor", labelsize=6,
                       labelrotation=45)
        ax.set_ylabel("wall time (ms, fastest run)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6)
    for k in range(len(scenes), nrows * cols):
        axes[k // cols][k % cols].axis("off")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return True


def main():
    parser = Parser(
        prog=PROG,
        description="Run the physics scenes of examples/physics with every "
        "strategy and interpolation and report time against error.")
    parser.add_argument("--backend", default="cpu",
                        choices=["cpu", "cuda", "auto"])
    parser.add_argument("--scenes", default=",".join(SCENES),
                        help="comma-separated (default: %(default)s)")
    parser.add_argument("--out", default="accuracy-out",
                        help="output folder (default: %(default)s)")
    parser.add_argument("--quick", action="store_true",
                        help="small ranges and few steps (for CI)")
    parser.add_argument("--no-convergence", action="store_true",
                        help="skip the convergence study")
    parser.add_argument("--convergence-only", action="store_true")
    parser.add_argument("--repeat", type=int, default=1,
                        help="sim-run --repeat, 1 to 100000: the tables and "
                        "the plot take the fastest run's wall time (default "
                        "1)")
    parser.add_argument("--group-size", type=int, default=32,
                        help="threads per group, a multiple of 32 from 32 to "
                        "1024 (to 4096 on the cpu backend; default 32: hip "
                        "sub-steps a group by its smallest num_steps)")
    parser.add_argument("--check-finite", action="store_true",
                        help="pass --check-finite to sim-run (slower)")
    parser.add_argument("--scenes-dir",
                        default=os.path.join(ROOT, "examples", "physics"))
    parser.add_argument("--replot", metavar="RESULTS_JSON",
                        help="only redraw OUT/accuracy.png from a results.json")
    parser.add_argument("--sim-run")
    parser.add_argument("--sim-translate")
    args = parser.parse_args()
    args.scenes = [s.strip() for s in args.scenes.split(",") if s.strip()]
    if not args.scenes and not args.convergence_only:
        parser.error("--scenes selects no scene (known: %s)" %
                     ", ".join(SCENES))
    for s in args.scenes:
        if s not in SCENES:
            parser.error("unknown scene %s (known: %s)" % (s, ", ".join(
                SCENES)))
    if not 1 <= args.repeat <= 100000:
        parser.error("--repeat takes a number of runs from 1 to 100000, not "
                     "%d" % args.repeat)
    most = 4096 if args.backend == "cpu" else 1024
    if not (32 <= args.group_size <= most and args.group_size % 32 == 0):
        parser.error("--group-size takes a multiple of 32 (a warp) from 32 "
                     "to %d%s, not %d" % (
                         most, "" if args.backend == "cpu" else
                         " (4096 on the cpu backend)", args.group_size))
    if args.replot:
        results = read_results(args.replot)
        make_out_folder(args.out)
        path = os.path.join(args.out, "accuracy.png")
        try:
            drawn = plot(results, path)
        except (KeyError, TypeError, ValueError) as error:
            fail("--replot %s: a result lacks %s (not a results.json of "
                 "accuracy_study.py?)" % (args.replot, error), 2)
        if drawn:
            log("wrote %s" % path)
        return 0
    if not os.path.isdir(args.scenes_dir):
        parser.error("--scenes-dir %s is not a folder" % args.scenes_dir)
    needed = [] if args.convergence_only else list(args.scenes)
    if not args.no_convergence:
        if args.convergence_only or "harmonic" in args.scenes:
            needed.append("harmonic")
        needed += lts_convergence_scenes(args)
    missing = [scene + ".mlir" for scene in dict.fromkeys(needed)
               if not os.path.isfile(os.path.join(args.scenes_dir,
                                                  scene + ".mlir"))]
    if missing:
        parser.error("--scenes-dir %s has no %s" % (args.scenes_dir,
                                                    ", ".join(missing)))
    args.sim_run = find_tool("sim-run", args.sim_run)
    args.sim_translate = find_tool("sim-translate", args.sim_translate)
    make_out_folder(args.out)
    command = "python3 python/accuracy_study.py " + " ".join(
        a for a in sys.argv[1:])
    start = time.time()
    results = []
    if not args.convergence_only:
        study(args, results)
    conv = None
    if not args.no_convergence and (args.convergence_only or
                                    "harmonic" in args.scenes):
        conv = convergence(args)
    lts_conv = None
    if not args.no_convergence and lts_convergence_scenes(args):
        lts_conv = lts_convergence(args, lts_convergence_scenes(args))
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump({"command": command, "backend": args.backend,
                   "results": results, "convergence": conv,
                   "lts_convergence": lts_conv}, f, indent=1)
    with open(os.path.join(args.out, "results.md"), "w") as f:
        f.write(markdown(results, conv, command, lts_conv))
    if results and plot(results, os.path.join(args.out, "accuracy.png")):
        log("wrote %s" % os.path.join(args.out, "accuracy.png"))
    log("wrote %s/results.md and results.json in %.1f s" % (
        args.out, time.time() - start))
    bad = [r for r in results if not r["finite"]]
    print("done: %d runs, %d not finite" % (len(results), len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
