"""A Python example scene equals its .mlir version bit for bit.

    examples_equal.py NAME SCENE.mlir --steps N --set range=R [--set ...]
                      [--opt-level L]

Compiles python/examples/NAME.py (traced with the sim package) and
SCENE.mlir into bundles, runs every strategy on the CPU backend: the Python
bundle through sim.Session, the .mlir bundle through `sim-run --dump`, and
compares the observed buffers byte for byte (and, through the runtime, the
totals and the exact solutions). Prints one line per strategy; exits 1 on
the first difference.
"""
import argparse
import importlib
import os
import subprocess
import sys
import tempfile

import numpy as np

import sim
import simlists

parser = argparse.ArgumentParser()
parser.add_argument("name")
parser.add_argument("mlir")
parser.add_argument("--steps", type=int, required=True)
parser.add_argument("--set", action="append", default=[])
parser.add_argument("--opt-level", type=int,
                    help="--sim-opt-level of both compilations (default: "
                         "the compiler's)")
args = parser.parse_args()
# Both bundles run here only: CPU kernels for this machine's level.
translate_args = ["--sim-cpu-isas=host"] + (
    [] if args.opt_level is None else [f"--sim-opt-level={args.opt_level}"])
values = dict(item.split("=", 1) for item in args.set)

sys.path.insert(0, os.path.join(os.path.dirname(sim.__file__), "..",
                                "examples"))
scene = importlib.import_module(args.name).scene
ours = sim.compile(scene, args=translate_args)
sim_run = sim.find_tool("sim-run")
failed = False
with tempfile.TemporaryDirectory() as tmp:
    theirs_path = os.path.join(tmp, "theirs.simb")
    subprocess.run([sim.find_tool("sim-translate"), args.mlir,
                    "--sim-to-bundle", "-o", theirs_path, *translate_args],
                   check=True, stderr=subprocess.DEVNULL)
    theirs = sim.Bundle(theirs_path)
    assert ours.observed == theirs.observed, (ours.observed, theirs.observed)
    for strategy in simlists.STRATEGIES:
        session = ours.session(strategy, "cpu", **values)
        initial = session.buffers()
        session.run(args.steps)
        mine = session.buffers()
        dump = os.path.join(tmp, strategy)
        command = [sim_run, theirs_path, "--backend", "cpu", "--strategy",
                   strategy, "--steps", str(args.steps), "--dump", dump]
        for item in args.set:
            command += ["--set", item]
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        report = []
        for name, array in mine.items():
            reference = np.load(os.path.join(dump, name + ".npy"))
            same = (reference.dtype == array.dtype and
                    reference.shape == array.shape and
                    reference.tobytes() == array.tobytes())
            moved = float(np.max(np.abs(array.astype(np.float64) -
                                        initial[name])))
            report.append(f"{name} {'equal' if same else 'DIFFERENT'} "
                          f"{array.dtype} {array.shape}"
                          + (" (changed)" if moved > 0 else " (UNCHANGED)"))
            failed |= not same or moved == 0
        # Totals and exact solutions through the runtime.
        other = theirs.session(strategy, "cpu", **values)
        other.run(args.steps)
        for name, value in session.totals().items():
            same = value == other.totals()[name]
            report.append(f"total {name} {'equal' if same else 'DIFFERENT'}")
            failed |= not same
        for name in mine:
            if session.info(name).exact:
                same = session.exact(name).tobytes() == \
                    other.exact(name).tobytes()
                report.append(f"exact {name} "
                              f"{'equal' if same else 'DIFFERENT'}")
                failed |= not same
        print(f"{args.name} {strategy}: " + ", ".join(report))
        sys.stdout.flush()
print(f"compile {ours.compile_seconds:.1f} s")
sys.exit(1 if failed else 0)
