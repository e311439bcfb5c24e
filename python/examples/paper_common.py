"""The building blocks of the paper's benchmark scenes, as traced Python.

The same formulas as python/simscene/emitters.py (which writes
examples/paper/*.mlir as text), written with the sim package, so that
gravity_like.py and pbd_like.py give the numbers of the .mlir scenes bit for
bit:

* `step_count(scene, c)`: num_steps = splitmix64 hash of the component, a key
  that @dist selects and the local time, % 3 + 1 (@dist = 3: all 1,
  @dist = 4: all max_steps);
* `init_value(seed)`: a pseudo-random vec4 in [-1, 1) per item;
* `window_sums(i, buffers)`: the sums of the 9 neighbours i-4..i+4 (one
  `scf.for` whose reads are `B[i + k]`: a window);
* `matrix_load(scene, rows)`: @L rounds of a 4x4 matrix product, the
  paper's per-item load;
* `relax(state, force, n, dt)`: the update.
"""

import sim
from sim import f32, u64, vector

VEC4F = vector(4, f32)
VEC4U = vector(4, u64)

GOLDEN = 0x9E3779B97F4A7C15
MIX_MUL1 = 0xBF58476D1CE4E5B9
MIX_MUL2 = 0x94D049BB133111EB
KEY_MUL = 0xD6E8FEB86659FD93
TIME_MUL = 0xFF51AFD7ED558CCD
MASK64 = (1 << 64) - 1


def splitmix64(z):
    """The splitmix64 finalizer on u64 values (scalars or vectors)."""
    z = (z ^ (z >> 30)) * MIX_MUL1
    z = (z ^ (z >> 27)) * MIX_MUL2
    return z ^ (z >> 31)


def step_count(scene, component):
    """The num_steps body of component number `component`."""
    p = scene.params
    seed = ((component + 1) * GOLDEN) & MASK64

    def num_steps(i, t):
        item = u64(i)
        group_size = sim.max(sim.i64(p.group), 1)
        group_id = item // u64(group_size)
        key = sim.select(p.dist == 1, group_id, item)
        key = sim.select(p.dist == 0, 0, key)
        x = seed ^ key * KEY_MUL ^ u64(t) * TIME_MUL
        hashed = sim.i32(splitmix64(x) % 3 + 1)
        n = sim.select(p.dist == 3, 1, hashed)
        return sim.select(p.dist == 4, p.max_steps, n)

    return num_steps


def init_value(seed):
    """The init body of the buffer with `seed`: lane l of item i is the top
    24 bits of splitmix64((4 i + l) * KEY_MUL ^ (seed + 1) * GOLDEN) mapped
    to [-1, 1)."""
    salt = ((seed + 1) * GOLDEN) & MASK64

    def init(i):
        elem = VEC4U(u64(i)) * 4 + VEC4U(0, 1, 2, 3)
        z = splitmix64(elem * KEY_MUL ^ salt)
        return sim.fma(VEC4F(z >> 40), 2.0 ** -23, -1.0)

    return init


def window_sums(i, buffers):
    """The sums of each buffer over the items i-4..i+4."""
    zero = VEC4F(0.0)

    @sim.loop(-4, 5, carry=tuple(zero for _ in buffers))
    def sums(k, *accs):
        j = i + k
        return tuple(acc + b[j] for acc, b in zip(accs, buffers))

    return sums


def window_means(i, buffers):
    return [s * (1.0 / 9.0) for s in window_sums(i, buffers)]


def two_more_rows(a, b):
    """Rows 3 and 4 when a component reads only two: a * b and (a - b) / 2."""
    return [a * b, (a - b) * 0.5]


def matrix_load(scene, rows):
    """X := M * X for @L rounds, M = rows / 4 (X starts as M); returns the
    sum of X's rows plus rows[0]."""
    m = [row * 0.25 for row in rows]
    splat = [[VEC4F(m[r][c]) for c in range(4)] for r in range(4)]

    @sim.loop(0, sim.index(scene.params.L), carry=tuple(m))
    def x(_, *xs):
        out = []
        for r in range(4):
            y = splat[r][0] * xs[0]
            for c in range(1, 4):
                y = sim.fma(splat[r][c], xs[c], y)
            out.append(y)
        return tuple(out)

    return x[0] + x[1] + x[2] + x[3] + rows[0]


def relax(state, force, n, dt):
    """state + h * (tanh(force) - state), h = min(n * dt, 1); tanh(force)
    without a state."""
    target = sim.tanh(force)
    if state is None:
        return target
    h = sim.min(f32(n) * dt, 1.0)
    return sim.fma(h, target - state, state)
