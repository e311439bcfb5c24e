"""The command line of the examples: print, save, compile or run a scene.

    python3 python/examples/kepler.py                      # the scene's MLIR
    python3 python/examples/kepler.py -o kepler.mlir       # ... into a file
    python3 python/examples/kepler.py --run 6283 --output-every 500 \\
        --strategy hip --output kepler.npz                  # run, save outputs
"""

import argparse

import sim


def main(scene, argv=None):
    parser = argparse.ArgumentParser(description=f"the {scene.name} scene")
    parser.add_argument("-o", "--mlir", metavar="FILE",
                        help="write the scene's MLIR text to FILE")
    parser.add_argument("--run", type=int, metavar="STEPS",
                        help="compile and run STEPS base steps")
    parser.add_argument("--strategy", default="hip")
    parser.add_argument("--backend", default="auto")
    parser.add_argument("--set", action="append", default=[],
                        metavar="NAME=VALUE", help="range, dt or a parameter")
    parser.add_argument("--output-every", type=int, metavar="N")
    parser.add_argument("--output", metavar="FILE.npz")
    args = parser.parse_args(argv)
    if args.run is not None and args.run < 0:
        parser.error(f"--run takes a number of base steps >= 0, not "
                     f"{args.run}")
    if args.output_every is not None and args.output_every < 1:
        parser.error(f"--output-every takes a number of base steps >= 1, "
                     f"not {args.output_every}")
    for item in args.set:
        if "=" not in item or not item.split("=", 1)[0]:
            parser.error(f"--set takes NAME=VALUE, not {item!r}")
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
    session = bundle.session(args.strategy, args.backend, **values)
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
