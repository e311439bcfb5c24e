"""Local time steps after Session.set: a component whose num_steps reads
only parameters and dt keeps its blocks' levels (invariant_levels), and the
writer of a pair with such a reader keeps its largest estimate
(keeps_estimate); a set of a parameter or dt (max_steps is fixed when a
scene is compiled) must make the next run compute them again.

The scene runs 128 base steps, then the parameters given (or dt) change
and it runs 1024 more: the CPU backend must equal the reference executor
bit for bit, with the same evaluations of COMPONENT and the same big
steps, and stay bounded. For the heat rod of examples/physics the soft
half becomes ten times more conductive (its stable step drops from 119 to
11 base steps); before the fix the CPU kept the old levels and blew up.
For its flux form every interface becomes stiff, so the flux writer's
largest estimate, which bounded nothing, now bounds the big step. For
Integration/Inputs/local-unit.mlir the finest num_steps, the unit of every
sub-step, rises from 3 to 5: a unit kept from the first run would step
the blocks otherwise (docs/Model.md, "Levels")."""
import argparse

import numpy as np
import sim

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("scene", help="a scene (.mlir) with an lts strategy")
parser.add_argument("--component", default="Conduct",
                    help="the component whose evaluations are compared")
parser.add_argument("--set", dest="changes", action="append", default=[],
                    metavar="NAME=VALUE",
                    help="a parameter the second run changes (repeatable; "
                         "default k_soft=0.1 and ratio=10)")
args = parser.parse_args()
params = dict(change.split("=", 1) for change in args.changes) or \
    dict(k_soft="0.1", ratio="10")

bundle = sim.compile(open(args.scene).read(), strategies="lts")
def number(text):
    """An integer parameter's value as an int, any other as a float."""
    try:
        return int(text)
    except ValueError:
        return float(text)


changes = [("params", {name: number(value) for name, value in params.items()}),
           ("dt", dict(dt=1.0e-8))]
for label, change in changes:
    results = {}
    for backend in ("cpu", "reference"):
        session = bundle.session("lts", backend=backend)
        session.run(128)
        session.set(**change)
        session.run(1024)
        metrics = session.metrics()
        results[backend] = (session["U"].copy(),
                            metrics["evaluations"][args.component],
                            metrics["big_steps"])
    cpu, reference = results["cpu"], results["reference"]
    print(f"{label}: equal {np.array_equal(cpu[0], reference[0])} "
          f"evaluations equal {cpu[1] == reference[1]} "
          f"big steps equal {cpu[2] == reference[2]} "
          f"bounded {bool(np.all(np.abs(cpu[0]) <= 2.0))}")
