#!/usr/bin/env python3
"""Checks grid-sync.mlir's @U against its own recurrence, in float64.

@Advect is grid_sync: every sub-step has one size over the whole range, the
minimum of num_steps (@ns; some items ask for @ns + 1), capped by the end of
the big step. This replays those sub-steps (upwind Euler, wrap) for the big
steps given and compares with a dumped U.npy (float32 rounding only).

Usage: grid-sync-reference.py U.npy NS BIG_STEP...
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from strategies import read_npy  # noqa: E402

path, ns, bigs = sys.argv[1], int(sys.argv[2]), [int(m) for m in sys.argv[3:]]
shape, got = read_npy(path)
R, dt = shape[0], 0.05
u = [math.sin(i * 0.2) for i in range(R)]
subs = []
for m in bigs:
    left = m
    while left:
        n = min(ns, left)
        subs.append(n)
        left -= n
for n in subs:
    u = [u[i] + n * dt * (u[i - 1] - u[i]) for i in range(R)]
err = max(abs(a - b) for a, b in zip(u, got))
print("U after sub-steps %s: max-abs %s" %
      (" ".join(map(str, subs)), "ok" if err < 1e-5 else "%.3e" % err))
sys.exit(0 if err < 1e-5 else 1)
