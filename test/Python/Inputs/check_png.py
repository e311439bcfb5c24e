"""Checks that each argument is a PNG image of a plausible size."""
import struct
import sys

for path in sys.argv[1:]:
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path} is not a PNG file")
    width, height = struct.unpack(">II", data[16:24])
    if not (200 <= width <= 4000 and 200 <= height <= 4000):
        sys.exit(f"{path}: odd size {width}x{height}")
print("ok")
