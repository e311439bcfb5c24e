"""Checks that every function of CPU shared objects that keeps 32- or
64-byte registers on the stack realigns its frame, so that its spill slots
lie on whole cache lines (lib/Target/CPU/CPUKernels.cpp).

usage: spill-alignment.py OBJDUMP OBJECT...
Prints, per object, each function that spills wide registers without
realigning its frame and how many functions spill them; exits 1 if any
function does not realign."""
import os
import re
import subprocess
import sys

# A ymm or zmm register stored to or loaded from the frame.
wide_stack = re.compile(
    r"vmov\w+\s+(%[yz]mm\d+,\s*-?(0x[0-9a-f]+)?\(%r(bp|sp|bx)\)"
    r"|-?(0x[0-9a-f]+)?\(%r(bp|sp|bx)\),\s*%[yz]mm\d+)")
# The frame realigned to 32 or 64 bytes.
realign = re.compile(r"and\w*\s+\$(-0x40|-0x20),\s*%rsp")

objdump, objects = sys.argv[1], sys.argv[2:]
failed = False
for path in objects:
    text = subprocess.run([objdump, "-d", "--no-show-raw-insn", path],
                          capture_output=True, text=True, check=True).stdout
    functions = re.split(r"\n[0-9a-f]+ <([^>]+)>:\n", text)[1:]
    spilling = 0
    for name, body in zip(functions[0::2], functions[1::2]):
        if not wide_stack.search(body):
            continue
        spilling += 1
        if not realign.search(body):
            print("%s: %s spills wide registers on a frame it does not "
                  "realign" % (os.path.basename(path), name))
            failed = True
    print("%s: %d functions spill wide registers" %
          (os.path.basename(path), spilling))
sys.exit(1 if failed else 0)
