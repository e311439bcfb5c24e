"""Checks that every function of a bundle's CPU objects that keeps 32- or
64-byte registers on the stack realigns its frame to 64 bytes, so that its
spill slots lie on whole cache lines (lib/Target/CPU/CPUKernels.cpp).

usage: spill-alignment.py OBJDUMP BUNDLE
Prints one line per object and function checked; exits 1 at the first
function that spills wide registers without realigning."""
import re
import struct
import subprocess
import sys
import tempfile

objdump, bundle = sys.argv[1], sys.argv[2]
data = open(bundle, "rb").read()
start, objects = 0, []
while True:
    start = data.find(b"\x7fELF", start)
    if start < 0:
        break
    (shoff,) = struct.unpack_from("<Q", data, start + 0x28)
    shentsize, shnum = struct.unpack_from("<HH", data, start + 0x3A)
    size = shoff + shentsize * shnum
    objects.append(data[start : start + size])
    start += size

wide_stack = re.compile(
    r"vmov\w+\s+(%[yz]mm\d+,\s*-?(0x[0-9a-f]+)?\(%r(bp|sp|bx)\)"
    r"|-?(0x[0-9a-f]+)?\(%r(bp|sp|bx)\),\s*%[yz]mm\d+)")
realign = re.compile(r"and\w*\s+\$(-0x40|-0x20|0xffffffffffffff[ce]0),\s*%rsp")
failed = False
for index, obj in enumerate(objects):
    with tempfile.NamedTemporaryFile(suffix=".so") as f:
        f.write(obj)
        f.flush()
        text = subprocess.run(
            [objdump, "-d", "--no-show-raw-insn", f.name],
            capture_output=True, text=True, check=True).stdout
    functions = re.split(r"\n[0-9a-f]+ <([^>]+)>:\n", text)[1:]
    spilling = 0
    for name, body in zip(functions[0::2], functions[1::2]):
        if not wide_stack.search(body):
            continue
        spilling += 1
        if not realign.search(body):
            print(f"object {index}: {name} spills wide registers on a "
                  f"frame it does not realign")
            failed = True
    print(f"object {index}: {spilling} functions spill wide registers")
sys.exit(1 if failed else 0)
