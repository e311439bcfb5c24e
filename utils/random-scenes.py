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
           negative, INT32_MAX), or no num_steps at all; sometimes an
           oscillator whose position has a Hermite interpolation (now and
           then pulled by its neighbours too: a chain), and
           parameters (a rate, and a mode that makes every num_steps 1)
  pair     a writer and a reader that may form a flux pair or an item pair
           under lts (docs/Model.md), sometimes breaking one of its rules,
           sometimes followed by a third component and a total

Every scene is compiled with `sim-translate --sim-to-bundle`. A scene the
compiler rejects with a diagnostic counts as rejected (its first error is
printed with -v); a compiler that crashes, or a run that disagrees with the
reference executor, fails the check. Each scene runs on the CPU backend
for every strategy, also with groups of 7 items and on 2 threads, with
--output-every 7 (hip, lts), lts with the per-lane level limit
(--sim-cpu-levels-per-lane) at groups of 1 and 64, and with other values
of its parameters and dt. With --ptxas its PTX must assemble for sm_90
under every strategy without a spill. With --ranks it also runs on that many ranks
(sim-run --distributed under mpirun) and must give the one-process result
bit for bit. A run whose state grows past the floats (NaN or infinity on
both executors) counts as diverged, not failed: the scene is useless, not
wrong.

usage: utils/random-scenes.py [--seeds A-B|N ...] [--shape stencil|pair|any]
         [--jobs J] [--keep DIR] [--ranks R ...] [--ptxas PATH] [--odd-steps]
         [--sim-translate PATH]
         [--sim-run PATH] [-v]

Writes one line per failure with the seed, where to find the scene and the
command that failed, and exits with 1 when something failed. `--print
SEED` writes one seed's scene to stdout. docs/Testing.md, "Random scenes".
"""

import argparse
import concurrent.futures
import json
import os
import random
import shlex
import shutil
import subprocess
import sys
import tempfile

NUM_STEPS_RULES = ["const", "region", "band", "item", "state", "out-of-range"]


class SceneWriter:
    """What both shapes share: value names, init bodies, index expressions
    and num_steps rules."""

    # --odd-steps: the smallest num_steps a rule yields is 3, 5, 6 or 7
    # instead of 1, 2, 0 or negative, so that lts takes its sub-steps in
    # units other than 1 (docs/Model.md, "Levels"). The same draws, other
    # values: a seed's scene keeps its shape.
    odd_steps = False

    def __init__(self, seed):
        self.rng = random.Random(seed)
        # Draws added later take their own generator, so that every seed
        # keeps the scene it had before them (the tests name seeds by what
        # their scenes hold).
        self.extra = random.Random(f"constant field {seed}")
        self.clamps = random.Random(f"clamped gather {seed}")
        self.constant_field = None
        self.chain = False
        self.count = 0
        self.lines = []
        self.parameters = False

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

    def buffer(self, out, name, attrs, rng=None):
        """A buffer whose init varies smoothly with the item (and the lane)."""
        rng = rng or self.rng
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
        """%i, %i plus a constant offset, or a gather (%i * k mod range),
        now and then clamped to %i - a .. %i + b (a neighbour list given a
        reach: a window, docs/Model.md)."""
        if where == "gather":
            k = self.int_constant(self.rng.choice([3, 7, 11]), "index")
            product = self.fresh()
            self.emit(f"{product} = arith.muli %i, {k} : index")
            bound = self.int_constant(self.range, "index")
            j = self.fresh()
            self.emit(f"{j} = arith.remui {product}, {bound} : index")
            if self.clamps.random() < 0.4:
                below, above = (self.clamps.choice([0, 1, 2, 5, 40])
                                for _ in range(2))
                low, high, at_least, clamped = (self.fresh() for _ in range(4))
                self.emit(f"{low} = arith.subi %i, "
                          f"{self.int_constant(below, 'index')} : index")
                self.emit(f"{high} = arith.addi %i, "
                          f"{self.int_constant(above, 'index')} : index")
                self.emit(f"{at_least} = arith.maxsi {j}, {low} : index")
                self.emit(f"{clamped} = arith.minsi {at_least}, {high} : index")
                return clamped
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

    def splat(self, value):
        """A scalar as the buffers' type (a broadcast for vectors)."""
        if self.buffer_type == self.scalar:
            return value
        splat = self.fresh()
        self.emit(f"{splat} = vector.broadcast {value} : {self.scalar} to "
                  f"{self.buffer_type}")
        return splat

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
        low = rng.choice([3, 5, 6, 3, 7] if self.odd_steps
                         else [1, 1, 2, 0, -3])
        high = rng.choice([2, 4, 8, self.max_steps, self.max_steps + 5])
        if rule == "const":
            return self.int_constant(rng.choice(
                [3, 5, 6, 7, self.max_steps] if self.odd_steps
                else [1, 2, 3, 4, self.max_steps]))
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
            if self.parameters:
                # @mode = 1 makes every item take single base steps.
                mode = self.fresh()
                self.emit(f"{mode} = sim.get_param @mode : i32")
                uniform = self.fresh()
                self.emit(f"{uniform} = arith.cmpi ne, {mode}, "
                          f"{self.int_constant(0)} : i32")
                selected = self.fresh()
                self.emit(f"{selected} = arith.select {uniform}, "
                          f"{self.int_constant(1)}, {steps} : i32")
                steps = selected
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
        return self.splat(h)

    def relax(self, old, target, h, rate):
        """old + h rate (target - old): with h rate <= 1 the new value lies
        between old and target, so no scene diverges."""
        ty = self.buffer_type
        difference = self.fresh()
        self.emit(f"{difference} = arith.subf {target}, {old} : {ty}")
        scaled = self.fresh()
        self.emit(f"{scaled} = arith.mulf {h}, {self.float_constant(rate)} : {ty}")
        if self.parameters:
            # A rate of at most 1, so that the relaxation stays one.
            factor = self.fresh()
            self.emit(f"{factor} = sim.get_param @rate : {self.scalar}")
            factor = self.splat(factor)
            product = self.fresh()
            self.emit(f"{product} = arith.mulf {scaled}, {factor} : {ty}")
            scaled = product
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
        self.parameters = rng.random() < 0.3
        if self.parameters:
            out.append(f"  sim.param @rate = 1.0 : {self.scalar}")
            out.append("  sim.param @mode = 0 : i32")
        for name in buffers:
            interp = rng.choice(["", "", " interp(#sim.linear)",
                                 " interp(#sim.cubic)", " interp(none)"])
            boundary = rng.choice(["", " boundary(clamp)", " boundary(zero)",
                                   " boundary(wrap)"])
            self.buffer(out, name, interp + boundary)
        # Now and then a constant field (docs/Model.md) that components
        # read at their items, through windows and through gathers.
        if self.extra.random() < 0.3:
            self.constant_field = "@K"
            self.buffer(out, "@K", " constant" + self.extra.choice(
                ["", " boundary(zero)", " boundary(wrap)"]), rng=self.extra)
        # Now and then an oscillator whose position has a Hermite
        # interpolation from its velocity.
        oscillator = None
        if rng.random() < 0.25:
            oscillator = components
            components += 1
            velocity = rng.choice([" interp(none)", "", " boundary(zero)"])
            position = rng.choice(["", " boundary(wrap)"])
            # Now and then a chain (its neighbours pull it too, below), with
            # one boundary rule for both, as lts needs to read the
            # neighbours through their time levels.
            self.chain = self.extra.random() < 0.5
            if self.chain:
                velocity = velocity.replace(" boundary(zero)", "") + position
            self.buffer(out, "@Hv", velocity)
            self.buffer(out, "@Hx", " interp(#sim.hermite<@Hv>)" + position)
            buffers += ["@Hv", "@Hx"]
            writer += [oscillator, oscillator]
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
            if c != oscillator:
                # Only the oscillator reads its velocity (interp(none)).
                readable[c] = [b for b in readable[c] if b != "@Hv"] or [
                    b for b, w in zip(buffers, writer) if w == c]
        for c in range(components):
            writes = [b for b, w in zip(buffers, writer) if w == c]

            def oscillate(c=c):
                # v' = k (s - x) with s a read of another buffer and
                # h^2 k <= 1 at the largest step: symplectic Euler stays
                # bounded.
                x, v = self.read("@Hx", 0), self.read("@Hv", 0)
                others = [b for b in readable[c] if b not in ("@Hv", "@Hx")]
                target = (self.read(rng.choice(others), rng.randint(-2, 2))
                          if others else self.read("@Hx", rng.choice([-1, 1])))
                ty = self.buffer_type
                if others and self.chain:
                    # A chain: also pulled towards a neighbour's position,
                    # which lts reads through the time levels of @Hx and
                    # of its derivative @Hv.
                    neighbour = self.read("@Hx", self.extra.choice([-2, -1, 1, 3]))
                    both = self.fresh()
                    self.emit(f"{both} = arith.addf {target}, {neighbour} : {ty}")
                    target = self.fresh()
                    self.emit(f"{target} = arith.mulf {both}, "
                              f"{self.float_constant(0.5)} : {ty}")
                h = self.step_length()
                pull = self.fresh()
                self.emit(f"{pull} = arith.subf {target}, {x} : {ty}")
                stiffness = rng.uniform(0.1, 0.9) / (self.max_steps * 1e-2) ** 2
                force = self.fresh()
                self.emit(f"{force} = arith.mulf {pull}, "
                          f"{self.float_constant(stiffness)} : {ty}")
                v1 = self.fresh()
                self.emit(f"{v1} = math.fma {h}, {force}, {v} : {ty}")
                x1 = self.fresh()
                self.emit(f"{x1} = math.fma {h}, {v1}, {x} : {ty}")
                return [v1, x1]

            def evaluate(c=c, writes=writes):
                reads = []
                for _ in range(rng.randint(1, 5)):
                    if rng.random() < 0.15:
                        where = "gather"
                    else:
                        width = rng.choice([1, 1, 2, 3, 5, 40])
                        where = rng.randint(-width, width)
                    reads.append(self.read(rng.choice(readable[c]), where))
                if self.constant_field and self.extra.random() < 0.6:
                    where = self.extra.choice([0, 0, -1, 1, -3, 4, 40,
                                               "gather"])
                    reads.append(self.read(self.constant_field, where))
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

            self.component(out, f"@C{c}", writes, readable[c],
                           oscillate if c == oscillator else evaluate,
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


def run(command, log, env=None):
    """Runs `command` with its output in `log`; returns the exit status
    (124 when it ran past two minutes)."""
    with open(log, "w") as out:
        try:
            return subprocess.run(command, stdout=out, stderr=subprocess.STDOUT,
                                  timeout=120, env=env).returncode
        except subprocess.TimeoutExpired:
            return 124


# What a distributed run must reproduce besides the dumped buffers.
COMPARED = ["evaluations", "big_steps", "big_step_histogram", "cut_big_steps",
            "totals", "steps_done"]


def compare_ranks(args, seed, folder, scene, steps, log):
    """Runs the scene on one process and on each of args.ranks ranks under
    every strategy; returns what differs, or None."""
    bundle = os.path.join(folder, f"scene-{seed}.distributed.simb")
    command = [args.sim_translate, scene, "--sim-to-bundle",
               "--sim-cpu-isas=host", "--sim-distributed", "-o", bundle]
    status = run(command, log)
    if status == 1 and first_line(log, ["error:"]):
        return None  # A diagnostic: nothing to compare.
    if status != 0:
        return f"{' '.join(command)} exited with {status}"
    env = dict(os.environ)
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    for strategy in args.strategies:
        def dump(name, prefix, extra):
            out = os.path.join(folder, f"scene-{seed}.{strategy}.{name}")
            shutil.rmtree(out, ignore_errors=True)
            command = prefix + [args.sim_run, bundle, "--backend", "cpu",
                                "--strategy", strategy, "--steps", steps,
                                "--threads", "1", "--group-size", "8",
                                "--no-init-check", "--dump", out, "--json",
                                out + ".json"] + extra
            if run(command, log, env) != 0:
                return None, " ".join(command)
            with open(out + ".json") as report:
                return (dumped(out), json.load(report)), None
        one, failed = dump("one", [], [])
        if one is None:
            return f"{failed} failed"
        for ranks in args.ranks:
            many, failed = dump(f"ranks{ranks}",
                                shlex.split(args.mpirun) + ["-n", str(ranks)],
                                ["--distributed"])
            if many is None:
                return f"{failed} failed"
            what = [f"{file} bytes" for file in one[0]
                    if many[0].get(file) != one[0][file]]
            what += [key for key in COMPARED if many[1].get(key) != one[1].get(key)]
            if what:
                return f"{strategy} on {ranks} ranks differs: {', '.join(what)}"
    return None


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
    with open(scene) as text:
        parameters = "sim.param @mode" in text.read()
    if parameters:
        runs += [(s, "plain", ["--set", "rate=0.5", "--set", "mode=1"])
                 for s in ("simple", "hip", "lts") if s in args.strategies]
        runs += [(s, "plain", ["--set", "rate=0.25", "--set", "dt=0.005"])
                 for s in ("hip", "lts") if s in args.strategies]
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
    failed = compare_restart(args, seed, folder, bundles["plain"], steps, log)
    if failed:
        return "failed", failed
    if args.ptxas:
        failed = assemble(args, seed, folder, scene, log)
        if failed:
            return "failed", failed
    # A rank holds at least one group of 8 items.
    if args.ranks and 8 * max(args.ranks) <= scene_range(scene):
        differs = compare_ranks(args, seed, folder, scene, steps, log)
        if differs:
            return "failed", differs
    return "passed", ""


def dumped(folder):
    files = {}
    for file in sorted(os.listdir(folder)):
        with open(os.path.join(folder, file), "rb") as data:
            files[file] = data.read()
    return files


def compare_restart(args, seed, folder, bundle, steps, log):
    """A run stopped halfway and continued from its checkpoint must end
    where one run stopped at the same output time ends; returns what
    differs, or None."""
    half = str(max(1, int(steps) // 2))
    for strategy in ("hip", "lts"):
        if strategy not in args.strategies:
            continue
        base = os.path.join(folder, f"scene-{seed}.{strategy}")
        checkpoint = base + ".checkpoint"
        common = [args.sim_run, bundle, "--backend", "cpu", "--strategy",
                  strategy, "--no-init-check"]
        commands = [
            common + ["--steps", steps, "--output-every", half, "--dump",
                      base + ".whole"],
            common + ["--steps", half, "--checkpoint", checkpoint],
            common + ["--steps", steps, "--restart", checkpoint,
                      "--output-every", half, "--dump", base + ".restarted"],
        ]
        for stale in (".whole", ".restarted"):
            shutil.rmtree(base + stale, ignore_errors=True)
        for command in commands:
            status = run(command, log)
            if status != 0:
                return f"{' '.join(command)} exited with {status}"
        whole, restarted = dumped(base + ".whole"), dumped(base + ".restarted")
        if not whole:
            return f"{strategy}: sim-run --dump wrote nothing"
        differs = [f for f in whole if restarted.get(f) != whole[f]]
        if differs:
            return (f"{strategy}: continued from a checkpoint at base step "
                    f"{half}, {', '.join(differs)} differ")
    return None


def assemble(args, seed, folder, scene, log):
    """Lowers the scene to PTX for every strategy and assembles it with
    ptxas for sm_90; returns what failed (an error or a spill), or None."""
    ptx = os.path.join(folder, f"scene-{seed}.ptx")
    for strategy in args.strategies:
        command = [args.sim_translate, "--sim-to-ptx", scene,
                   f"--sim-strategy={strategy}", "-o", ptx]
        status = run(command, log)
        if status != 0:
            return f"{' '.join(command)} exited with {status}"
        command = [args.ptxas, "-arch=sm_90", "-v", ptx, "-o", ptx + ".cubin"]
        if run(command, log) != 0:
            return f"{' '.join(command)}: {first_line(log, ['error'])}"
        kernel = None
        with open(log) as text:
            for line in text:
                if "Function properties for" in line:
                    kernel = line.split()[-1]
                elif "bytes spill stores" in line:
                    words = line.split()
                    stores, loads = int(words[4]), int(words[8])
                    if stores or loads:
                        return (f"{strategy}: {kernel} spills {stores} bytes "
                                f"and reloads {loads}")
    return None


def scene_range(scene):
    with open(scene) as text:
        header = text.readline()
    return int(header.split("range(", 1)[1].split(")", 1)[0])


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
    parser.add_argument("--ranks", type=int, nargs="*", default=[],
                        help="also run every scene whose range gives each "
                        "rank a group of 8 items on this many ranks "
                        "(sim-run --distributed) and compare with one "
                        "process bit for bit, e.g. --ranks 2 3")
    parser.add_argument("--mpirun", default="mpirun --oversubscribe",
                        help="how to start ranks (default: mpirun "
                        "--oversubscribe)")
    parser.add_argument("--ptxas", metavar="PATH",
                        help="also lower every scene to PTX under every "
                        "strategy and assemble it with this ptxas for sm_90: "
                        "it must assemble without a spill")
    parser.add_argument("--print", type=int, metavar="SEED",
                        help="write SEED's scene to stdout and stop")
    parser.add_argument("--odd-steps", action="store_true",
                        help="num_steps rules whose smallest values are 3, "
                        "5, 6 or 7, not 1, 2 or below: lts sub-steps in "
                        "units other than 1 (another scene per seed)")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="one line per seed, rejections with their error")
    args = parser.parse_args()
    SceneWriter.odd_steps = args.odd_steps
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
