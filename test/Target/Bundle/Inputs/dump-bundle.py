#!/usr/bin/env python3
"""Prints a .simb bundle (docs/Bundle.md, format 2) for FileCheck.

Checks the 32-byte header (magic, version 7, the file size, zlib's CRC-32 of
everything after the header, the reserved field), decodes the FlatBuffer
after it with flatc into JSON (flatc --json --strict-json --raw-binary
--defaults-json, against runtime/schema/bundle.fbs), and prints one line
per record with every index resolved to the name it points at: the scene,
each plan (buffers, components, totals, kernels with their parameters,
phases of launches with their arguments), whether every launch matches the
kernel it calls, whether every kernel is a PTX `.entry` and an exported
`sim_cpu_<kernel>` of the CPU shared object (read from its ELF dynamic
symbol table), and the reference model. Exits with 1 and a line starting
with `error:` on the first problem.

Usage: dump-bundle.py --flatc FLATC --schema bundle.fbs BUNDLE
       dump-bundle.py --flatc FLATC --schema bundle.fbs --json BUNDLE
(--json checks the header and prints the decoded JSON instead, every key
sorted.)
"""

import argparse
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import zlib

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "..", "python"))
from simlists import STRATEGIES, schema_name  # noqa: E402

HEADER_SIZE = 32
MAGIC = b"SIMBNDL\0"
MEMORY_ARGS = {"Clock", "Buffer", "Snapshot", "Exact", "Total", "Levels"}


def fail(message):
    print("error: " + message)
    sys.exit(1)


def name(text):
    """A name as it is when it is a plain word, else quoted as JSON."""
    if re.fullmatch(r"[A-Za-z0-9_.$-]+", text):
        return text
    return json.dumps(text, ensure_ascii=False)


def elf_exports(data, what):
    """The defined global symbols of an ELF64 little-endian shared object."""
    if data[:4] != b"\x7fELF" or data[4] != 2 or data[5] != 1:
        fail("%s is not a 64-bit little-endian ELF file" % what)
    (e_type,) = struct.unpack_from("<H", data, 0x10)
    if e_type != 3:
        fail("%s is an ELF file of type %d, not a shared object"
             % (what, e_type))
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
            sym, info, _, shndx, _, _ = struct.unpack_from(
                "<IBBHQQ", data, offset + i * entsize)
            if shndx != 0 and info >> 4 == 1:  # defined, STB_GLOBAL
                end = data.index(b"\0", strtab + sym)
                names.add(data[strtab + sym:end].decode())
    return names


def check_header(data, quiet):
    if len(data) < HEADER_SIZE:
        fail("the file has %d bytes, fewer than the %d-byte header"
             % (len(data), HEADER_SIZE))
    magic, version, crc, size, reserved = struct.unpack_from("<8sIIQQ", data)
    if magic != MAGIC:
        fail("the magic is %r, not %r" % (magic, MAGIC))
    if version != 7:
        fail("the format version is %d, not 7" % version)
    if size != len(data):
        fail("the header gives a size of %d bytes, the file has %d"
             % (size, len(data)))
    actual = zlib.crc32(data[HEADER_SIZE:]) & 0xFFFFFFFF
    if crc != actual:
        fail("the header's CRC-32 is %08x, the payload's is %08x"
             % (crc, actual))
    if reserved:
        fail("the reserved field is %d, not 0" % reserved)
    if not quiet:
        print("header: magic SIMBNDL, version 7, size %d (the file's), "
              "crc32 matches the payload, reserved 0" % size)


def decode(flatc, schema, payload):
    """The FlatBuffer `payload` as flatc's JSON."""
    with tempfile.TemporaryDirectory() as tmp:
        binary = os.path.join(tmp, "bundle.bin")
        with open(binary, "wb") as f:
            f.write(payload)
        result = subprocess.run(
            [flatc, "--json", "--strict-json", "--raw-binary",
             "--defaults-json", "-o", tmp, schema, "--", binary],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        if result.returncode != 0:
            fail("flatc cannot decode the payload: " +
                 result.stdout.decode(errors="replace").strip())
        with open(os.path.join(tmp, "bundle.json"), encoding="utf-8") as f:
            return json.load(f)


def element(e):
    return e["scalar"] + ("x%d" % e["lanes"] if e["lanes"] != 1 else "")


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def value(v):
    """A Value; flatc writes doubles with 12 significant digits, so an f32
    is printed as the shortest decimal of the float those digits round to."""
    x = v["float_value"]
    if v["type"] == "F32":
        text = next(t for t in ("%.*g" % (d, x) for d in range(1, 18))
                    if f32(float(t)) == f32(x))
        return "F32 " + text
    if v["type"] == "F64":
        return "F64 %r" % x
    return "%s %d" % (v["type"], v["int_value"])


def precision(record, scalar):
    """" from f32" where the values derive from narrower floats than their
    own type (precision_bytes); "" where they do not."""
    own = {"F32": 4, "F64": 8}[scalar]
    bytes_ = record.get("precision_bytes", 0)
    if bytes_ not in (0, 4, 8):
        fail("precision_bytes %d is not 0, 4 or 8" % bytes_)
    return " from f32" if bytes_ and bytes_ < own else ""


def dump_scene(scene):
    print("scene %s range %d dt %s max_steps %d" % (
        name(scene["name"]), scene["range"], value(scene["dt"]),
        scene["max_steps"]))
    for i, p in enumerate(scene.get("params", [])):
        print("param %d %s %s" % (i, name(p["name"]), value(p["value"])))
    buffers = scene.get("buffers", [])
    for i, b in enumerate(buffers):
        interp = b["interp"]
        if interp == "Hermite":
            d = b["derivative"]
            if not 0 <= d < len(buffers):
                fail("buffer %d's derivative %d is not a scene buffer" % (i, d))
            interp += "(%s)" % name(buffers[d]["name"])
        elif b["derivative"] != -1:
            fail("buffer %d is not Hermite but has a derivative" % i)
        print("buffer %d %s %s interp %s boundary %s%s%s%s" % (
            i, name(b["name"]), element(b["element"]), interp, b["boundary"],
            " observed" if b["observed"] else "",
            " exact" if b["exact"] else "",
            precision(b, b["element"]["scalar"])))
    for i, t in enumerate(scene.get("totals", [])):
        print("total %d %s %s%s" % (i, name(t["name"]), t["type"],
                                    precision(t, t["type"])))


def dump_steps(steps, plan, names, depth, launches):
    indent = "  " * depth
    for step in steps:
        if "repeat" in step:
            print("%srepeat %d" % (indent, step["repeat"]["count"]))
            dump_steps(step["repeat"]["body"], plan, names, depth + 1,
                       launches)
            print("%send" % indent)
            continue
        launch = step["launch"]
        launches.append(launch)
        kernels = plan.get("kernels", [])
        if not 0 <= launch["kernel"] < len(kernels):
            fail("a launch names kernel %d of %d" % (launch["kernel"],
                                                     len(kernels)))
        component = launch["component"]
        args = []
        for arg in launch["args"]:
            kind, index = arg["kind"], arg["index"]
            table = {"Buffer": "buffers", "Snapshot": "buffers",
                     "Exact": "buffers", "Param": "params",
                     "Total": "totals", "Levels": "components"}.get(kind)
            if table is None:
                if index:
                    fail("a %s argument has index %d" % (kind, index))
                args.append(kind.lower())
                continue
            if not 0 <= index < len(names[table]):
                fail("a %s argument names %d of %d" % (kind, index,
                                                       len(names[table])))
            args.append("%s:%s" % (kind.lower(), names[table][index]))
        components = plan.get("components", [])
        if component != -1 and not 0 <= component < len(components):
            fail("a launch is for component %d of %d" % (component,
                                                         len(components)))
        print("%slaunch %s %s for %s shared %d %d args %s" % (
            indent, name(kernels[launch["kernel"]]["name"]),
            launch["shape"].lower(),
            name(components[component]["name"]) if component != -1 else "-",
            launch["shared_per_thread"], launch["shared_fixed"],
            " ".join(args)))


def check_launches(plan, launches):
    """Whether each launch passes what its kernel takes."""
    problems = []
    for launch in launches:
        kernel = plan["kernels"][launch["kernel"]]
        params = kernel["params"]
        if len(params) != len(launch["args"]):
            problems.append("%s: %d arguments, %d parameters" % (
                kernel["name"], len(launch["args"]), len(params)))
            continue
        for arg, param in zip(launch["args"], params):
            if (arg["kind"] in MEMORY_ARGS) != (param["type"] == "Memref"):
                problems.append("%s: %s for a %s parameter" % (
                    kernel["name"], arg["kind"], param["type"]))
        if (launch["shared_per_thread"], launch["shared_fixed"]) != (
                kernel["shared_per_thread"], kernel["shared_fixed"]):
            problems.append("%s: shared memory" % kernel["name"])
        if kernel["clock_slots"] != plan["clock_slots"]:
            problems.append("%s: clock slots" % kernel["name"])
    if problems:
        fail("launches that do not match their kernels: " +
             "; ".join(problems))
    print("%d launches, every one matches its kernel" % len(launches))


def param(p):
    if p["type"] != "Memref":
        return p["type"].lower()
    return "memref<%s stride %d>" % (element(p["element"]), p["stride"])


def dump_plan(index, plan, scene):
    print("--- plan %d %s group_size %d step_cap %d clock_slots %d "
          "histogram %d" % (index, plan["strategy"], plan["group_size"],
                            plan["step_cap"], plan["clock_slots"],
                            plan["histogram"]))
    scene_buffers = scene.get("buffers", [])
    scene_totals = scene.get("totals", [])
    names = {"buffers": [], "totals": [],
             "params": [name(p["name"]) for p in scene.get("params", [])],
             "components": [name(c["name"])
                            for c in plan.get("components", [])]}
    for i, b in enumerate(plan.get("buffers", [])):
        if not 0 <= b["buffer"] < len(scene_buffers):
            fail("plan buffer %d is scene buffer %d of %d" % (
                i, b["buffer"], len(scene_buffers)))
        names["buffers"].append(name(scene_buffers[b["buffer"]]["name"]))
        print("buffer %d %s stride %d%s" % (i, names["buffers"][-1],
                                             b["stride"],
                                             " snapshot" if b["snapshot"]
                                             else ""))
    for i, c in enumerate(plan.get("components", [])):
        for w in c["writes"]:
            if not 0 <= w < len(names["buffers"]):
                fail("component %d writes plan buffer %d" % (i, w))
        sub_clock = c["sub_clock"]
        print("component %d %s writes %s evaluations %d advance %s%s%s" % (
            i, name(c["name"]), " ".join(names["buffers"][w]
                                         for w in c["writes"]),
            c["evaluations"], c["advance"],
            " estimates" if c["estimates"] else "",
            " sub_clock %d" % sub_clock
            if sub_clock or c["advance"] == "GridSubSteps" else ""))
    for i, t in enumerate(plan.get("totals", [])):
        if not 0 <= t < len(scene_totals):
            fail("plan total %d is scene total %d" % (i, t))
        names["totals"].append(name(scene_totals[t]["name"]))
        print("total %d %s" % (i, names["totals"][-1]))
    for i, k in enumerate(plan.get("kernels", [])):
        print("kernel %d %s(%s) shared %d %d clock_slots %d%s" % (
            i, name(k["name"]), ", ".join(param(p) for p in k["params"]),
            k["shared_per_thread"], k["shared_fixed"], k["clock_slots"],
            " uneven_groups" if k.get("uneven_groups") else ""))
    launches = []
    for phase in plan.get("phases", []):
        print("phase %s" % phase["kind"])
        dump_steps(phase["body"], plan, names, 1, launches)
    check_launches(plan, launches)

    kernels = [k["name"] for k in plan.get("kernels", [])]
    ptx = plan.get("ptx")
    if ptx is None:
        print("ptx: none")
    else:
        entries = set(re.findall(r"\.entry (\S+?)\(", ptx))
        missing = [k for k in kernels if k not in entries]
        target = re.search(r"^\.target \S+", ptx, re.M)
        print("ptx: %s, chip %s, %d kernels, %s" % (
            target.group(0) if target else "no .target",
            plan.get("ptx_chip", "none"), len(kernels),
            "missing " + " ".join(missing) if missing
            else "every one an .entry"))
    for cpu in plan.get("cpu", []):
        exports = elf_exports(bytes(cpu["object"]), "a CPU object")
        missing = [k for k in kernels if "sim_cpu_" + k not in exports]
        print("cpu %s: shared object, %d kernels, %s" % (
            cpu["isa"], len(kernels), "missing " + " ".join(missing)
            if missing else "every one exported"))


def dump_reference(reference, scene):
    print("--- reference")
    scene_params = scene.get("params", [])
    scene_buffers = scene.get("buffers", [])
    scene_totals = scene.get("totals", [])
    for i, p in enumerate(reference.get("params", [])):
        if not 0 <= p < len(scene_params):
            fail("model parameter %d is scene parameter %d" % (i, p))
        print("param %d %s" % (i, name(scene_params[p]["name"])))
    buffers = []
    for i, b in enumerate(reference.get("buffers", [])):
        if not 0 <= b < len(scene_buffers):
            fail("model buffer %d is scene buffer %d" % (i, b))
        buffers.append(name(scene_buffers[b]["name"]))
        print("buffer %d %s" % (i, buffers[-1]))

    def model_buffers(indices):
        for b in indices:
            if not 0 <= b < len(buffers):
                fail("a model buffer index %d of %d" % (b, len(buffers)))
        return " ".join(buffers[b] for b in indices) or "-"

    strategies = [schema_name(s) for s in STRATEGIES]
    for i, c in enumerate(reference.get("components", [])):
        if len(c["stepping"]) != len(strategies):
            fail("component %d has %d steppings" % (i, len(c["stepping"])))
        stepping = " ".join(
            "%s:%s%s" % (s, st["advance"], "+estimates"
                         if st["estimates"] else "")
            for s, st in zip(strategies, c["stepping"]))
        window = c.get("local_window", [])
        print("component %d %s %s%s writes %s reads %s%s" % (
            i, name(c["name"]), c["sub_stepping"],
            " num_steps" if c["num_steps"] else "",
            model_buffers(c["writes"]), model_buffers(c.get("reads", [])),
            " local_window %s" % " ".join(str(w) for w in window)
            if window else ""))
        print("  stepping %s" % stepping)
    for t in reference.get("totals", []):
        if not 0 <= t["total"] < len(scene_totals):
            fail("a reference total is scene total %d" % t["total"])
        print("total %s reads %s" % (name(scene_totals[t["total"]]["name"]),
                                     model_buffers(t.get("reads", []))))
    exports = sorted(e for e in elf_exports(bytes(reference["object"]),
                                            "the reference object")
                     if e.startswith("sim_ref_"))
    print("functions %s: shared object, exports %s" % (reference["isa"],
                                                        " ".join(exports)))


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    parser.add_argument("--flatc", required=True)
    parser.add_argument("--schema", required=True)
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--extract-cpu", metavar="DIR",
                        help="also write each plan's CPU shared objects as "
                        "DIR/plan<index>-<isa>.so")
    parser.add_argument("bundle")
    args = parser.parse_args()

    with open(args.bundle, "rb") as f:
        data = f.read()
    check_header(data, quiet=args.json)
    bundle = decode(args.flatc, args.schema, data[HEADER_SIZE:])
    if args.extract_cpu:
        os.makedirs(args.extract_cpu, exist_ok=True)
        for i, plan in enumerate(bundle.get("plans", [])):
            for cpu in plan.get("cpu", []):
                path = os.path.join(args.extract_cpu,
                                    "plan%d-%s.so" % (i, cpu["isa"]))
                with open(path, "wb") as f:
                    f.write(bytes(cpu["object"]))
    if args.json:
        json.dump(bundle, sys.stdout, indent=1, sort_keys=True)
        print()
        return
    print("producer %s" % bundle.get("producer", "none"))
    scene = bundle["scene"]
    dump_scene(scene)
    for i, plan in enumerate(bundle.get("plans", [])):
        dump_plan(i, plan, scene)
    if "reference" in bundle:
        dump_reference(bundle["reference"], scene)
    else:
        print("--- no reference")


if __name__ == "__main__":
    main()
