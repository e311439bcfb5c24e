"""Emitters for the building blocks of the paper's benchmark scenes.

Each `emit_*` function appends ops to a `Body` and returns the SSA name of its
result. Next to the emitters that compute something a runtime test may want
to reproduce (the step-count hash and the initial values) is a plain Python
reference implementation of the same formula: `step_count` and `init_value`.

The formulas (all integer arithmetic is on unsigned 64-bit values, wrapping):

* splitmix64 finalizer (Steele, Lea and Flood 2014):
      z ^= z >> 30; z *= 0xBF58476D1CE4E5B9;
      z ^= z >> 27; z *= 0x94D049BB133111EB;
      z ^= z >> 31
* step count of component number `c` for `key` at local time `t`:
      n = mix((c + 1) * GOLDEN ^ key * KEY_MUL ^ t * TIME_MUL) % 3 + 1
  where key = 0 (@dist = 0, per component), i / @group (@dist = 1, per group
  of items) or i (any other @dist, per item); @dist = 3 makes every n 1 and
  @dist = 4 makes every n max_steps (the extremes of the cross-checks).
* initial value of lane `l` (0..3) of item `i` in the buffer with seed `s`:
      z = mix((4 * i + l) * KEY_MUL ^ (s + 1) * GOLDEN)
      v = (z >> 40) * 2**-23 - 1          (exact in f32, in [-1, 1))
"""

from __future__ import annotations

from typing import Sequence

from .builder import Body, signed64

__all__ = [
    "GOLDEN",
    "KEY_MUL",
    "TIME_MUL",
    "MIX_MUL1",
    "MIX_MUL2",
    "emit_init_value",
    "emit_matrix_load",
    "emit_relaxation",
    "emit_splitmix64",
    "emit_step_count",
    "emit_window_gather",
    "init_value",
    "splitmix64",
    "step_count",
]

MASK64 = (1 << 64) - 1
GOLDEN = 0x9E3779B97F4A7C15    # splitmix64's increment (2**64 / phi)
MIX_MUL1 = 0xBF58476D1CE4E5B9  # splitmix64 finalizer multipliers
MIX_MUL2 = 0x94D049BB133111EB
KEY_MUL = 0xD6E8FEB86659FD93   # odd multipliers that spread key and time
TIME_MUL = 0xFF51AFD7ED558CCD  # (the latter is MurmurHash3's fmix64 one)

VEC4F = "vector<4xf32>"
VEC4I = "vector<4xi64>"


# -- Python reference implementations ----------------------------------------

def splitmix64(x: int) -> int:
    """The splitmix64 finalizer on an unsigned 64-bit value."""
    z = x & MASK64
    z = ((z ^ (z >> 30)) * MIX_MUL1) & MASK64
    z = ((z ^ (z >> 27)) * MIX_MUL2) & MASK64
    return z ^ (z >> 31)


def step_count(component: int, key: int, t: int) -> int:
    """What `emit_step_count` computes: a value in [1..3]."""
    x = (((component + 1) * GOLDEN) ^ (key * KEY_MUL) ^ (t * TIME_MUL)) & MASK64
    return splitmix64(x) % 3 + 1


def step_key(i: int, dist: int, group: int) -> int:
    """The hash key of item `i` for the distribution `dist`."""
    if dist == 0:
        return 0
    if dist == 1:
        return i // max(group, 1)
    return i


def init_value(seed: int, i: int) -> list[float]:
    """What `emit_init_value` computes for item `i`: four floats in [-1, 1)."""
    values = []
    for lane in range(4):
        x = (((4 * i + lane) * KEY_MUL) ^ ((seed + 1) * GOLDEN)) & MASK64
        values.append((splitmix64(x) >> 40) * 2.0**-23 - 1.0)
    return values


# -- Emitters ------------------------------------------------------------------

def _int_const(body: Body, value: int, type_: str, hint: str) -> str:
    """An i64 (or vector<4xi64> splat) constant, with its hex in a comment."""
    value &= MASK64
    text = str(signed64(value))
    comment = f"0x{value:016X}" if value > 0xFFFF else None
    if type_.startswith("vector<"):
        return body.const(f"dense<{text}>", type_, hint=hint + "_v",
                          comment=comment)
    return body.const(text, type_, hint=hint, comment=comment)


def emit_splitmix64(body: Body, x: str, type_: str = "i64") -> str:
    """The splitmix64 finalizer on `x` (an `i64` or a `vector<4xi64>`)."""
    c30 = _int_const(body, 30, type_, "c30")
    c27 = _int_const(body, 27, type_, "c27")
    c31 = _int_const(body, 31, type_, "c31")
    m1 = _int_const(body, MIX_MUL1, type_, "mix_mul1")
    m2 = _int_const(body, MIX_MUL2, type_, "mix_mul2")
    s = body.op("s30", f"arith.shrui {x}, {c30} : {type_}")
    z = body.op("z1", f"arith.xori {x}, {s} : {type_}")
    z = body.op("z2", f"arith.muli {z}, {m1} : {type_}")
    s = body.op("s27", f"arith.shrui {z}, {c27} : {type_}")
    z = body.op("z3", f"arith.xori {z}, {s} : {type_}")
    z = body.op("z4", f"arith.muli {z}, {m2} : {type_}")
    s = body.op("s31", f"arith.shrui {z}, {c31} : {type_}")
    return body.op("mixed", f"arith.xori {z}, {s} : {type_}")


def emit_step_count(body: Body, component: int) -> str:
    """num_steps of the paper's scenes: n in [1..3] from a hash (an `i32`).

    `body` is a num_steps body. The hash key depends on `@dist` (0: per
    component, 1: per group of `@group` items, otherwise per item), so the
    same scene covers the three distributions of the benchmarks; @dist = 3
    and 4 give every item 1 and max_steps.
    """
    i, t = body.arg("i"), body.arg("t")
    c0 = body.const(0, "i32")
    c1 = body.const(1, "i32")
    c0_64 = body.const(0, "i64")
    c1_64 = body.const(1, "i64")
    c3_64 = body.const(3, "i64")
    seed = _int_const(body, (component + 1) * GOLDEN, "i64", "seed")
    key_mul = _int_const(body, KEY_MUL, "i64", "key_mul")
    time_mul = _int_const(body, TIME_MUL, "i64", "time_mul")

    body.comment("The hash key: 0 (@dist = 0, per component), i / @group "
                 "(@dist = 1),\nor i (otherwise, per item).")
    dist = body.op("dist", "sim.get_param @dist : i32")
    group = body.op("group", "sim.get_param @group : i32")
    item = body.op("item", f"arith.index_castui {i} : index to i64")
    group64 = body.op("group64", f"arith.extsi {group} : i32 to i64")
    group64 = body.op("group_size", f"arith.maxsi {group64}, {c1_64} : i64")
    in_group = body.op("group_id", f"arith.divui {item}, {group64} : i64")
    per_group = body.op("per_group", f"arith.cmpi eq, {dist}, {c1} : i32")
    per_comp = body.op("per_component", f"arith.cmpi eq, {dist}, {c0} : i32")
    key = body.op("item_key", f"arith.select {per_group}, {in_group}, {item} : i64")
    key = body.op("key", f"arith.select {per_comp}, {c0_64}, {key} : i64")
    body.comment(f"n = splitmix64(seed ^ key * KEY_MUL ^ t * TIME_MUL) % 3 + 1"
                 f"\nwith seed = {component + 1} * GOLDEN.")
    kx = body.op("key_term", f"arith.muli {key}, {key_mul} : i64")
    tx = body.op("time_term", f"arith.muli {t}, {time_mul} : i64")
    x = body.op("x0", f"arith.xori {seed}, {kx} : i64")
    x = body.op("x", f"arith.xori {x}, {tx} : i64")
    z = emit_splitmix64(body, x, "i64")
    r = body.op("r", f"arith.remui {z}, {c3_64} : i64")
    n = body.op("n64", f"arith.addi {r}, {c1_64} : i64")
    n = body.op("hashed", f"arith.trunci {n} : i64 to i32")
    body.comment("@dist = 3: every n is 1; @dist = 4: every n is max_steps.")
    c3 = body.const(3, "i32")
    c4 = body.const(4, "i32")
    max_steps = body.op("max_steps", "sim.get_param @max_steps : i32")
    all_one = body.op("all_one", f"arith.cmpi eq, {dist}, {c3} : i32")
    all_max = body.op("all_max", f"arith.cmpi eq, {dist}, {c4} : i32")
    n = body.op("n_or_one", f"arith.select {all_one}, {c1}, {n} : i32")
    return body.op("n", f"arith.select {all_max}, {max_steps}, {n} : i32")


def emit_init_value(body: Body, seed: int) -> str:
    """A deterministic pseudo-random `vector<4xf32>` in [-1, 1) for item %i.

    `body` is an init body; `seed` distinguishes buffers.
    """
    i = body.arg("i")
    c4 = _int_const(body, 4, VEC4I, "c4")
    lanes = body.const("dense<[0, 1, 2, 3]>", VEC4I, hint="lanes")
    key_mul = _int_const(body, KEY_MUL, VEC4I, "key_mul")
    salt = _int_const(body, (seed + 1) * GOLDEN, VEC4I, "seed")
    c40 = _int_const(body, 40, VEC4I, "c40")
    ulp = body.const("dense<1.1920928955078125E-7>", VEC4F, hint="two_pow_m23",
                     comment="2^-23")
    minus_one = body.const("dense<-1.0>", VEC4F, hint="minus_one")
    body.comment(f"Element 4 * i + lane, hashed with splitmix64 (seed {seed}); "
                 "the top 24 bits\nmapped to [-1, 1).")
    item = body.op("item", f"arith.index_castui {i} : index to i64")
    items = body.op("items", f"vector.broadcast {item} : i64 to {VEC4I}")
    elem = body.op("elem0", f"arith.muli {items}, {c4} : {VEC4I}")
    elem = body.op("elem", f"arith.addi {elem}, {lanes} : {VEC4I}")
    x = body.op("x0", f"arith.muli {elem}, {key_mul} : {VEC4I}")
    x = body.op("x", f"arith.xori {x}, {salt} : {VEC4I}")
    z = emit_splitmix64(body, x, VEC4I)
    top = body.op("top24", f"arith.shrui {z}, {c40} : {VEC4I}")
    u = body.op("u", f"arith.uitofp {top} : {VEC4I} to {VEC4F}")
    return body.op("value", f"vector.fma {u}, {ulp}, {minus_one} : {VEC4F}")


def emit_window_gather(body: Body, buffers: Sequence[str], lo: int = -4,
                       hi: int = 4) -> list[str]:
    """Sums of `buffers` over the items i+lo..i+hi (the paper's 9 neighbours).

    Emits one `scf.for %k = lo to hi+1` that reads every buffer at
    `%j = arith.addi %i, %k` (the shape the window analysis recognises) and
    returns the per-buffer sums.
    """
    i = body.arg("i")
    lower = body.const(lo, "index")
    upper = body.const(hi + 1, "index")
    step = body.const(1, "index")
    zero = body.const("dense<0.0>", VEC4F, hint="zero")

    def build(k: str, accs: list[str]) -> list[str]:
        j = body.op("j", f"arith.addi {i}, {k} : index")
        nexts = []
        for buffer, acc in zip(buffers, accs):
            v = body.op(f"v_{buffer}", f"sim.read @{buffer}[{j}] : {VEC4F}")
            nexts.append(body.op(f"acc_{buffer}_next",
                                 f"arith.addf {acc}, {v} : {VEC4F}"))
        return nexts

    return body.scf_for(lower, upper, step,
                        [(f"acc_{b}", zero) for b in buffers],
                        [VEC4F] * len(buffers), build, iv_hint="k",
                        result_hint="sum" if len(buffers) == 1 else "sums")


def emit_matrix_load(body: Body, rows: Sequence[str], bias: str) -> str:
    """The paper's per-item load: L rounds of a 4x4 matrix product.

    `rows` are four `vector<4xf32>` with entries in [-1, 1]. M = rows / 4, so
    every row of M has a sum of |entries| <= 1 and no power of M grows. X
    starts as M; `scf.for` runs `@L` rounds of X := M * X, where row r of the
    product is sum_c M[r][c] * X[c]: a `vector.extract` of the scalar M[r][c],
    a `vector.broadcast` of it (hoisted out of the loop, M does not change),
    and a `vector.fma` with row c of X. The result reduces X to one vec4 (the
    sum of its rows) plus `bias`, so the force does not fade when M^L decays.
    """
    if len(rows) != 4:
        raise ValueError("the matrix load needs four rows")
    quarter = body.const("dense<2.5E-1>", VEC4F, hint="quarter")
    c0 = body.const(0, "index")
    c1 = body.const(1, "index")
    body.comment("M = rows / 4: entries in [-1/4, 1/4], so every row of M has"
                 "\nsum |m_rc| <= 1 and X stays bounded.")
    m = [body.op(f"m{r}", f"arith.mulf {row}, {quarter} : {VEC4F}")
         for r, row in enumerate(rows)]
    body.comment("Splat every scalar M[r][c] once, outside the rounds.")
    splat = [[None] * 4 for _ in range(4)]
    for r in range(4):
        for c in range(4):
            s = body.op(f"m{r}{c}", f"vector.extract {m[r]}[{c}] : f32 from "
                        f"{VEC4F}")
            splat[r][c] = body.op(f"m{r}{c}_splat",
                                  f"vector.broadcast {s} : f32 to {VEC4F}")
    body.comment("@L rounds of X := M * X (64 multiply-adds per round).")
    rounds = body.op("rounds", "sim.get_param @L : i32")
    rounds = body.op("rounds_idx", f"arith.index_cast {rounds} : i32 to index")

    def build(_: str, x: list[str]) -> list[str]:
        out = []
        for r in range(4):
            y = body.op(f"p{r}0", f"arith.mulf {splat[r][0]}, {x[0]} : {VEC4F}")
            for c in range(1, 4):
                y = body.op(f"p{r}{c}", f"vector.fma {splat[r][c]}, {x[c]}, "
                            f"{y} : {VEC4F}")
            out.append(y)
        return out

    xs = body.scf_for(c0, rounds, c1, [(f"x{r}", m[r]) for r in range(4)],
                      [VEC4F] * 4, build, iv_hint="round", result_hint="x")
    body.comment("Reduce X to one vec4: the sum of its rows, plus the bias.")
    acc = body.op("xsum", f"arith.addf {xs[0]}, {xs[1]} : {VEC4F}")
    acc = body.op("xsum", f"arith.addf {acc}, {xs[2]} : {VEC4F}")
    acc = body.op("xsum", f"arith.addf {acc}, {xs[3]} : {VEC4F}")
    return body.op("force", f"arith.addf {acc}, {bias} : {VEC4F}")


def emit_relaxation(body: Body, state: str | None, force: str) -> str:
    """The new value: `state + h * (tanh(force) - state)`, h = min(n * dt, 1).

    A convex combination of the state and tanh(force), so a state in [-1, 1]
    stays there. Without a `state` (a component that does not read its own
    buffer) the new value is `tanh(force)`.
    """
    target = body.op("target", f"math.tanh {force} : {VEC4F}")
    if state is None:
        return target
    n, dt = body.arg("n"), body.arg("dt")
    one = body.const(1.0, "f32", hint="one")
    nf = body.op("nf", f"arith.sitofp {n} : i32 to f32")
    h = body.op("h_raw", f"arith.mulf {nf}, {dt} : f32")
    h = body.op("h", f"arith.minimumf {h}, {one} : f32")
    hv = body.op("hv", f"vector.broadcast {h} : f32 to {VEC4F}")
    delta = body.op("delta", f"arith.subf {target}, {state} : {VEC4F}")
    return body.op("new", f"vector.fma {hv}, {delta}, {state} : {VEC4F}")
