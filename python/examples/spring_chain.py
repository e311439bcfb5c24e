"""spring_chain: a ring of masses on springs with a stiff segment (f64).

A user's scene for local time stepping (docs/Model.md): item i is a mass
M_i = 1 + sin(i / 10) / 2 on a ring, joined to its neighbours by springs of
stiffness 1, except the springs of the second quarter, @ratio (100) times
stiffer. Masses and stiffnesses are constant buffers (computed where they
are read, never stored). Each mass takes symplectic-Euler steps of h = n dt
with num_steps = @c / (w dt), w = sqrt(4 k / M) its fastest frequency, and
reads its neighbours' positions @X, interpolated with cubic Hermite through
their velocities @V. The component writes both, so under `lts` every block
of 32 masses keeps both at its two time levels and takes its own sub-step:
the stiff quarter about 4 base steps, the rest the whole big step of 16,
where `hip` sub-steps the whole ring at the stiff quarter's rate.
@Energy (kinetic plus spring energy) is conserved up to the scheme's
O(h) oscillation.

    python3 python/examples/spring_chain.py --run 2048 --strategy lts
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                ".."))
import sim  # noqa: E402
from sim import f64, i32  # noqa: E402

N = 4096
scene = sim.Scene("spring_chain", range=N, dt=1.0e-3, max_steps=16,
                  precision=f64)
ratio = scene.param("ratio", 100.0)   # stiff over soft springs
c = scene.param("c", 0.2)             # radians of phase per (sub-)step


@scene.buffer(constant=True, boundary="wrap")
def K(i):
    """The spring between masses i and i + 1."""
    stiff = sim.select(i < N // 2, ratio, f64(1.0))
    return sim.select(i >= N // 4, stiff, f64(1.0))


@scene.buffer(constant=True, boundary="wrap")
def M(i):
    return 1.0 + 0.5 * sim.sin(f64(i) * 0.1)


@scene.buffer(interp="none", boundary="wrap")
def V(i):
    return 0.0


@scene.buffer(interp=sim.hermite(V), boundary="wrap")
def X(i):
    return 0.01 * sim.sin(6.283185307179586 * f64(i) / N)


@scene.component(writes=[V, X])
def Step(i, n, dt):
    h = f64(n) * dt
    force = K[i] * (X[i + 1] - X[i]) - K[i - 1] * (X[i] - X[i - 1])
    v = sim.fma(h, force / M[i], V[i])
    return v, sim.fma(h, v, X[i])


@Step.num_steps
def Step(i, t):
    w = sim.sqrt(4.0 * sim.max(K[i], K[i - 1]) / M[i])
    return i32(sim.min(c / (w * scene.params.dt), 1.0e6))


@scene.total
def Energy(i):
    stretch = X[i + 1] - X[i]
    return 0.5 * M[i] * V[i] * V[i] + 0.5 * K[i] * stretch * stretch


scene.observe(X)

if __name__ == "__main__":
    from run_example import main
    main(scene)
