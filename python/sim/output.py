"""Outputs over time, and the `.npz` layout they are saved in.

A run with `output_every=N` records the state at base steps T0, T0+N, ...
and its end (a run ends exactly at its end, so every output time falls on
a big-step boundary). `Output.save` writes one `.npz` (numpy's zip of
`.npy` files; `sim-run --output-every N --output FILE.npz` writes the same
layout), K output times:

| key | dtype, shape | what |
| --- | --- | --- |
| `t` | int64 [K] | base steps |
| `time` | float64 [K] | t * dt |
| `buffer/<name>` | the buffer's (float32/float64), [K, range] or [K, range, lanes] | observed buffers |
| `total/<name>` | float64 [K] | totals |
| `error/<name>/max_abs`, `error/<name>/rms_rel` | float64 [K] | optional: errors against the exact solution |
| `exact/<name>` | like `buffer/<name>` | optional: the exact solution |
| `meta/scene`, `meta/strategy`, `meta/backend` | 0-d string arrays | what ran |

`max_abs` is the largest absolute difference over all items and lanes,
`rms_rel` is ||a - b||_2 / ||b||_2 (0 when both are zero, infinite when only
the exact solution is), as sim-run reports them.
"""

from __future__ import annotations

import os
import zipfile

import numpy as np

__all__ = ["Output", "error_norms"]


def error_norms(values, reference) -> tuple[float, float]:
    """(max-abs, RMS-relative) difference of `values` against `reference`."""
    a = np.asarray(values, dtype=np.float64).ravel()
    b = np.asarray(reference, dtype=np.float64).ravel()
    d = a - b
    max_abs = float(np.max(np.abs(d))) if d.size else 0.0
    norm_b = float(np.sqrt(np.sum(b * b)))
    norm_d = float(np.sqrt(np.sum(d * d)))
    if norm_b > 0:
        rms_rel = norm_d / norm_b
    else:
        rms_rel = 0.0 if norm_d == 0 else float("inf")
    return max_abs, rms_rel


class Output:
    """Observed buffers and totals at K output times (see the module)."""

    def __init__(self, t, time, buffers, totals, errors=None, exact=None,
                 meta=None):
        self.t = np.asarray(t, dtype=np.int64)
        self.time = np.asarray(time, dtype=np.float64)
        self.buffers: dict[str, np.ndarray] = dict(buffers)
        self.totals: dict[str, np.ndarray] = {
            k: np.asarray(v, dtype=np.float64) for k, v in totals.items()}
        self.errors: dict[str, dict[str, np.ndarray]] = dict(errors or {})
        self.exact: dict[str, np.ndarray] = dict(exact or {})
        self.meta: dict[str, str] = dict(meta or {})

    def __len__(self) -> int:
        return len(self.t)

    def arrays(self) -> dict[str, np.ndarray]:
        """The arrays of the `.npz` layout, by key."""
        out = {"t": self.t, "time": self.time}
        for name, values in self.buffers.items():
            out[f"buffer/{name}"] = values
        for name, values in self.totals.items():
            out[f"total/{name}"] = values
        for name, norms in self.errors.items():
            for norm, values in norms.items():
                out[f"error/{name}/{norm}"] = np.asarray(values,
                                                         dtype=np.float64)
        for name, values in self.exact.items():
            out[f"exact/{name}"] = values
        for key, value in self.meta.items():
            out[f"meta/{key}"] = np.array(str(value))
        return out

    def save(self, path) -> str:
        """Writes the output as `.npz` (uncompressed); returns the path."""
        path = str(path)
        with open(path, "wb") as f:  # savez would append .npz to a name
            np.savez(f, **self.arrays())
        return path

    @classmethod
    def load(cls, path) -> "Output":
        """An Output from a `.npz` of this layout (ours or sim-run's)."""
        try:
            with np.load(path, allow_pickle=False) as data:
                arrays = {key: data[key] for key in data.files}
        except (zipfile.BadZipFile, EOFError) as error:
            # A truncated or corrupted file: numpy lets zipfile's errors
            # through.
            raise ValueError(f"{os.fspath(path)} is not a readable .npz "
                             f"file ({error})") from None
        if not isinstance(arrays, dict) or "t" not in arrays or \
                "time" not in arrays:
            raise ValueError(f"{os.fspath(path)} is not an output of sim "
                             f"(no 't' and 'time' arrays; sim-run --output "
                             f"and Output.save write them)")
        return cls.from_arrays(arrays)

    @classmethod
    def from_arrays(cls, arrays: dict) -> "Output":
        buffers, totals, errors, exact, meta = {}, {}, {}, {}, {}
        for key, value in arrays.items():
            kind, _, rest = key.partition("/")
            if kind == "buffer":
                buffers[rest] = value
            elif kind == "total":
                totals[rest] = value
            elif kind == "exact":
                exact[rest] = value
            elif kind == "error":
                name, _, norm = rest.rpartition("/")
                errors.setdefault(name, {})[norm] = value
            elif kind == "meta":
                item = value.item() if value.shape == () else value
                meta[rest] = (item.decode() if isinstance(item, bytes)
                              else str(item))
        return cls(arrays["t"], arrays["time"], buffers, totals, errors,
                   exact, meta)

    def __repr__(self):
        return (f"<sim.Output {self.meta.get('scene', '?')}: {len(self)} "
                f"output times, buffers {sorted(self.buffers)}, totals "
                f"{sorted(self.totals)}>")
