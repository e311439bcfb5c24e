"""Reading the .npy files sim-run --dump writes, with the standard library.

`read_npy(path)` returns the shape and the values (a flat list of floats) of a
little-endian `<f4` or `<f8` array, the only kinds sim-run writes (and the
raw bytes with `with_bytes=True`);
`compare(a, b)` the largest absolute difference and the RMS-relative
difference of two equally long lists (b the reference).
"""

import ast
import math
import struct

__all__ = ["read_npy", "compare"]


def read_npy(path, with_bytes=False):
    """Returns (shape, flat list of floats) of a little-endian f4/f8 .npy,
    and with `with_bytes` the raw data too (for comparing bit for bit)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:6] != b"\x93NUMPY":
        raise ValueError("%s is not a .npy file" % path)
    major = data[6]
    if major == 1:
        (length,) = struct.unpack("<H", data[8:10])
        start = 10
    else:
        (length,) = struct.unpack("<I", data[8:12])
        start = 12
    header = ast.literal_eval(data[start:start + length].decode("latin1"))
    code = {"<f4": "f", "<f8": "d"}.get(header["descr"])
    if code is None or header.get("fortran_order"):
        raise ValueError("%s: unsupported array %r" % (path, header))
    body = data[start + length:]
    count = len(body) // struct.calcsize(code)
    values = list(struct.unpack("<%d%s" % (count, code), body))
    return (header["shape"], values, body) if with_bytes else (header["shape"],
                                                                values)


def compare(a, b):
    """max-abs and RMS-relative difference of a against the reference b."""
    diff = [x - y for x, y in zip(a, b)]
    max_abs = max((abs(d) for d in diff), default=0.0)
    norm_b = math.sqrt(sum(y * y for y in b))
    norm_d = math.sqrt(sum(d * d for d in diff))
    rms_rel = norm_d / norm_b if norm_b > 0 else (0.0 if norm_d == 0 else
                                                  math.inf)
    return {"max_abs": max_abs, "rms_rel": rms_rel}
