"""Totals from Python (simrt.Session.totals) on the CPU and the reference
executor, at T = 0 against the value computed here, and after a run."""
import sys

import simrt

# At T = 0 every x is 1 and every v 0: E = sum of 0.5 w^2, w = 1 + i / 64.
expected = sum(0.5 * (1 + i / 64) ** 2 for i in range(64))
with simrt.Bundle(sys.argv[1]) as bundle:
    totals = {}
    for backend in ("cpu", "reference"):
        with simrt.Session(bundle, strategy="hip", backend=backend) as session:
            session.init()
            start = session.totals()
            print(backend, "initial energy matches",
                  abs(start["Energy"] - expected) <= 1e-12 * expected,
                  "momentum", start["Momentum"])
            session.run(100)
            totals[backend] = session.totals()
    print("names", sorted(totals["cpu"]))
    print("cpu equals reference",
          all(abs(totals["cpu"][name] - totals["reference"][name]) <= 1e-12
              * max(1.0, abs(totals["reference"][name]))
              for name in totals["cpu"]))
