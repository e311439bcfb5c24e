"""make_output.py FILE.npz: writes a small output file in the layout of
Output.save (a vector buffer X with its exact solution and errors, a scalar
buffer Y, two totals), without compiling or running anything."""
import sys

import numpy as np

import sim

t = np.arange(0, 500, 100)
time = t * 1e-3
items = np.arange(32)
phase = items[None, :] * 0.2 + time[:, None]
exact = np.stack([np.cos(phase), np.sin(phase)], axis=-1)
x = exact + 1e-4 * time[:, None, None]
norms = [sim.error_norms(a, b) for a, b in zip(x, exact)]
out = sim.Output(
    t, time, {"X": x, "Y": np.cos(phase).astype(np.float32)},
    {"Energy": -16 + 1e-9 * t, "Momentum": np.full(len(t), 25.6)},
    {"X": {"max_abs": [a for a, _ in norms], "rms_rel": [r for _, r in norms]}},
    {"X": exact}, {"scene": "made", "strategy": "hip", "backend": "cpu"})
out.save(sys.argv[1])
