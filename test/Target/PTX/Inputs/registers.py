#!/usr/bin/env python3
"""Registers of sim's GPU kernels against the hand-written CUDA baseline.

`ptxas -v` prints, for every kernel it assembles, its registers, stack
frame and spill bytes. This script compares those of sim's evaluate and
sub-step kernels with the hand-written kernel of the same component in
bench/cuda/baseline.cu (issue 17: at most 1.25x its registers, no spill, no
stack frame). The hand-written counts come from a data file, so that the
check runs where ptxas exists but nvcc does not:

  hand-written  compiles bench/cuda/baseline.cu with nvcc as
                bench/cuda/CMakeLists.txt does (-O3 -arch=sm_90
                -fmad=false) plus -Xptxas -v, and writes the data file:
                one line per scene, sim kernel and strategy.

                  registers.py hand-written --source bench/cuda/baseline.cu \\
                      -o test/Target/PTX/Inputs/hand-written-registers.txt

  check         reads the `ptxas -v` output of one scene and strategy and
                prints one line per evaluate and sub-step kernel; exits
                with 1 when one has more than --ratio times the registers
                of its hand-written kernel, spills, has a stack frame or
                has no hand-written kernel to compare with.

                  registers.py check --hand-written FILE --scene S \\
                      --strategy ST [--ratio 1.25] [--allow K=R]... PTXAS_LOG

                --allow K=R lets kernel K have up to R times the
                hand-written registers instead (a known exception, which
                the test that passes it says why it accepts).

Which hand-written kernel stands for which of sim's: `evaluateKernel<Scene,
Component k>` for `evaluate_Ck` under every strategy (simple, traditional,
and the components hip evaluates once per big step), `substepKernel<Scene,
Component k, false>` for `substep_Ck` under hip and `substepKernel<...,
true>` (shared-memory caches) for `substep_Ck` under hip-cache.

Standard library only.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

SCENES = {"GravityLike": "gravity_like", "PbdLike": "pbd_like"}
EVERY_STRATEGY = "*"

ENTRY = re.compile(r"Compiling entry function '([^']+)'")
FRAME = re.compile(r"(\d+) bytes stack frame, (\d+) bytes spill stores, "
                   r"(\d+) bytes spill loads")
USED = re.compile(r"Used (\d+) registers")


def parse_ptxas(text):
    """Returns {kernel: {registers, stack, spill_stores, spill_loads}} from
    the output of `ptxas -v`, in the order ptxas prints them."""
    kernels = {}
    current = None
    for line in text.splitlines():
        match = ENTRY.search(line)
        if match:
            current = kernels.setdefault(match.group(1), {})
            continue
        if current is None:
            continue
        match = FRAME.search(line)
        if match:
            current["stack"], current["spill_stores"], \
                current["spill_loads"] = map(int, match.groups())
            continue
        match = USED.search(line)
        if match:
            current["registers"] = int(match.group(1))
    return kernels


def hand_written_key(mangled):
    """(scene, sim kernel, strategy) of a baseline kernel's mangled name, or
    None for the kernels no sim kernel is compared with (init, advance,
    estimate)."""
    kind = re.search(r"(evaluateKernel|substepKernel)I", mangled)
    scene = re.search(r"\d(" + "|".join(SCENES) + r")(?:E|\d)", mangled)
    component = re.search(r"ComponentILi(\d+)E", mangled)
    if not (kind and scene and component):
        return None
    name = SCENES[scene.group(1)]
    if kind.group(1) == "evaluateKernel":
        return name, "evaluate_C" + component.group(1), EVERY_STRATEGY
    cache = re.search(r"ELb([01])EE", mangled)
    if not cache:
        return None
    strategy = "hip-cache" if cache.group(1) == "1" else "hip"
    return name, "substep_C" + component.group(1), strategy


def find_host_compiler():
    # bench/cuda/CMakeLists.txt: GCC, which every CUDA release on Debian 12
    # accepts as its host compiler.
    for name in ("g++-12", "g++"):
        path = shutil.which(name)
        if path:
            return path
    return None


def hand_written(args):
    nvcc = args.nvcc or shutil.which("nvcc") or "/usr/local/cuda/bin/nvcc"
    flags = ["-O3", "-arch=" + args.arch, "-fmad=false", "-std=c++17",
             "-diag-suppress", "177"]
    host = find_host_compiler()
    # bench/common/BaselineOptions.h includes runtime/tools/CommandLine.h,
    # as bench/cuda/CMakeLists.txt says.
    tools = os.path.join(os.path.dirname(os.path.abspath(args.source)),
                         os.pardir, os.pardir, "runtime", "tools")
    with tempfile.TemporaryDirectory() as scratch:
        command = [nvcc] + flags + (["-ccbin", host] if host else []) + [
            "-I", os.path.normpath(tools),
            "-Xptxas", "-v", "-c", args.source,
            "-o", os.path.join(scratch, "baseline.o")]
        result = subprocess.run(command, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True)
    if result.returncode != 0:
        sys.stderr.write(result.stdout)
        print("registers.py: nvcc failed: " + " ".join(command),
              file=sys.stderr)
        return 1
    version = [line for line in subprocess.run(
        [nvcc, "--version"], stdout=subprocess.PIPE,
        text=True).stdout.splitlines() if "release" in line]
    rows = []
    for mangled, info in parse_ptxas(result.stdout).items():
        key = hand_written_key(mangled)
        if key:
            rows.append(key + (info["registers"],))
    rows.sort(key=lambda row: (row[0], row[1], row[2]))
    lines = [
        "# Registers of the hand-written CUDA kernels of bench/cuda/"
        "baseline.cu, which",
        "# test/Target/PTX/registers.test compares sim's kernels with. "
        "Regenerate with",
        "#   test/Target/PTX/Inputs/registers.py hand-written "
        "--source bench/cuda/baseline.cu \\",
        "#     -o test/Target/PTX/Inputs/hand-written-registers.txt",
        "# nvcc " + " ".join(flags) + " -Xptxas -v: " +
        (version[-1] if version else "unknown version"),
        "# scene sim-kernel strategy registers (strategy * : every one)",
    ]
    lines += ["%s %s %s %d" % row for row in rows]
    text = "\n".join(lines) + "\n"
    if args.output == "-":
        sys.stdout.write(text)
    else:
        with open(args.output, "w") as out:
            out.write(text)
    return 0


def read_hand_written(path):
    table = {}
    with open(path) as data:
        for line in data:
            line = line.split("#", 1)[0].split()
            if not line:
                continue
            scene, kernel, strategy, registers = line
            table[(scene, kernel, strategy)] = int(registers)
    return table


def check(args):
    table = read_hand_written(args.hand_written)
    allowed = {}
    for exception in args.allow:
        kernel, _, ratio = exception.partition("=")
        allowed[kernel] = float(ratio)
    with open(args.log) as log:
        kernels = parse_ptxas(log.read())
    failures = 0
    checked = 0
    for kernel, info in kernels.items():
        if not re.fullmatch(r"(evaluate|substep)_C\d+", kernel):
            continue
        checked += 1
        problems = []
        registers = info.get("registers")
        if registers is None or "stack" not in info:
            problems.append("no register count from ptxas")
        # The paper scenes read no buffer of their own at other items, so
        # lts compiles the kernels of hip (and bench/cuda runs lts as hip).
        compared = "hip" if args.strategy == "lts" else args.strategy
        reference = table.get((args.scene, kernel, compared),
                              table.get((args.scene, kernel, EVERY_STRATEGY)))
        line = "%s %s %s: %s registers" % (args.scene, args.strategy, kernel,
                                            registers)
        limit = allowed.get(kernel, args.ratio)
        if reference is None:
            problems.append("no hand-written kernel to compare with")
        elif registers is not None:
            ratio = registers / reference
            line += ", hand-written %d (%.2fx)" % (reference, ratio)
            if ratio > limit:
                problems.append("more than %.2fx the hand-written kernel's "
                                "registers" % limit)
        if "stack" in info:
            line += ", stack %d, spills %d/%d" % (
                info["stack"], info["spill_stores"], info["spill_loads"])
            if info["spill_stores"] or info["spill_loads"]:
                problems.append("spills")
            if info["stack"]:
                problems.append("a stack frame")
        if problems:
            failures += 1
            line += ": FAIL (" + "; ".join(problems) + ")"
        elif kernel in allowed:
            line += ": ok (allowed up to %.2fx)" % limit
        else:
            line += ": ok"
        print(line)
    for kernel in allowed:
        if kernel not in kernels:
            failures += 1
            print("%s %s %s: allowed, but ptxas compiled no such kernel: FAIL"
                  % (args.scene, args.strategy, kernel))
    if not checked:
        print("%s %s: no evaluate or sub-step kernel in %s: FAIL" %
              (args.scene, args.strategy, args.log))
        return 1
    return 1 if failures else 0


def main(argv):
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    written = commands.add_parser("hand-written")
    written.add_argument("--source", required=True)
    written.add_argument("--nvcc")
    written.add_argument("--arch", default="sm_90")
    written.add_argument("-o", "--output", default="-")
    checking = commands.add_parser("check")
    checking.add_argument("--hand-written", required=True)
    checking.add_argument("--scene", required=True)
    checking.add_argument("--strategy", required=True)
    checking.add_argument("--ratio", type=float, default=1.25)
    checking.add_argument("--allow", action="append", default=[],
                          metavar="KERNEL=RATIO")
    checking.add_argument("log")
    args = parser.parse_args(argv)
    if args.command == "hand-written":
        return hand_written(args)
    return check(args)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
