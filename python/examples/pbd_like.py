"""pbd_like: the paper's PBD-like scene (Section 5.2, Fig. 10) in Python.

The Python version of examples/paper/pbd_like.mlir, with the same numbers
bit for bit (test/Python/examples-equal.test). C0 predicts positions from
its own state and the result of the previous step (B6 through the back
edge); C1 accumulates neighbourhood information for an imaginary collision
detection in C2; C3 and C4 are SPH-like sums over the neighbours, C5 reads
the neighbourhoods of B4 and B3, and C6 updates the items from B5. B3 and B4
use the paper's cubic interpolation, the others linear. B6 is observed.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                ".."))
import sim  # noqa: E402
from paper_common import (VEC4F, init_value, matrix_load, relax,  # noqa: E402
                          step_count, two_more_rows, window_means)

scene = sim.Scene("pbd_like", range=65536, dt=1.0e-3, max_steps=3)
scene.param("L", 8)        # rounds of the 4x4 matrix product (the load)
scene.param("dist", 0)     # step counts: 0 per component, 1 per group, 2 per item
scene.param("group", 32)   # items per group when dist = 1

INTERP = {"B3": "cubic", "B4": "cubic"}
B = [scene.buffer(VEC4F, name=f"B{k}", interp=INTERP.get(f"B{k}", "linear"))(
    init_value(k)) for k in range(7)]


def neighbourhood(i, buffer):
    """The rows of a component that reads one buffer in a window."""
    (mean,) = window_means(i, [buffer])
    return [mean, buffer[i], buffer[i - 1], buffer[i + 1]]


@scene.component(writes=B[0], num_steps=step_count(scene, 0))
def C0(i, n, dt):
    state = B[0][i]
    b6 = B[6][i]               # through the back edge: the value at T
    rows = [b6, state] + two_more_rows(b6, state)
    return relax(state, matrix_load(scene, rows), n, dt)


@scene.component(writes=B[1], num_steps=step_count(scene, 1))
def C1(i, n, dt):
    return relax(None, matrix_load(scene, neighbourhood(i, B[0])), n, dt)


@scene.component(writes=B[2], num_steps=step_count(scene, 2))
def C2(i, n, dt):
    b0 = B[0][i]
    (mean,) = window_means(i, [B[1]])
    rows = [mean, B[1][i], b0, B[1][i - 1]]
    return relax(None, matrix_load(scene, rows), n, dt)


@scene.component(writes=B[3], num_steps=step_count(scene, 3))
def C3(i, n, dt):
    return relax(None, matrix_load(scene, neighbourhood(i, B[2])), n, dt)


@scene.component(writes=B[4], num_steps=step_count(scene, 4))
def C4(i, n, dt):
    return relax(None, matrix_load(scene, neighbourhood(i, B[3])), n, dt)


@scene.component(writes=B[5], num_steps=step_count(scene, 5))
def C5(i, n, dt):
    mean4, mean3 = window_means(i, [B[4], B[3]])
    rows = [mean4, mean3, B[4][i], B[3][i]]
    return relax(None, matrix_load(scene, rows), n, dt)


@scene.component(writes=B[6], num_steps=step_count(scene, 6))
def C6(i, n, dt):
    state = B[6][i]
    (mean,) = window_means(i, [B[5]])
    rows = [mean, B[5][i], state, B[5][i - 1]]
    return relax(state, matrix_load(scene, rows), n, dt)


scene.schedule(C0)
scene.observe(B[6])

if __name__ == "__main__":
    from run_example import main
    main(scene)
