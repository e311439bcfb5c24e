"""Rewrites a checkpoint's manifest and makes the file whole again.

    edit_checkpoint.py FLATC SCHEMA_DIR IN OUT STATEMENTS

Decodes IN's manifest to JSON with flatc, runs the Python STATEMENTS on it
(bound to `m`), encodes it again and writes OUT with the buffers' bytes, a
header and a CRC-32 that match (docs/Runtime.md, "Checkpoints"), so that
the runtime's checks of the manifest itself are what a test reaches.
"""

import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib

HEADER = 32
ALIGN = 64


def aligned(size):
    return (size + ALIGN - 1) // ALIGN * ALIGN


def main():
    flatc, schemas, source, target, statements = sys.argv[1:6]
    data = open(source, "rb").read()
    (manifest_bytes,) = struct.unpack_from("<I", data, HEADER)
    states = data[aligned(HEADER + 4 + manifest_bytes):]
    schema = os.path.join(schemas, "checkpoint.fbs")
    with tempfile.TemporaryDirectory() as work:
        raw = os.path.join(work, "manifest.bin")
        with open(raw, "wb") as out:
            out.write(data[HEADER:HEADER + 4 + manifest_bytes])
        subprocess.check_call([flatc, "--json", "--strict-json",
                               "--raw-binary", "--size-prefixed", "-I",
                               schemas, "-o", work, schema, "--", raw])
        text = os.path.join(work, "manifest.json")
        m = json.load(open(text))
        exec(statements, {"m": m})
        json.dump(m, open(text, "w"))
        subprocess.check_call([flatc, "--binary", "--size-prefixed", "-I",
                               schemas, "-o", work, schema, text])
        # The schema names the file extension flatc writes.
        manifest = open(os.path.join(work, "manifest.simc"), "rb").read()
    padding = aligned(HEADER + len(manifest)) - HEADER - len(manifest)
    body = manifest + b"\0" * padding + states
    header = b"SIMCKPT\0" + struct.pack("<IIQQ", 1, zlib.crc32(body),
                                        HEADER + len(body), 0)
    with open(target, "wb") as out:
        out.write(header + body)


if __name__ == "__main__":
    main()
