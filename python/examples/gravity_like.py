"""gravity_like: the paper's gravity-like scene (Section 5.1, Fig. 9) in Python.

The Python version of examples/paper/gravity_like.mlir, with the same
numbers bit for bit (test/Python/examples-equal.test): C0 computes
particle-specific information from its own state and the result of the
previous step (B2 through the back edge), C1 sums the 9 neighbouring items
of B0 for C2, and C2 reads the neighbourhoods of B0 and B1 and updates the
items. B2 is observed.

    python3 python/examples/gravity_like.py            # prints the scene
    python3 python/examples/gravity_like.py --run 20   # runs it (CPU)
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                ".."))
import sim  # noqa: E402
from paper_common import (VEC4F, init_value, matrix_load, relax,  # noqa: E402
                          step_count, two_more_rows, window_means)

scene = sim.Scene("gravity_like", range=65536, dt=1.0e-3, max_steps=3)
scene.param("L", 8)        # rounds of the 4x4 matrix product (the load)
scene.param("dist", 0)     # step counts: 0 per component, 1 per group, 2 per item
scene.param("group", 32)   # items per group when dist = 1

B0 = scene.buffer(VEC4F, name="B0")(init_value(0))
B1 = scene.buffer(VEC4F, name="B1")(init_value(1))
B2 = scene.buffer(VEC4F, name="B2")(init_value(2))


@scene.component(writes=B0, num_steps=step_count(scene, 0))
def C0(i, n, dt):
    state = B0[i]
    b2 = B2[i]                 # through the back edge: the value at T
    rows = [b2, state] + two_more_rows(b2, state)
    return relax(state, matrix_load(scene, rows), n, dt)


@scene.component(writes=B1, num_steps=step_count(scene, 1))
def C1(i, n, dt):
    (mean,) = window_means(i, [B0])
    rows = [mean, B0[i], B0[i - 1], B0[i + 1]]
    return relax(None, matrix_load(scene, rows), n, dt)


@scene.component(writes=B2, num_steps=step_count(scene, 2))
def C2(i, n, dt):
    state = B2[i]
    mean0, mean1 = window_means(i, [B0, B1])
    rows = [mean0, mean1, B0[i], B1[i]]
    return relax(state, matrix_load(scene, rows), n, dt)


scene.schedule(C0)
scene.observe(B2)

if __name__ == "__main__":
    from run_example import main
    main(scene)
