#!/usr/bin/env python3
"""Mutate scenes token by token and check that the compiler and the runtime
end every one in a result or a clean error (docs/Testing.md, "Mutated
scenes").

Each seed takes one scene of the corpus (the examples and the integration
scenes by default), replaces one to three of its tokens with another token
of the same kind from the same scene (a buffer or value name, a type, a
boundary rule, an op name) or an extreme number, sometimes drops a line,
and compiles it with `sim-translate --sim-to-bundle` for one strategy. A
scene that compiles then runs a few base steps on the CPU backend with
`sim-run --check --check-tolerance 0` against the reference executor.

A seed fails when a tool dies of a signal, prints an LLVM crash banner
("PLEASE submit a bug report", "LLVM ERROR", an assertion), runs past the
time limit, or when a run that both executors finish with finite values
disagrees with the reference executor. Diagnostics and refused scenes are
the expected outcome of most seeds. Failing scenes and their logs are kept
in --keep (default: a folder under /tmp), named by seed, so that
`--print SEED` or the kept file reproduces them.

Tokens are mutated where a user could make the mistake; the numbers of a
vector shape and of a result number (`%x#3`) are left alone: MLIR's parser
allocates as many as they say, so `vector<9223372036854775807xf32>` ends in
LLVM's out-of-memory error, a limit of the upstream parser rather than of
this project.
"""

import argparse
import concurrent.futures
import glob
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

TOKEN = re.compile(
    r"@[A-Za-z_][A-Za-z0-9_]*"                # symbols
    r"|%[A-Za-z0-9_]+(?:#\d+)?"               # values (with a result number)
    r"|-?\d+\.\d+(?:e[-+]?\d+)?"              # floats
    r"|(?<![x<#\w])-?\d+(?![x\w])"            # integers, not vector shapes
    r"|\b(?:f32|f64|i1|i8|i32|i64|index)\b"   # types
    r"|#sim\.[a-z_]+"                         # interpolations
    r"|\b(?:wrap|clamp|zero|none)\b"          # boundary rules
    r"|\b[a-z_]+\.[a-z_.]+\b")                # op names
EXTREME_INTS = ["0", "1", "-1", "2", "3", "7", "31", "32", "33", "64",
                "4097", "2147483647", "-2147483648", "9223372036854775807"]
EXTREME_FLOATS = ["0.0", "-0.0", "1.0e308", "1.0e-320", "-1.0", "3.0e38",
                  "0.5"]
CRASH_MARKS = ("PLEASE submit a bug report", "Stack dump", "LLVM ERROR",
               "Assertion", "UNREACHABLE", "AddressSanitizer",
               "UndefinedBehaviorSanitizer",
               "terminate called", "Segmentation fault")
STRATEGIES = ["simple", "traditional", "hip", "hip-cache", "lts"]


def default_corpus():
    files = sorted(glob.glob(os.path.join(ROOT, "examples", "*", "*.mlir")))
    files += sorted(glob.glob(os.path.join(ROOT, "test", "Integration",
                                           "Inputs", "*.mlir")))
    return files


def strip_test_lines(text):
    return "\n".join(line for line in text.split("\n")
                     if not line.lstrip().startswith("// RUN")
                     and "CHECK" not in line)


TYPES = {"f32", "f64", "i1", "i8", "i32", "i64", "index"}
BOUNDARIES = {"wrap", "clamp", "zero", "none"}


def kind_of(token):
    if token[0] in "@%":
        return token[0]
    if token.startswith("#sim."):
        return "interp"
    if token in TYPES:
        return "type"
    if token in BOUNDARIES:
        return "boundary"
    return "op"


def token_text(token):
    return token.split("#")[0] if token[0] == "%" else token


def mutate(text, rng):
    """One to three token replacements and sometimes a dropped line."""
    for _ in range(rng.choice([1, 1, 2, 3])):
        tokens = list(TOKEN.finditer(text))
        if not tokens:
            break
        match = rng.choice(tokens)
        old = match.group(0)
        if re.fullmatch(r"-?\d+", old):
            new = rng.choice(EXTREME_INTS)
        elif re.fullmatch(r"-?\d+\.\d+(?:e[-+]?\d+)?", old):
            new = rng.choice(EXTREME_FLOATS)
        else:
            # Another token of the same kind from the same scene (a value
            # without its result number, if any).
            same = sorted({token_text(t.group(0)) for t in tokens
                           if kind_of(t.group(0)) == kind_of(old)} - {old})
            if not same:
                continue
            new = rng.choice(same)
        text = text[:match.start()] + new + text[match.end():]
    if rng.random() < 0.15:
        lines = text.split("\n")
        del lines[rng.randrange(len(lines))]
        text = "\n".join(lines)
    return text


def scene_for(seed, corpus):
    rng = random.Random(seed)
    source = corpus[rng.randrange(len(corpus))]
    with open(source) as f:
        text = mutate(strip_test_lines(f.read()), rng)
    return source, rng.choice(STRATEGIES), text


def run(command, timeout):
    try:
        done = subprocess.run(command, capture_output=True, text=True,
                              errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, ""
    return done.returncode, done.stdout + done.stderr


def crashed(code, output):
    if code is None:
        return "ran past the time limit"
    if code < 0:
        return f"killed by signal {-code}"
    for mark in CRASH_MARKS:
        if mark in output:
            return f"printed '{mark}'"
    return None


def check_seed(seed, args, corpus, folder):
    source, strategy, text = scene_for(seed, corpus)
    scene = os.path.join(folder, f"work-{seed}.mlir")
    bundle = os.path.join(folder, f"work-{seed}.simb")
    with open(scene, "w") as f:
        f.write(text)
    outcome, log = "refused", ""
    code, output = run([args.sim_translate, scene, "--sim-to-bundle",
                        f"--sim-strategies={strategy}", "--sim-cpu-isas=host",
                        "-o", bundle], args.timeout)
    why = crashed(code, output)
    log = output
    if not why and code == 0:
        outcome = "ran"
        code, output = run([args.sim_run, bundle, "--backend", "cpu",
                            "--strategy", strategy, "--steps",
                            str(args.steps), "--threads", "1", "--check",
                            "--check-tolerance", "0"], args.timeout)
        log += output
        why = crashed(code, output)
        if not why and "check: FAIL" in output and \
                "non-finite" not in output and "not finite" not in output:
            why = "disagrees with the reference executor"
    for path in (scene, bundle):
        if os.path.exists(path):
            os.remove(path)
    if why:
        name = os.path.join(args.keep, f"seed-{seed}")
        with open(name + ".mlir", "w") as f:
            f.write(text)
        with open(name + ".log", "w") as f:
            f.write(f"seed {seed}: {os.path.relpath(source, ROOT)}, "
                    f"strategy {strategy}: {why}\n\n{log}")
        return seed, "failed", f"{why} ({os.path.relpath(source, ROOT)}, " \
                               f"{strategy}; {name}.log)"
    return seed, outcome, ""


def parse_seeds(items):
    seeds = []
    for item in items:
        if "-" in item[1:]:
            low, high = item.split("-", 1)
            seeds.extend(range(int(low), int(high) + 1))
        else:
            seeds.append(int(item))
    return seeds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     epilog=__doc__.split("\n\n", 1)[1],
                                     formatter_class=argparse.
                                     RawDescriptionHelpFormatter)
    parser.add_argument("--seeds", nargs="+", default=["1-200"],
                        help="seeds or ranges A-B (default 1-200)")
    parser.add_argument("--corpus", nargs="+", metavar="SCENE",
                        help="scenes to mutate (default: examples/ and "
                        "test/Integration/Inputs/)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="seeds checked at once (default: the CPUs)")
    parser.add_argument("--steps", type=int, default=40,
                        help="base steps a compiled scene runs (default 40)")
    parser.add_argument("--timeout", type=float, default=120,
                        help="seconds a tool may take per seed (default 120)")
    parser.add_argument("--budget", type=float, default=0,
                        help="stop starting seeds after this many seconds "
                        "(default 0: no limit)")
    parser.add_argument("--keep", help="folder for failing scenes and logs "
                        "(default: a new folder under /tmp)")
    parser.add_argument("--print", type=int, metavar="SEED",
                        help="write SEED's mutated scene to stdout and stop")
    parser.add_argument("--sim-translate", default=os.path.join(
        ROOT, "build", "bin", "sim-translate"))
    parser.add_argument("--sim-run", default=os.path.join(
        ROOT, "build", "bin", "sim-run"))
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="one line per seed")
    args = parser.parse_args()

    corpus = args.corpus or default_corpus()
    if not corpus:
        parser.error("no scenes to mutate")
    if args.print is not None:
        source, strategy, text = scene_for(args.print, corpus)
        print(f"// seed {args.print}: {os.path.relpath(source, ROOT)}, "
              f"strategy {strategy}")
        print(text)
        return 0
    for name in ("sim_translate", "sim_run"):
        tool = getattr(args, name)
        found = tool if os.sep in tool else shutil.which(tool)
        if not found or not os.access(found, os.X_OK):
            parser.error(f"{tool} is not an executable (build first, or "
                         "pass --sim-translate/--sim-run)")
        setattr(args, name, found)
    args.keep = args.keep or tempfile.mkdtemp(prefix="sim-mutated-")
    os.makedirs(args.keep, exist_ok=True)
    seeds = parse_seeds(args.seeds)
    counts = {"ran": 0, "refused": 0, "failed": 0}
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="sim-mutate-") as folder, \
            concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        pending = set()
        queue = iter(seeds)
        done_count = 0
        while True:
            while len(pending) < args.jobs:
                if args.budget and time.monotonic() - start > args.budget:
                    break
                seed = next(queue, None)
                if seed is None:
                    break
                pending.add(pool.submit(check_seed, seed, args, corpus,
                                        folder))
            if not pending:
                break
            finished, pending = concurrent.futures.wait(
                pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for future in finished:
                seed, outcome, detail = future.result()
                counts[outcome] += 1
                done_count += 1
                if outcome == "failed":
                    print(f"seed {seed}: FAILED: {detail}", flush=True)
                elif args.verbose:
                    print(f"seed {seed}: {outcome}", flush=True)
            if sys.stderr.isatty():
                print(f"\r{done_count}/{len(seeds)} seeds", end="",
                      file=sys.stderr, flush=True)
    if sys.stderr.isatty():
        print(file=sys.stderr)
    print(f"{counts['ran']} ran, {counts['refused']} refused, "
          f"{counts['failed']} failed")
    if counts["failed"]:
        print(f"failing scenes and logs: {args.keep}")
    return 1 if counts["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
