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

A `<name>` in a key is the name escaped as sim-run escapes it (the stems
of its dump files, runtime/tools/simrun/Output.h): the bytes A-Z, a-z,
0-9, `_`, `-` and a `.` not first are kept, every other byte of the UTF-8
name becomes `%XX` (upper-case hex), so `x$y` is `buffer/x%24y`; an empty
name is `_`, a stem is cut to 200 bytes, and a stem that would share a dump
file with an earlier one gets `-2`, `-3`, ... (`X.reference` after `X`).
`Output.load` decodes the keys back to the names.

`max_abs` is the largest absolute difference over all items and lanes,
`rms_rel` is ||a - b||_2 / ||b||_2 (0 when both are zero, infinite when only
the exact solution is), as sim-run reports them.
"""

from __future__ import annotations

import os
import re
import secrets
import stat
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


# What sim-run's sanitiseName and dumpStems (runtime/tools/simrun/Output.h)
# make of names; the keys of both tools' files must agree.
_MAX_STEM = 200
_DUMP_SUFFIXES = (".npy", ".reference.npy", ".check.npy")
_KEPT = frozenset(b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                  b"0123456789_-")


def _sanitise(name: str) -> str:
    """sim-run's file-name stem of `name` (sanitiseName)."""
    if not name:
        return "_"
    stem = ""
    for i, byte in enumerate(name.encode("utf-8")):
        kept = byte in _KEPT or (byte == ord(".") and i > 0)
        piece = chr(byte) if kept else f"%{byte:02X}"
        if len(stem) + len(piece) > _MAX_STEM:
            break
        stem += piece
    return stem


def _next_stem(name: str, taken: set) -> str:
    """The stem dumpStems gives `name` after the stems whose files are in
    `taken`; adds its files to `taken`."""
    base = stem = _sanitise(name)
    n = 2
    while any(stem + suffix in taken for suffix in _DUMP_SUFFIXES):
        stem = f"{base}-{n}"
        n += 1
    taken.update(stem + suffix for suffix in _DUMP_SUFFIXES)
    return stem


def _stems(names) -> dict[str, str]:
    """The stem of each of `names`, in order (dumpStems)."""
    taken: set = set()
    return {name: _next_stem(name, taken) for name in names}


_ESCAPE = re.compile(r"%([0-9A-F]{2})")


def _unescape(stem: str) -> str:
    data = _ESCAPE.sub(lambda m: chr(int(m.group(1), 16)), stem)
    return data.encode("latin-1").decode("utf-8", errors="replace")


def _names(stems) -> dict[str, str]:
    """The name of each of `stems` (in the order dumpStems made them): the
    name whose stem it is, so a `-N` dumpStems added is taken off again
    (a scene's names have no '-'). A name cut to 200 bytes stays cut."""
    taken: set = set()
    names = {}
    for stem in stems:
        candidates = [_unescape(stem)]
        match = re.fullmatch(r"(.+)-[0-9]+", stem)
        if match:
            candidates.insert(0, _unescape(match.group(1)))
        for name in candidates:
            trial = set(taken)
            if _next_stem(name, trial) == stem:
                break
        else:
            name = candidates[0]
        taken.update(stem + suffix for suffix in _DUMP_SUFFIXES)
        names[stem] = name
    return names


def _create_temporary(folder: str, name: str) -> tuple[int, str]:
    """A new file in `folder` for `name` to be written under: its
    descriptor (open for writing) and path. Made with the mode a new file
    of open() has (0666 less the umask), not tempfile's 0600."""
    while True:
        tmp = os.path.join(folder, f".{name}.{secrets.token_hex(4)}.tmp")
        try:
            return os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL |
                           getattr(os, "O_CLOEXEC", 0), 0o666), tmp
        except FileExistsError:
            continue


def _write_npz(f, arrays: dict):
    """Writes `arrays` to the open file `f` as numpy.savez does (an
    uncompressed zip of `<key>.npy`), closing the zip archive also when a
    write fails: numpy leaves it to the garbage collector, which then
    reports an error of its own ("Exception ignored in ZipFile.__del__")."""
    archive = zipfile.ZipFile(f, mode="w", compression=zipfile.ZIP_STORED,
                              allowZip64=True)
    try:
        for key, value in arrays.items():
            # Always zip64, as numpy (gh-10776).
            with archive.open(key + ".npy", "w", force_zip64=True) as member:
                np.lib.format.write_array(member, np.asanyarray(value))
    except BaseException:
        try:
            archive.close()  # Lets go of `f` even when this write fails.
        except Exception:
            pass
        raise
    archive.close()


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
        """The arrays of the `.npz` layout, by key (names escaped as
        sim-run escapes them; see the module)."""
        out = {"t": self.t, "time": self.time}
        # Errors and exact solutions share their buffer's stem.
        stem = _stems(dict.fromkeys([*self.buffers, *self.errors,
                                     *self.exact]))
        total_stem = _stems(self.totals)
        for name, values in self.buffers.items():
            out[f"buffer/{stem[name]}"] = values
        for name, values in self.totals.items():
            out[f"total/{total_stem[name]}"] = values
        for name, norms in self.errors.items():
            for norm, values in norms.items():
                out[f"error/{stem[name]}/{norm}"] = np.asarray(
                    values, dtype=np.float64)
        for name, values in self.exact.items():
            out[f"exact/{stem[name]}"] = values
        for key, value in self.meta.items():
            out[f"meta/{key}"] = np.array(str(value))
        return out

    def save(self, path) -> str:
        """Writes the output as `.npz` (uncompressed); returns the path.

        The file is written next to `path` under a temporary name and
        renamed onto it only once complete, so a write that fails (a full
        disk, a file size limit) leaves a file that was at `path` as it
        was and no partial file behind: it raises one OSError saying
        so."""
        path = str(path)
        arrays = self.arrays()
        # A symbolic link is written through, as open() would, onto its
        # target (renaming onto the link would replace the link).
        target = os.path.realpath(path) if os.path.islink(path) else path
        folder = os.path.dirname(os.path.abspath(target))
        kept = os.path.exists(target)
        tmp = None
        try:
            fd, tmp = _create_temporary(folder, os.path.basename(target))
            if kept:
                # The mode a file written over in place keeps.
                try:
                    os.chmod(tmp, stat.S_IMODE(os.stat(target).st_mode))
                except OSError:
                    pass
            with os.fdopen(fd, "wb") as f:
                _write_npz(f, arrays)
                f.flush()
                os.fsync(f.fileno())
            os.replace(tmp, target)
            tmp = None
        except OSError as error:
            reason = error.strerror or str(error)
            what = (f"{path} is left as it was" if kept
                    else f"no file was made")
            raise OSError(error.errno, f"Output.save: cannot write {path} "
                          f"({reason}); {what}") from None
        finally:
            if tmp is not None:
                try:
                    os.unlink(tmp)
                except OSError:
                    pass
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
        """An Output from the arrays of the layout by key (escaped names,
        decoded here)."""
        buffers, totals, errors, exact, meta = {}, {}, {}, {}, {}
        # The buffers' stems in the order they were made: those of buffer/
        # keys, then those only errors or exact solutions have.
        keys = [key.partition("/") for key in arrays]
        stems = dict.fromkeys(rest for kind, _, rest in keys
                              if kind == "buffer")
        stems.update(dict.fromkeys(
            rest.rpartition("/")[0] if kind == "error" else rest
            for kind, _, rest in keys if kind in ("exact", "error")))
        name = _names(stems)
        total_name = _names(rest for kind, _, rest in keys
                            if kind == "total")
        for key, value in arrays.items():
            kind, _, rest = key.partition("/")
            if kind == "buffer":
                buffers[name[rest]] = value
            elif kind == "total":
                totals[total_name[rest]] = value
            elif kind == "exact":
                exact[name[rest]] = value
            elif kind == "error":
                stem, _, norm = rest.rpartition("/")
                errors.setdefault(name[stem], {})[norm] = value
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
