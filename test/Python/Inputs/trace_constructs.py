"""A scene that uses every construct of the tracer (test/Python/sim-trace.test).

Each body exercises one group: arithmetic and comparisons on f32, f64 and
vectors, select, math functions, casts, an unrolled window (sim.range), an
scf.for with iter_args (sim.loop), parameters, dt and range, num_steps, a
total, every interpolation and boundary, schedule and observe.
"""
import sys

import sim
from sim import f32, f64, i32, u64, vector

V2 = vector(2, f64)
V4 = vector(4, f32)

s = sim.Scene("constructs", range=64, dt=1e-3, max_steps=4)
k = s.param("k", 2.0)                  # f32 (the scene's precision)
rounds = s.param("rounds", 3)          # i32
scale = s.param("scale", 0.5, f64)


@s.buffer(f32, boundary="wrap")
def A(i):
    return f32(i) * 0.25 - 1.0


@s.buffer(f64, interp="cubic", boundary="zero")
def D(i):
    x = f64(i)
    return -x / 3.0 + x * x


@s.buffer(V4, interp="none")
def P(i):
    return V4(1.0, 2.0, 3.0, f32(i))


@s.buffer(V2, interp=sim.hermite("W"))
def Y(i):
    return V2(f64(i), 0.0)


@Y.exact
def Y(i, t):
    return V2(sim.cos(t), sim.sin(t) * scale)


@s.buffer(V2, interp="none")
def W(i):
    return V2(0.0)


@s.component(writes=A)
def Window(i, t, n, dt):
    total = A[i] * 0.0
    for j in sim.range(-2, 3):
        total = total + A[i + j]
    bigger = A[i] > total / 5.0
    return sim.select(bigger, A[i] - k * dt, sim.max(A[i], -1.0))


@Window.num_steps
def Window(i, t):
    return sim.select(A[i] >= 0.0, 1, s.params.max_steps)


@s.component(writes=D)
def Loop(i, t, n, dt):
    @sim.loop(-1, 2, carry=(D[i] * 0.0, f64(0.0)))
    def acc(j, total, weight):
        w = sim.exp(-sim.abs(f64(j)))
        return total + w * D[i + j], weight + w

    mean = acc[0] / acc[1]
    return sim.fma(f64(n) * f64(dt), mean - D[i], D[i])


@s.component(writes=[P, Y, W])
def Vectors(i, t, n, dt):
    p = P[i]
    q = sim.sqrt(sim.abs(p)) + sim.tanh(p) * p.x
    r = p.replace(3, sim.sum(p)) + sim.broadcast(f32(t), 4)
    @sim.loop(0, rounds, carry=Y[i])
    def y(_, y):
        return y * 0.5 + V2(sim.dot(y, y), y[1])
    h = f64(n) * f64(dt)
    inside = (p > 0.0) & ~(p >= 10.0)
    return sim.min(sim.where(inside, q, -q), r), y + W[i] * h, W[i] - y * h


@s.total
def Size(i):
    v = Y[i]
    return sim.dot(v, v) + f64(A[i]) * f64(D[i])


@s.total(f32)
def Count(i):
    bits = u64(i) >> 1 ^ 0xFF
    return f32(i32(bits % 7 // 2)) + f32(sim.atan2(D[i], 2.0)) + sim.pow(A[i], 2.0)


s.schedule(Window, Loop, Vectors)
s.observe(A, D, Y)
sys.stdout.write(s.mlir())
