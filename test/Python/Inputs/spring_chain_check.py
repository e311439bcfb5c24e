"""python/examples/spring_chain.py under lts: the blocks of the soft
springs take longer sub-steps than hip's grid-wide ones, reading their
neighbours' Hermite positions through the time levels; the CPU backend
equals the reference executor bit for bit, and the energy holds."""
import os
import sys

sys.path.insert(0, os.path.join(os.environ["SIM_SRC_ROOT"], "python",
                                "examples"))
import numpy as np  # noqa: E402
import sim  # noqa: E402
from spring_chain import scene  # noqa: E402

bundle = sim.compile(scene, strategies=["simple", "hip", "lts"])
for strategy in ["simple", "hip", "lts"]:
    session = bundle.session(strategy, backend="cpu")
    before = session.totals()["Energy"]
    session.run(256)
    after = session.totals()["Energy"]
    print(f"{strategy}: evaluations {session.metrics()['evaluations']['Step']}, energy "
          f"within 1e-4: {abs(after - before) <= 1e-4 * before}")

cpu = bundle.session("lts", backend="cpu")
reference = bundle.session("lts", backend="reference")
cpu.run(48)
reference.run(48)
print("lts cpu equals reference:",
      bool(np.array_equal(cpu["X"], reference["X"])) and
      bool(np.array_equal(cpu["V"], reference["V"])))
