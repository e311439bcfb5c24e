"""harmonic: harmonic oscillators, each driving a faster resonator (f64).

The Python version of examples/physics/harmonic.mlir, with the same numbers
bit for bit (test/Python/examples-equal.test). Item i is a driver
x'' = -w^2 x with w = 1 + i / 16 (x = cos(w t)) that drives a resonator
y'' = -k^2 y + x(t), k = @ratio * w, at rest at t = 0:
y = (cos(w t) - cos(k t)) / (k^2 - w^2). Both take velocity Verlet steps of
h = n dt with num_steps = floor(@c / (freq dt)); @X is interpolated with
cubic Hermite through its derivative @V, which the resonator reads inside
the driver's big steps.

    python3 python/examples/harmonic.py --run 2000 --strategy hip
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                ".."))
import sim  # noqa: E402
from sim import f64  # noqa: E402

scene = sim.Scene("harmonic", range=256, dt=1.0e-3, max_steps=8,
                  precision=f64)
c = scene.param("c", 4.0e-2)          # radians of phase per (sub-)step
ratio = scene.param("ratio", 2.0)     # resonator over driver frequency


def omega(i):
    return sim.fma(f64(i), 0.0625, 1.0)        # w = 1 + i / 16


def steps_for(freq):
    """floor(@c / (freq dt)), capped so that it fits an i32."""
    return sim.i32(sim.min(c / (freq * scene.params.dt), 1.0e6))


@scene.buffer(interp="none")
def V(i):
    return 0.0


@scene.buffer(interp=sim.hermite(V))
def X(i):
    return 1.0


@X.exact
def X(i, t):
    return sim.cos(omega(i) * t)


@scene.buffer(interp="none")
def W(i):
    return 0.0


@scene.buffer
def Y(i):
    return 0.0


@Y.exact
def Y(i, t):
    w = omega(i)
    k = w * ratio
    return (sim.cos(w * t) - sim.cos(k * t)) / (k * k - w * w)


@scene.buffer(interp="none")
def F(i):
    return X[i]                 # the forcing at the resonator's local time


@scene.component(writes=[V, X], num_steps=lambda i: steps_for(omega(i)))
def Driver(i, n, dt):
    x, v = X[i], V[i]
    nw2 = -(omega(i) * omega(i))
    h = f64(n) * dt
    hh = h * 0.5
    vh = sim.fma(hh, nw2 * x, v)           # velocity Verlet: half kick,
    x1 = sim.fma(h, vh, x)                 # drift,
    return sim.fma(hh, nw2 * x1, vh), x1   # half kick


@scene.component(writes=[W, Y, F],
                 num_steps=lambda i: steps_for(omega(i) * ratio))
def Resonator(i, n, dt):
    y, u, f0 = Y[i], W[i], F[i]
    f1 = X[i]                   # the driver at the end of this sub-step
    k = omega(i) * ratio
    nk2 = -(k * k)
    h = f64(n) * dt
    hh = h * 0.5
    uh = sim.fma(hh, sim.fma(nk2, y, f0), u)
    y1 = sim.fma(h, uh, y)
    return sim.fma(hh, sim.fma(nk2, y1, f1), uh), y1, f1


scene.schedule(Driver, Resonator)
scene.observe(X, Y)

if __name__ == "__main__":
    from run_example import main
    main(scene)
