"""Particles on a ring that read a partner from a neighbour list, the list's
entry clamped to the reach it was built with (sim.clamp): the read is the
window i-4..i+4, so under lts the blocks of particles take local steps
(test/Python/neighbour-list.test). Prints the scene's MLIR."""

import sim
from sim import f64, i32, i64

N = 1024
scene = sim.Scene("neighbours", range=N, dt=1.0e-3, max_steps=16,
                  precision=f64)


@scene.buffer(constant=True)
def Partner(i):
    """i + 2 or i + 3: an irregular list, built within i-4..i+4."""
    return f64(i64(i) + 2 + i64(i) % 2)


@scene.buffer(boundary="wrap")
def X(i):
    return sim.sin(f64(i) * 0.03)


@scene.buffer(boundary="wrap")
def V(i):
    return 0.0


def light(i):
    return (i >= 256) & (i < 384)


@scene.component(writes=[X, V])
def Move(i, n, dt):
    partner = sim.clamp(sim.index(i64(Partner[i])), i - 4, i + 4)
    force = X[partner] - X[i] + X[i - 1] - X[i]
    mass = sim.select(light(i), f64(0.0625), f64(1.0))
    h = f64(n) * dt
    v = sim.fma(h, force / mass, V[i])
    return sim.fma(h, v, X[i]), v


@Move.num_steps
def Move(i, t):
    return sim.select(light(i), i32(1), i32(16))


scene.observe(X)

if __name__ == "__main__":
    print(scene.mlir())
