"""Local time steps after Session.set: a component whose num_steps reads
only parameters and dt keeps its blocks' levels (invariant_levels); a set
of a parameter or dt (max_steps is fixed when a scene is compiled)
must make the next run compute them again.
The heat rod of examples/physics runs 128 base steps, then its soft half
becomes ten times more conductive (its stable step drops from 119 to 11
base steps) and it runs 1024 more: the CPU backend must equal the
reference executor bit for bit, with the same evaluations, and stay
bounded. Before the fix the CPU kept the old levels and blew up."""
import sys

import numpy as np
import sim

bundle = sim.compile(open(sys.argv[1]).read(), strategies="lts")
changes = [("params", dict(k_soft=0.1, ratio=10.0)),
           ("dt", dict(dt=1.0e-8))]
for label, change in changes:
    results = {}
    for backend in ("cpu", "reference"):
        session = bundle.session("lts", backend=backend)
        session.run(128)
        session.set(**change)
        session.run(1024)
        results[backend] = (session["U"].copy(),
                            session.metrics()["evaluations"]["Conduct"])
    cpu, reference = results["cpu"], results["reference"]
    print(f"{label}: equal {np.array_equal(cpu[0], reference[0])} "
          f"evaluations equal {cpu[1] == reference[1]} "
          f"bounded {bool(np.all(np.abs(cpu[0]) <= 2.0))}")
