"""The command line of the examples: print, save, compile or run a scene.

    python3 python/examples/kepler.py                      # the scene's MLIR
    python3 python/examples/kepler.py -o kepler.mlir       # ... into a file
    python3 python/examples/kepler.py --run 6283 --output-every 500 \\
        --strategy hip --output kepler.npz                  # run, save outputs

Mistakes in the arguments (an unknown strategy, backend or parameter, a
range out of bounds, an output that is a folder, --output without
--output-every) are usage errors, one line and status 2, found before the
scene is compiled where they can be; what fails later (compiling, the
runtime) ends the run with one `error:` line and status 1.
"""

import argparse
import math
import os
import sys

import sim
import simrt
from simlists import STRATEGIES

# simrt's backends (sim-run --backend).
BACKENDS = ("auto", "cpu", "cuda", "reference")


class Parser(argparse.ArgumentParser):
    """argparse whose usage errors are one line (and status 2), as the sim
    tools print theirs."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} "
                     f"--help)\n")


def check_output_file(parser, option, path):
    """A usage error unless `path` can be a file (not a folder, in a folder
    that exists)."""
    if os.path.isdir(path):
        parser.error(f"{option} {path} is a folder, not a file")
    folder = os.path.dirname(path) or "."
    if not os.path.isdir(folder):
        parser.error(f"{option} {path}: no folder {folder}")


def check_sets(parser, scene, items):
    """Checks --set's names (range, dt and the scene's parameters) and the
    values it can before compiling; the runtime checks the rest."""
    known = ["range", "dt"] + [p.name for p in scene.params
                               if p.name not in ("range", "dt", "max_steps")]
    for item in items:
        name, _, value = item.partition("=")
        if "=" not in item or not name:
            parser.error(f"--set takes NAME=VALUE, not {item!r}")
        if name not in known:
            parser.error(f"--set: {name!r} is not range, dt or a parameter "
                         f"of scene {scene.name!r} (parameters: "
                         f"{', '.join(known[2:]) or 'none'})")
        if name == "range":
            try:
                ok = 1 <= int(value, 0) <= 2 ** 40
            except ValueError:
                ok = False
            if not ok:
                parser.error(f"--set range: {value!r} is not a number of "
                             f"items from 1 to 2^40")
        if name == "dt":
            try:
                ok = 0 < float(value) < math.inf
            except ValueError:
                ok = False
            if not ok:
                parser.error(f"--set dt: {value!r} is not a finite number "
                             f"> 0")


def main(scene, argv=None):
    parser = Parser(description=f"the {scene.name} scene")
    parser.add_argument("-o", "--mlir", metavar="FILE",
                        help="write the scene's MLIR text to FILE")
    parser.add_argument("--run", type=int, metavar="STEPS",
                        help="compile and run STEPS base steps")
    parser.add_argument("--strategy", default="hip", choices=STRATEGIES,
                        help=f"{', '.join(STRATEGIES)} (default hip)")
    parser.add_argument("--backend", default="auto", choices=BACKENDS,
                        help=f"{', '.join(BACKENDS)} (default auto)")
    parser.add_argument("--set", action="append", default=[],
                        metavar="NAME=VALUE", help="range, dt or a parameter")
    parser.add_argument("--output-every", type=int, metavar="N",
                        help="with --run: an output every N base steps and "
                             "at the end")
    parser.add_argument("--output", metavar="FILE.npz",
                        help="with --run and --output-every: write the "
                             "outputs into FILE.npz")
    args = parser.parse_args(argv)
    if args.run is not None and args.run < 0:
        parser.error(f"--run takes a number of base steps >= 0, not "
                     f"{args.run}")
    if args.output_every is not None and args.output_every < 1:
        parser.error(f"--output-every takes a number of base steps >= 1, "
                     f"not {args.output_every}")
    check_sets(parser, scene, args.set)
    if args.run is None:
        for option in ("--set", "--output-every", "--output"):
            if getattr(args, option[2:].replace("-", "_")):
                parser.error(f"{option} needs --run (it is about a run)")
    if args.output and args.output_every is None:
        # As sim-run: the output times are --output-every's.
        parser.error("--output needs --output-every (the output times)")
    if args.output:
        check_output_file(parser, "--output", args.output)
    if args.mlir and args.run is None:
        check_output_file(parser, "-o/--mlir", args.mlir)
    try:
        run(scene, args)
    except (sim.SimError, simrt.Error) as error:
        sys.exit(f"{parser.prog}: error: {error}")
    except OSError as error:
        sys.exit(f"{parser.prog}: error: " + (
            f"{error.filename}: {error.strerror}"
            if error.filename and error.strerror else str(error)))


def run(scene, args):
    if args.run is None:
        text = scene.mlir()
        if args.mlir:
            with open(args.mlir, "w") as f:
                f.write(text)
        else:
            print(text, end="")
        return
    bundle = sim.compile(scene, strategies=[args.strategy])
    print(f"compiled {scene.name} in {bundle.compile_seconds:.2f} s")
    values = dict(item.split("=", 1) for item in args.set)
    # params=: a --set of a parameter named like a session option (threads)
    # sets the parameter.
    session = bundle.session(args.strategy, args.backend, params=values)
    # One output at the end unless asked for more (a run of 0 steps has
    # only the initial state).
    out = session.run(args.run,
                      output_every=args.output_every or max(args.run, 1),
                      errors=True)
    metrics = session.metrics()
    print(f"{args.strategy} on {metrics['device']}: {args.run} base steps in "
          f"{metrics['big_steps']} big steps, {metrics['wall_seconds']:.3f} s")
    for name, values in out.totals.items():
        print(f"  total {name}: {values[0]:.9e} -> {values[-1]:.9e}")
    for name, norms in out.errors.items():
        print(f"  error {name}: max-abs {norms['max_abs'][-1]:.3e} rms-rel "
              f"{norms['rms_rel'][-1]:.3e}")
    if args.output:
        out.save(args.output)
        print(f"wrote {args.output}")
