"""kepler: Kepler orbits of eccentricity @ecc = 0.6 (f64), one per item.

The Python version of examples/physics/kepler.mlir, with the same numbers
bit for bit (test/Python/examples-equal.test). Item i is the orbit of a test
body around GM = 1 with semi-major axis 1, at mean anomaly
M = 2 pi i / range + t. One component takes kick-drift-kick leapfrog steps
of h = n dt with num_steps = floor(@eta r^1.5 / dt); the exact solution
solves Kepler's equation with 12 Newton steps. The totals are the energy
(exactly -range / 2) and the angular momentum (exactly 0.8 range).

    python3 python/examples/kepler.py --run 6283 --output-every 500 \\
        --output kepler.npz && python3 -m sim.plot kepler.npz
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                ".."))
import sim  # noqa: E402
from sim import f64, vector  # noqa: E402

VEC2 = vector(2, f64)

scene = sim.Scene("kepler", range=256, dt=1.0e-3, max_steps=8, precision=f64)
ecc = scene.param("ecc", 6.0e-1)      # eccentricity of every orbit
eta = scene.param("eta", 4.0e-3)      # num_steps = floor(eta r^1.5 / dt)


def orbit(i, t):
    """cos E, sin E and sqrt(1 - e^2) of item i's orbit at time t."""
    M = f64(i) / f64(scene.params.range) * 6.283185307179586 + t
    E0 = sim.fma(ecc, sim.sin(M), M)

    @sim.loop(0, 12, carry=E0)           # Newton's method on E - e sin E = M
    def E(k, e):
        return e - (e - ecc * sim.sin(e) - M) / (1.0 - ecc * sim.cos(e))

    return sim.cos(E), sim.sin(E), sim.sqrt(1.0 - ecc * ecc)


def velocity(i, t):
    cE, sE, b = orbit(i, t)
    Ed = 1.0 / (1.0 - ecc * cE)
    return VEC2(-sE * Ed, b * cE * Ed)


def position(i, t):
    cE, sE, b = orbit(i, t)
    return VEC2(cE - ecc, b * sE)


V = scene.buffer(VEC2, interp="none", name="V")(lambda i: velocity(i, 0.0))
V.exact(velocity)
X = scene.buffer(VEC2, interp=sim.hermite(V), name="X")(
    lambda i: position(i, 0.0))
X.exact(position)


def radius(x):
    r2 = sim.sum(x * x)
    return r2, sim.sqrt(r2)


@scene.component(writes=[V, X])
def Orbit(i, n, dt):
    x, v = X[i], V[i]
    h = f64(n) * dt
    hh = h * 0.5
    r2, r = radius(x)                       # kick: a = -x / r^3
    vh = sim.fma(hh, -1.0 / (r2 * r) * x, v)
    x1 = sim.fma(h, vh, x)                  # drift
    r2, r = radius(x1)                      # kick
    return sim.fma(hh, -1.0 / (r2 * r) * x1, vh), x1


@Orbit.num_steps
def Orbit(i, t):
    r2, r = radius(X[i])
    q = eta * sim.sqrt(r2 * r) / scene.params.dt
    return sim.i32(sim.min(q, 1.0e6))


@scene.total
def Energy(i):
    _, r = radius(X[i])
    v = V[i]
    return 0.5 * sim.sum(v * v) - 1.0 / r


@scene.total
def AngularMomentum(i):
    x, v = X[i], V[i]
    return x[0] * v[1] - x[1] * v[0]


scene.schedule(Orbit)
scene.observe(X, V)

if __name__ == "__main__":
    from run_example import main
    main(scene)
