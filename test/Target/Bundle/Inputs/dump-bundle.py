#!/usr/bin/env python3
"""Prints a .simb bundle (docs/Bundle.md) for FileCheck, checking its layout.

The header and the section table one line each, then every section: the
text of scene and plan sections, and for the kernel sections whether every
kernel a plan launches is a PTX `.entry` and a `sim_cpu_<kernel>` the CPU
shared object exports (read from its ELF dynamic symbol table). Standard
library only. Exits with 1 and a message on the first layout error.

Usage: dump-bundle.py BUNDLE
"""

import re
import struct
import sys

KINDS = {1: "scene", 2: "plan", 3: "ptx", 4: "cpu", 5: "reference-model",
         6: "reference-functions"}
STRATEGIES = {0: "simple", 1: "traditional", 2: "hip", 3: "hip-cache",
              0xFFFFFFFF: "-"}


def fail(message):
    print("error: " + message)
    sys.exit(1)


def elf_exports(data):
    """The defined global symbols of an ELF64 little-endian shared object."""
    if data[:4] != b"\x7fELF" or data[4] != 2 or data[5] != 1:
        fail("the CPU section is not a 64-bit little-endian ELF file")
    (e_type,) = struct.unpack_from("<H", data, 0x10)
    if e_type != 3:
        fail("the CPU section is an ELF file of type %d, not a shared object"
             % e_type)
    shoff, = struct.unpack_from("<Q", data, 0x28)
    shentsize, shnum = struct.unpack_from("<HH", data, 0x3A)
    sections = [struct.unpack_from("<IIQQQQIIQQ", data, shoff + i * shentsize)
                for i in range(shnum)]
    names = set()
    for _, sh_type, _, _, offset, size, link, _, _, entsize in sections:
        if sh_type != 11:  # SHT_DYNSYM
            continue
        strtab = sections[link][4]
        for i in range(size // entsize):
            name, info, _, shndx, _, _ = struct.unpack_from(
                "<IBBHQQ", data, offset + i * entsize)
            if shndx != 0 and info >> 4 == 1:  # defined, STB_GLOBAL
                end = data.index(b"\0", strtab + name)
                names.add(data[strtab + name:end].decode())
    return names


def main():
    data = open(sys.argv[1], "rb").read()
    magic, version, count, size = struct.unpack_from("<8sIIQ", data, 0)
    print("magic %r version %d sections %d size %d" %
          (magic, version, count, size))
    if size != len(data):
        fail("the header says %d bytes, the file has %d" % (size, len(data)))
    table_end = 24 + 32 * count
    sections = []
    for i in range(count):
        kind, strategy, offset, length, reserved = struct.unpack_from(
            "<IIQQQ", data, 24 + 32 * i)
        print("section %d: %s %s at %d, %d bytes" %
              (i, KINDS.get(kind, "?%d" % kind),
               STRATEGIES.get(strategy, "?%d" % strategy), offset, length))
        if offset % 8 or offset < table_end or offset + length > len(data):
            fail("section %d is misplaced" % i)
        if reserved:
            fail("section %d has a nonzero reserved field" % i)
        sections.append((kind, STRATEGIES[strategy], offset, length))
    spans = sorted((offset, offset + length) for _, _, offset, length
                   in sections)
    for (_, end), (begin, _) in zip(spans, spans[1:]):
        if begin < end:
            fail("sections overlap")

    kernels = {}
    for kind, strategy, offset, length in sections:
        body = data[offset:offset + length]
        if kind in (1, 2, 5):
            print("--- %s %s" % (KINDS[kind], strategy))
            sys.stdout.write(body.decode())
            if kind == 2:
                kernels[strategy] = sorted(set(re.findall(
                    r"^launch (\S+)", body.decode(), re.M)))
    print("--- kernels")
    for kind, strategy, offset, length in sections:
        body = data[offset:offset + length]
        wanted = kernels.get(strategy, [])
        if kind == 3:
            if not body.endswith(b"\0") or b"\0" in body[:-1]:
                fail("the PTX of %s is not NUL-terminated text" % strategy)
            entries = set(re.findall(r"\.entry (\w+)\(", body.decode()))
            missing = [k for k in wanted if k not in entries]
            print("--- ptx %s: %s, %d kernels, %s" % (
                strategy, re.search(r"^\.target \S+", body.decode(),
                                    re.M).group(0),
                len(wanted), "missing " + " ".join(missing) if missing
                else "every one an .entry"))
        elif kind == 6:
            exports = sorted(e for e in elf_exports(body)
                             if e.startswith("sim_ref_"))
            print("--- reference functions: shared object, exports %s" %
                  " ".join(exports))
        elif kind == 4:
            exports = elf_exports(body)
            missing = [k for k in wanted if "sim_cpu_" + k not in exports]
            print("--- cpu %s: shared object, %d kernels, %s" % (
                strategy, len(wanted), "missing " + " ".join(missing)
                if missing else "every one exported"))


if __name__ == "__main__":
    main()
