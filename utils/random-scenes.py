#!/usr/bin/env python3
"""Random scenes, written the way users write them, run under every
strategy on the CPU backend and checked against the reference executor
bit for bit.

Each seed gives one scene (the same scene on every machine and every run).
Two shapes:

  stencil  one to four components in a random schedule over one to five
           buffers (f32, f64 or vectors of them; linear, cubic or no
           interpolation; clamp, zero or wrap boundaries); each reads its
           own and earlier components' buffers through windows up to
           i-40..i+40 and through gathers, the first one also through the
           back edge; num_steps constant, by region, by a band that moves
           with the time, by item, from the state, or out of range (0,
           negative, INT32_MAX), or no num_steps at all
  pair     a writer and a reader that may form a flux pair or an item pair
           under lts (docs/Model.md), sometimes breaking one of its rules,
           sometimes followed by a third component and a total

Every scene is compiled with `sim-translate --sim-to-bundle`. A scene the
compiler rejects with a diagnostic counts as rejected (its first error is
printed with -v); a compiler that crashes, or a run that disagrees with the
reference executor, fails the check. Each scene runs on the CPU backend
for every strategy, also with groups of 7 items and on 2 threads, with
--output-every 7 (hip, lts), and lts with the per-lane level limit
(--sim-cpu-levels-per-lane) at groups of 1 and 64. A run whose state
grows past the floats (NaN or infinity on both executors) counts as
diverged, not failed: the scene is useless, not wrong.

usage: utils/random-scenes.py [--seeds A-B|N ...] [--shape stencil|pair|any]
         [--jobs J] [--keep DIR] [--sim-translate PATH] [--sim-run PATH] [-v]

Writes one line per failure with the seed, the scene's path (under --keep,
else a temporary folder that is then removed) and the command that failed;
exits with 1 when something failed. `--print SEED` writes one seed's scene
to stdout. docs/Testing.md, "Random scenes".
"""

import argparse
import concurrent.futures
import os
import random
import shutil
import subprocess
import sys
import tempfile

NUM_STEPS_RULES = ["const", "region", "band", "item", "state", "out-of-range"]


class SceneWriter:
    """What both shapes share: value names, init bodies, index expressions
    and num_steps rules."""

    def __init__(self, seed):
        self.rng = random.Random(seed)
        self.count = 0
        self.lines = []

    def fresh(self):
        self.count += 1
        return f"%v{self.count}"

    def emit(self, text):
        self.lines.append("    " + text)

    def int_constant(self, value, ty="i32"):
        name = self.fresh()
        self.emit(f"{name} = arith.constant {value} : {ty}")
        return name

    def float_constant(self, value):
        """A constant of the buffers' type (a splat for vectors)."""
        name = self.fresh()
        if self.buffer_type == self.scalar:
            self.emit(f"{name} = arith.constant {value:.6e} : {self.scalar}")
        else:
            self.emit(f"{name} = arith.constant dense<{value:.6e}> : "
                      f"{self.buffer_type}")
        return name

    def buffer(self, out, name, attrs):
        """A buffer whose init varies smoothly with the item (and the lane)."""
        rng = self.rng
        scalar, ty = self.scalar, self.buffer_type
        out.append(f"  sim.buffer {name} : {ty}{attrs} init {{")
        out.append("  ^bb0(%i: index):")
        body = [
            "%i64 = arith.index_cast %i : index to i64",
            f"%f = arith.sitofp %i64 : i64 to {scalar}",
            f"%s = arith.constant {rng.choice(['1.0e-1', '3.0e-1', '7.0e-2', '1.3'])} : {scalar}",
            f"%a = arith.mulf %f, %s : {scalar}",
            f"%x = math.{rng.choice(['sin', 'cos'])} %a : {scalar}",
        ]
        if ty == scalar:
            body.append(f"sim.yield %x : {scalar}")
        else:
            lanes = ty.replace(scalar, "index")
            ints = ty.replace(scalar, "i32")
            body += [
                f"%xv = vector.broadcast %x : {scalar} to {ty}",
                f"%k = vector.step : {lanes}",
                f"%ki = arith.index_cast %k : {lanes} to {ints}",
                f"%kf = arith.sitofp %ki : {ints} to {ty}",
                f"%y = arith.addf %xv, %kf : {ty}",
                f"sim.yield %y : {ty}",
            ]
        out += ["    " + line for line in body]
        out.append("  }")

    def index(self, where):
        """%i, %i plus a constant offset, or a gather (%i * k mod range)."""
        if where == "gather":
            k = self.int_constant(self.rng.choice([3, 7, 11]), "index")
            product = self.fresh()
            self.emit(f"{product} = arith.muli %i, {k} : index")
            bound = self.int_constant(self.range, "index")
            j = self.fresh()
            self.emit(f"{j} = arith.remui {product}, {bound} : index")
            return j
        if where == 0:
            return "%i"
        offset = self.int_constant(abs(where), "index")
        j = self.fresh()
        op = "addi" if where > 0 else "subi"
        self.emit(f"{j} = arith.{op} %i, {offset} : index")
        return j

    def read(self, buffer, where):
        """A read of `buffer` at `where` (see index)."""
        value = self.fresh()
        self.emit(f"{value} = sim.read {buffer}[{self.index(where)}] : "
                  f"{self.buffer_type}")
        return value

    def first_lane(self, value):
        if self.buffer_type == self.scalar:
            return value
        lane = self.fresh()
        self.emit(f"{lane} = vector.extract {value}[0] : {self.scalar} from "
                  f"{self.buffer_type}")
        return lane

    def num_steps(self, readable):
        """A num_steps body's lines; returns the yielded value."""
        rng = self.rng
        rule = rng.choice(NUM_STEPS_RULES)
        low = rng.choice([1, 1, 2, 0, -3])
        high = rng.choice([2, 4, 8, self.max_steps, self.max_steps + 5])
        if rule == "const":
            return self.int_constant(rng.choice([1, 2, 3, 4, self.max_steps]))
        if rule == "out-of-range":
            return self.int_constant(rng.choice([1000, 2147483647, -2147483648]))
        if rule == "state":
            x = self.first_lane(self.read(rng.choice(readable),
                                          rng.choice([0, 0, 1, -1])))
            magnitude = self.fresh()
            self.emit(f"{magnitude} = math.absf {x} : {self.scalar}")
            threshold = self.fresh()
            self.emit(f"{threshold} = arith.constant 5.0e-1 : {self.scalar}")
            condition = self.fresh()
            self.emit(f"{condition} = arith.cmpf ogt, {magnitude}, {threshold} "
                      f": {self.scalar}")
        else:
            item = self.fresh()
            self.emit(f"{item} = arith.index_cast %i : index to i32")
            if rule == "item":
                divisor = self.int_constant(rng.choice([3, 5, 9]))
                rest = self.fresh()
                self.emit(f"{rest} = arith.remui {item}, {divisor} : i32")
                steps = self.fresh()
                self.emit(f"{steps} = arith.addi {rest}, {self.int_constant(1)} "
                          ": i32")
                return steps
            if rule == "region":
                edge = self.int_constant(rng.randrange(max(1, self.range)))
                condition = self.fresh()
                self.emit(f"{condition} = arith.cmpi ult, {item}, {edge} : i32")
            else:  # band: items t mod range .. + width
                time = self.fresh()
                self.emit(f"{time} = arith.trunci %t : i64 to i32")
                start = self.fresh()
                self.emit(f"{start} = arith.remui {time}, "
                          f"{self.int_constant(max(1, self.range))} : i32")
                distance = self.fresh()
                self.emit(f"{distance} = arith.subi {item}, {start} : i32")
                width = self.int_constant(rng.choice([1, 5, 20, 40]))
                condition = self.fresh()
                self.emit(f"{condition} = arith.cmpi ult, {distance}, {width} "
                          ": i32")
        steps = self.fresh()
        self.emit(f"{steps} = arith.select {condition}, "
                  f"{self.int_constant(low)}, {self.int_constant(high)} : i32")
        return steps

    def component(self, out, name, writes, readable, evaluate, with_num_steps):
        """A component: `evaluate()` emits the body and returns the yielded
        values."""
        header = f"  sim.component {name} writes({', '.join(writes)})"
        if with_num_steps:
            out.append(header + " num_steps {")
            out.append("  ^bb0(%i: index, %t: i64):")
            self.lines = []
            steps = self.num_steps(readable)
            out += self.lines
            out.append(f"    sim.yield {steps} : i32")
            out.append("  } evaluate {")
        else:
            out.append(header + " evaluate {")
        out.append(f"  ^bb0(%i: index, %t: i64, %n: i32, %dt: {self.scalar}):")
        self.lines = []
        results = evaluate()
        out += self.lines
        types = ", ".join([self.buffer_type] * len(results))
        out.append(f"    sim.yield {', '.join(results)} : {types}")
        out.append("  }")

    def step_length(self):
        """h = n dt, as the buffers' type."""
        steps = self.fresh()
        self.emit(f"{steps} = arith.sitofp %n : i32 to {self.scalar}")
        h = self.fresh()
        self.emit(f"{h} = arith.mulf {steps}, %dt : {self.scalar}")
        if self.buffer_type == self.scalar:
            return h
        splat = self.fresh()
        self.emit(f"{splat} = vector.broadcast {h} : {self.scalar} to "
                  f"{self.buffer_type}")
        return splat

    def relax(self, old, target, h, rate):
        """old + h rate (target - old): with h rate <= 1 the new value lies
        between old and target, so no scene diverges."""
        ty = self.buffer_type
        difference = self.fresh()
        self.emit(f"{difference} = arith.subf {target}, {old} : {ty}")
        scaled = self.fresh()
        self.emit(f"{scaled} = arith.mulf {h}, {self.float_constant(rate)} : {ty}")
        new = self.fresh()
        if self.rng.random() < 0.5:
            self.emit(f"{new} = math.fma {scaled}, {difference}, {old} : {ty}")
        else:
            product = self.fresh()
            self.emit(f"{product} = arith.mulf {scaled}, {difference} : {ty}")
            self.emit(f"{new} = arith.addf {old}, {product} : {ty}")
        return new


class StencilScene(SceneWriter):
    def write(self):
        rng = self.rng
        self.scalar = rng.choice(["f32", "f64"])
        self.buffer_type = self.scalar
        if rng.random() < 0.3:
            self.buffer_type = f"vector<{rng.choice([2, 3, 4])}x{self.scalar}>"
        self.range = rng.choice([1, 2, 5, 31, 32, 33, 64, 65, 100, 127, 200, 257])
        self.max_steps = rng.choice([1, 2, 3, 4, 5, 6, 8, 12, 16])
        buffers = [f"@B{b}" for b in range(rng.randint(1, 5))]
        components = rng.randint(1, min(4, len(buffers)))
        writer = list(range(components)) + [
            rng.randrange(components) for _ in buffers[components:]]
        rng.shuffle(writer)
        out = [f"sim.simulation @random range({self.range}) dt(1.0e-2 : "
               f"{self.scalar}) max_steps({self.max_steps}) {{"]
        for name in buffers:
            interp = rng.choice(["", "", " interp(#sim.linear)",
                                 " interp(#sim.cubic)", " interp(none)"])
            boundary = rng.choice(["", " boundary(clamp)", " boundary(zero)",
                                   " boundary(wrap)"])
            self.buffer(out, name, interp + boundary)
        order = list(range(components))
        rng.shuffle(order)
        # A component reads what it or an earlier one writes; the first one
        # reads everything (through the back edge), and now and then another
        # one does too (the compiler must reject the cycle).
        readable = {}
        for position, c in enumerate(order):
            if position == 0 or rng.random() < 0.05:
                readable[c] = buffers
            else:
                readable[c] = [b for b, w in zip(buffers, writer)
                               if w in order[:position + 1]]
        for c in range(components):
            writes = [b for b, w in zip(buffers, writer) if w == c]

            def evaluate(c=c, writes=writes):
                reads = []
                for _ in range(rng.randint(1, 5)):
                    if rng.random() < 0.15:
                        where = "gather"
                    else:
                        width = rng.choice([1, 1, 2, 3, 5, 40])
                        where = rng.randint(-width, width)
                    reads.append(self.read(rng.choice(readable[c]), where))
                total = reads[0]
                for value in reads[1:]:
                    name = self.fresh()
                    self.emit(f"{name} = arith.addf {total}, {value} : "
                              f"{self.buffer_type}")
                    total = name
                mean = self.fresh()
                self.emit(f"{mean} = arith.mulf {total}, "
                          f"{self.float_constant(1.0 / len(reads))} : "
                          f"{self.buffer_type}")
                h = self.step_length()
                return [self.relax(self.read(b, 0), mean, h,
                                   rng.uniform(0.1, 0.95) / (self.max_steps * 1e-2))
                        for b in writes]

            self.component(out, f"@C{c}", writes, readable[c], evaluate,
                           rng.random() < 0.8)
        out.append(f"  sim.schedule [{', '.join(f'@C{c}' for c in order)}]")
        observed = [b for b in buffers if rng.random() < 0.8] or buffers[:1]
        out.append(f"  sim.observe [{', '.join(observed)}]")
        out.append("}")
        return "\n".join(out) + "\n"


class PairScene(SceneWriter):
    def write(self):
        rng = self.rng
        self.scalar = self.buffer_type = rng.choice(["f32", "f64"])
        self.range = rng.choice([1, 3, 31, 32, 33, 64, 97, 128, 200, 257])
        self.max_steps = rng.choice([1, 2, 4, 5, 8, 16])
        flux = rng.random() < 0.6
        writer_boundary = rng.choice([" boundary(zero)", " boundary(wrap)",
                                      " boundary(clamp)", ""])
        fluxes = [f"@F{k}" for k in range(rng.randint(1, 2))]
        cells = [f"@U{k}" for k in range(rng.randint(1, 2))]
        follower = rng.random() < 0.5
        out = [f"sim.simulation @random range({self.range}) dt(1.0e-2 : "
               f"{self.scalar}) max_steps({self.max_steps}) {{"]
        for name in fluxes:
            if flux:
                attrs = " interp(#sim.flux)" + writer_boundary
            else:
                attrs = rng.choice(["", " interp(none)", " interp(#sim.cubic)"])
                attrs += (writer_boundary if rng.random() < 0.5
                          else rng.choice([" boundary(zero)", ""]))
            self.buffer(out, name, attrs)
        for name in cells:
            self.buffer(out, name,
                        rng.choice(["", " interp(#sim.linear)", " interp(#sim.cubic)"])
                        + rng.choice(["", " boundary(zero)", " boundary(wrap)"]))
        if follower:
            self.buffer(out, "@Dv", "")
        writer_window = rng.choice([(0, 1), (-1, 1), (0, 0), (-2, 2), (-1, 2)])
        reader_window = (rng.choice([(-1, 0), (-1, 1), (0, 0), (-2, 1)])
                         if flux or rng.random() < 0.3 else (0, 0))
        own_neighbours = rng.random() < 0.5

        def writer():
            values = []
            for b in cells:
                offsets = {writer_window[0], writer_window[1]}
                if rng.random() < 0.5:
                    offsets.add(0)
                values += [self.read(b, o) for o in sorted(offsets)]
            results = []
            for _ in fluxes:
                difference = self.fresh()
                self.emit(f"{difference} = arith.subf {rng.choice(values)}, "
                          f"{rng.choice(values)} : {self.scalar}")
                value = self.fresh()
                self.emit(f"{value} = arith.mulf {difference}, "
                          f"{self.float_constant(rng.uniform(0.03, 0.1))} : "
                          f"{self.scalar}")
                results.append(value)
            return results

        def reader():
            h = self.step_length()
            terms = [self.read(b, o) for b in fluxes
                     for o in sorted({reader_window[0], reader_window[1]})]
            total = terms[0]
            for term in terms[1:]:
                name = self.fresh()
                self.emit(f"{name} = arith.{rng.choice(['addf', 'subf'])} "
                          f"{total}, {term} : {self.scalar}")
                total = name
            results = []
            for b in cells:
                old = self.read(b, 0)
                change = total
                if own_neighbours:
                    neighbour = self.read(rng.choice(cells),
                                          rng.choice([-1, 1, 2, -3]))
                    difference = self.fresh()
                    self.emit(f"{difference} = arith.subf {neighbour}, {old} : "
                              f"{self.scalar}")
                    scaled = self.fresh()
                    self.emit(f"{scaled} = arith.mulf {difference}, "
                              f"{self.float_constant(0.1)} : {self.scalar}")
                    change = self.fresh()
                    self.emit(f"{change} = arith.addf {total}, {scaled} : "
                              f"{self.scalar}")
                rate = self.fresh()
                self.emit(f"{rate} = arith.mulf {h}, "
                          f"{self.float_constant(rng.uniform(0.1, 0.3) / (self.max_steps * 1e-2))}"
                          f" : {self.scalar}")
                product = self.fresh()
                self.emit(f"{product} = arith.mulf {rate}, {change} : {self.scalar}")
                new = self.fresh()
                self.emit(f"{new} = arith.addf {old}, {product} : {self.scalar}")
                results.append(new)
            return results

        def follow():
            value = self.read(cells[0], rng.choice([0, 1, -2, "gather"]))
            old = self.read("@Dv", 0)
            new = self.fresh()
            self.emit(f"{new} = arith.addf {old}, {value} : {self.scalar}")
            return [new]

        self.component(out, "@E", fluxes, cells, writer, True)
        self.component(out, "@C", cells, cells, reader, rng.random() < 0.6)
        schedule = ["@E", "@C"]
        if follower:
            self.component(out, "@D", ["@Dv"], cells, follow, rng.random() < 0.5)
            schedule.append("@D")
        if rng.random() < 0.5:
            out.append("  sim.total @Sum : f64 {")
            out.append("  ^bb0(%i: index):")
            out.append(f"    %x = sim.read {cells[0]}[%i] : {self.scalar}")
            if self.scalar == "f32":
                out.append("    %y = arith.extf %x : f32 to f64")
                out.append("    sim.yield %y : f64")
            else:
                out.append("    sim.yield %x : f64")
            out.append("  }")
        out.append(f"  sim.schedule [{', '.join(schedule)}]")
        observed = cells + (["@Dv"] if follower else []) + (
            fluxes[:1] if rng.random() < 0.3 else [])
        out.append(f"  sim.observe [{', '.join(observed)}]")
        out.append("}")
        return "\n".join(out) + "\n"


SHAPES = {"stencil": StencilScene, "pair": PairScene}


def scene_text(seed, shape):
    if shape == "any":
        shape = "pair" if seed % 3 == 0 else "stencil"
    return SHAPES[shape](seed).write()


def run(command, log):
    """Runs `command` with its output in `log`; returns the exit status
    (124 when it ran past two minutes)."""
    with open(log, "w") as out:
        try:
            return subprocess.run(command, stdout=out, stderr=subprocess.STDOUT,
                                  timeout=120).returncode
        except subprocess.TimeoutExpired:
            return 124


def first_line(log, words):
    with open(log, errors="replace") as text:
        for line in text:
            if any(word in line for word in words):
                return line.strip()
    return ""


def check(args, seed, folder):
    """Returns (verdict, detail) for one seed: passed, rejected, diverged or
    failed."""
    scene = os.path.join(folder, f"scene-{seed}.mlir")
    with open(scene, "w") as out:
        out.write(scene_text(seed, args.shape))
    log = os.path.join(folder, f"scene-{seed}.log")
    bundles = {}
    for name, extra in [("plain", []), ("lanes", ["--sim-cpu-levels-per-lane"])]:
        bundle = os.path.join(folder, f"scene-{seed}.{name}.simb")
        command = [args.sim_translate, scene, "--sim-to-bundle",
                   "--sim-cpu-isas=host", "-o", bundle] + extra
        status = run(command, log)
        if status == 1 and first_line(log, ["error:"]):
            return "rejected", first_line(log, ["error:"])
        if status != 0:
            return "failed", f"{' '.join(command)} exited with {status}"
        bundles[name] = bundle
    steps = str(20 + seed * 7919 % 97)
    runs = [(s, "plain", []) for s in args.strategies]
    runs += [(s, "plain", ["--group-size", "7"]) for s in args.strategies]
    runs += [(s, "plain", ["--threads", "2"]) for s in args.strategies]
    runs += [(s, "plain", ["--output-every", "7"])
             for s in ("hip", "lts") if s in args.strategies]
    if "lts" in args.strategies:
        runs += [("lts", "lanes", ["--group-size", g]) for g in ("1", "64")]
    for strategy, bundle, extra in runs:
        command = [args.sim_run, bundles[bundle], "--backend", "cpu",
                   "--strategy", strategy, "--steps", steps, "--check",
                   "--check-tolerance", "0"] + extra
        status = run(command, log)
        if status == 0:
            continue
        if first_line(log, ["non-finite values on the backend and"]):
            return "diverged", strategy
        why = first_line(log, ["check: FAIL", "error", "differ"])
        return "failed", f"{' '.join(command)} exited with {status}: {why}"
    return "passed", ""


def seeds(specs):
    for spec in specs:
        if "-" in spec:
            first, last = spec.split("-", 1)
            yield from range(int(first), int(last) + 1)
        else:
            yield int(spec)


def main():
    parser = argparse.ArgumentParser(
        description="Run random scenes under every strategy on the CPU "
        "backend and check them against the reference executor bit for bit "
        "(docs/Testing.md, \"Random scenes\").")
    parser.add_argument("--seeds", nargs="+", default=["1-20"],
                        help="seeds or ranges A-B (default 1-20)")
    parser.add_argument("--shape", choices=["stencil", "pair", "any"],
                        default="any", help="which scenes (default any: "
                        "every third seed a pair)")
    parser.add_argument("--strategies", nargs="+",
                        default=["simple", "traditional", "hip", "hip-cache",
                                 "lts"])
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="scenes checked at once (default: the CPUs)")
    parser.add_argument("--keep", metavar="DIR",
                        help="keep scenes, bundles and logs in DIR")
    parser.add_argument("--sim-translate", default=None,
                        help="the compiler (default: next to this script's "
                        "build/bin, then PATH)")
    parser.add_argument("--sim-run", default=None)
    parser.add_argument("--print", type=int, metavar="SEED",
                        help="write SEED's scene to stdout and stop")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="one line per seed, rejections with their error")
    args = parser.parse_args()
    if args.print is not None:
        sys.stdout.write(scene_text(args.print, args.shape))
        return 0
    build = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                         "build", "bin")
    for tool in ("sim_translate", "sim_run"):
        if getattr(args, tool) is None:
            name = tool.replace("_", "-")
            local = os.path.join(build, name)
            setattr(args, tool, local if os.access(local, os.X_OK)
                    else shutil.which(name))
            if getattr(args, tool) is None:
                parser.error(f"{name} not found: build sim or pass --{name}")
    folder = args.keep or tempfile.mkdtemp(prefix="random-scenes-")
    os.makedirs(folder, exist_ok=True)
    counts = {"passed": 0, "rejected": 0, "diverged": 0, "failed": 0}
    try:
        with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
            jobs = {pool.submit(check, args, seed, folder): seed
                    for seed in seeds(args.seeds)}
            for job in concurrent.futures.as_completed(jobs):
                seed = jobs[job]
                verdict, detail = job.result()
                counts[verdict] += 1
                if verdict == "failed":
                    where = (os.path.join(folder, f"scene-{seed}.mlir")
                             if args.keep else
                             f"the scene: --print {seed} --shape {args.shape}; "
                             "--keep DIR keeps its bundles")
                    print(f"FAILED seed {seed} ({where}): {detail}", flush=True)
                elif args.verbose:
                    print(f"{verdict} seed {seed} {detail}".rstrip(), flush=True)
    finally:
        if not args.keep:
            shutil.rmtree(folder, ignore_errors=True)
    print(", ".join(f"{counts[k]} {k}" for k in counts))
    return 1 if counts["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
