#!/usr/bin/env python3
"""Checks a backend against the reference executor over the cross-check matrix.

The matrix is test/Integration/crosscheck-matrix.json (its "about" says what
each field means): suites of scenes, each with its source, setting variants
and ranges. Both commands take the scenes of the suites named with --suite
(default: every suite) that run on --backend (default: cpu).

  compile  translates every scene into BUNDLES/NAME.simb with sim-translate
           --sim-to-bundle --sim-group-size=G [--sim-cpu-isas=LEVELS] (through sim-opt
           --sim-set-params first when the scene has `params`).
  run      for every scene, strategy (python/simlists.py), range and
           variant, runs

             sim-run BUNDLES/NAME.simb --backend B --strategy S --steps N
                     --set range=R [--set K=V]... --group-size G --check
                     [--check-tolerance X] --json OUT/CASE.json

`sim-run --check` runs the scene on backend B and on the reference executor
(docs/Reference.md) side by side and fails when a buffer differs by more than
the tolerance or when the evaluation counts or big-step sizes differ. Every
case prints one line; the last line is a summary. Exits with 1 when a case
disagrees (after running them all, so that a planted bug shows its extent).

Usage:
  crosscheck.py compile --bundles DIR [--suite S]... [--backend B]
                [--sim-translate T] [--sim-opt O] [--matrix M] [--jobs J]
  crosscheck.py run --bundles DIR --out DIR [--suite S]... [--backend B]
                [--sim-run R] [--matrix M] [--jobs J]

Standard library only.
"""

import argparse
import concurrent.futures
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(ROOT, "python"))
from simlists import STRATEGIES  # noqa: E402

MATRIX = os.path.join(os.path.dirname(HERE), "crosscheck-matrix.json")
SCENE_KEYS = {"name", "source", "params", "variants", "ranges", "backends",
              "note"}


def parse_args():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--matrix", default=MATRIX)
    common.add_argument("--suite", action="append", default=[],
                        help="a suite of the matrix (repeatable; default: "
                             "every suite)")
    common.add_argument("--backend", default="cpu")
    common.add_argument("--bundles", required=True, metavar="DIR")
    common.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    compile_ = commands.add_parser("compile", parents=[common])
    compile_.add_argument("--sim-translate", default="sim-translate")
    compile_.add_argument("--sim-opt", default="sim-opt")
    compile_.add_argument("--cpu-isas", metavar="LEVELS",
                          help="--sim-cpu-isas of the bundles (default: "
                               "sim-translate's; host where they run on "
                               "the machine that compiles them)")
    run = commands.add_parser("run", parents=[common])
    run.add_argument("--sim-run", default="sim-run")
    run.add_argument("--out", required=True, metavar="DIR")
    return parser.parse_args()


def fail(message):
    sys.exit("crosscheck: error: " + message)


def load_matrix(path):
    """The matrix, its scenes checked for the fields that crosscheck.py
    knows, so that a misspelt one is not silently ignored."""
    matrix = json.load(open(path))
    names = set()
    for suite, scenes in matrix["suites"].items():
        for scene in scenes:
            unknown = set(scene) - SCENE_KEYS
            missing = {"name", "source", "variants"} - set(scene)
            if unknown or missing:
                fail("%s: a scene of suite %s has %s" % (
                    path, suite, "unknown fields %s" % sorted(unknown)
                    if unknown else "no %s" % sorted(missing)))
            if scene["name"] in names:
                fail("%s: two scenes are named %s" % (path, scene["name"]))
            names.add(scene["name"])
    return matrix


def selected_scenes(args, matrix):
    if args.backend not in matrix["backends"]:
        fail("backend %s is not in the matrix (%s)" %
             (args.backend, ", ".join(matrix["backends"])))
    for suite in args.suite or matrix["suites"]:
        if suite not in matrix["suites"]:
            fail("no suite %s in %s (it has %s)" % (
                suite, args.matrix, ", ".join(matrix["suites"])))
        for scene in matrix["suites"][suite]:
            if args.backend in scene.get("backends", matrix["backends"]):
                yield scene


def bundle_path(args, scene):
    return os.path.join(args.bundles, scene["name"] + ".simb")


def run_command(command, stdin=None, timeout=300):
    """(exit status, output) of a command; -1 when it did not finish."""
    try:
        result = subprocess.run(command, input=stdin, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, timeout=timeout)
        return result.returncode, result.stdout
    except subprocess.TimeoutExpired:
        return -1, b"timed out after %d s" % timeout


def compile_scene(args, matrix, scene):
    source = os.path.join(ROOT, scene["source"])
    translate = [args.sim_translate, "--sim-to-bundle",
                 "--sim-group-size=%d" % matrix["group_size"], "-o",
                 bundle_path(args, scene)]
    if args.cpu_isas:
        translate.append("--sim-cpu-isas=" + args.cpu_isas)
    if "params" not in scene:
        return run_command(translate + [source])
    opt = subprocess.run([args.sim_opt, source, "--sim-set-params=values=" +
                          scene["params"]], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    if opt.returncode:
        return opt.returncode, opt.stderr
    return run_command(translate, stdin=opt.stdout)


def compile_bundles(args, matrix):
    scenes = list(selected_scenes(args, matrix))
    os.makedirs(args.bundles, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = pool.map(lambda scene: compile_scene(args, matrix, scene),
                           scenes)
        failed = [(scene, output) for scene, (status, output)
                  in zip(scenes, results) if status]
    for scene, output in failed:
        print("cannot compile %s (%s):\n%s" % (
            scene["name"], scene["source"], output.decode(errors="replace")))
    print("compiled %d of %d scenes for %s into %s" % (
        len(scenes) - len(failed), len(scenes), args.backend, args.bundles))
    return 1 if failed else 0


def cases(args, matrix):
    for scene in selected_scenes(args, matrix):
        for strategy in STRATEGIES:
            for range_ in scene.get("ranges", matrix["ranges"]):
                for variant in scene["variants"]:
                    sets = [] if variant == "as-is" else variant.split(",")
                    yield scene, strategy, range_, sets


def run_case(args, matrix, case):
    scene, strategy, range_, sets = case
    name = scene["name"]
    tag = "%s.%s.r%d.%s" % (name, strategy, range_,
                            "_".join(s.replace("=", "") for s in sets) or "as-is")
    out = os.path.join(args.out, tag + ".json")
    command = [args.sim_run, bundle_path(args, scene), "--backend",
               args.backend, "--strategy", strategy, "--steps",
               str(matrix["steps"]), "--set", "range=%d" % range_,
               "--group-size", str(matrix["group_size"]), "--check", "--json",
               out]
    for s in sets:
        command += ["--set", s]
    tolerance = matrix["tolerance"].get(args.backend)
    if tolerance:
        command += ["--check-tolerance", tolerance]
    status, output = run_command(command)
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
    return (label, status, output.decode(errors="replace"), worst,
            " ".join(command))


def run_cases(args, matrix):
    os.makedirs(args.out, exist_ok=True)
    all_cases = list(cases(args, matrix))
    failures = 0
    worst = 0.0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for label, status, output, case_worst, command in pool.map(
                lambda case: run_case(args, matrix, case), all_cases):
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


def main():
    args = parse_args()
    matrix = load_matrix(args.matrix)
    if args.command == "compile":
        return compile_bundles(args, matrix)
    return run_cases(args, matrix)


if __name__ == "__main__":
    sys.exit(main())
