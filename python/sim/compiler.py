"""Running the sim tools on traced scenes, and their diagnostics.

`compile(scene)` writes the scene's text to a temporary file and runs
`sim-translate --sim-to-bundle` on it; `run_sim_opt(text, args)` runs
`sim-opt`. The tools are found, in this order, through $SIM_TRANSLATE /
$SIM_OPT, next to the runtime library ($SIM_RUNTIME_LIB's `../bin`), in
this checkout's `build/bin`, and on PATH.

Every operation of a traced scene carries the Python line that made it
(`loc("scene.py":12:9)`), so a tool's diagnostic names that line; the first
error becomes a `CompileError` with its message, location and notes.
"""

from __future__ import annotations

import numbers
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from typing import Iterable, Sequence

from .errors import CompileError
from .ops import _is_bool
from .scene import Scene

try:
    from simlists import STRATEGIES
except ImportError:  # the sim package without python/ on sys.path
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(
        __file__))))
    from simlists import STRATEGIES

__all__ = ["find_tool", "run_sim_opt", "compile", "Diagnostic",
           "parse_diagnostics"]

_REPO = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))


def find_tool(name: str) -> str:
    """The path of a sim tool (`sim-translate`, `sim-opt`, `sim-run`)."""
    if not isinstance(name, str):
        raise TypeError(f"find_tool takes a tool's name (str), not {name!r}")
    variable = name.upper().replace("-", "_")
    env = os.environ.get(variable)
    if env:
        # A tool asked for by name is that tool: a wrong path is an error,
        # not a reason to run another build's.
        if os.path.isfile(env) and os.access(env, os.X_OK):
            return os.path.normpath(env)
        raise FileNotFoundError(f"${variable} is {env!r}, which is not an "
                                f"executable file")
    candidates = []
    lib = os.environ.get("SIM_RUNTIME_LIB")
    if lib:
        candidates.append(os.path.join(os.path.dirname(os.path.abspath(lib)),
                                       "..", "bin", name))
    candidates.append(os.path.join(_REPO, "build", "bin", name))
    on_path = shutil.which(name)
    if on_path:
        candidates.append(on_path)
    for candidate in candidates:
        if candidate and os.path.isfile(candidate) and \
                os.access(candidate, os.X_OK):
            return os.path.normpath(candidate)
    raise FileNotFoundError(
        f"cannot find {name} (set ${name.upper().replace('-', '_')}, build "
        f"it into {os.path.join(_REPO, 'build', 'bin')}, or put it on PATH)")


class Diagnostic:
    """One diagnostic of a tool: severity, message and location."""

    def __init__(self, severity, message, filename=None, line=None,
                 column=None):
        self.severity = severity
        self.message = message
        self.filename = filename
        self.line = line
        self.column = column
        self.notes: list["Diagnostic"] = []

    def __str__(self):
        where = (f"{self.filename}:{self.line}:{self.column}: "
                 if self.filename else "")
        return f"{where}{self.severity}: {self.message}"

    def __repr__(self):
        return f"<Diagnostic {self}>"


_DIAGNOSTIC = re.compile(
    r"^(?:(?P<file>.+?):(?P<line>\d+):(?P<col>\d+): )?"
    r"(?P<severity>error|warning|note|remark): (?P<message>.*)$")


def parse_diagnostics(text: str) -> list[Diagnostic]:
    """The diagnostics in a tool's stderr; notes attach to the diagnostic
    before them."""
    found: list[Diagnostic] = []
    for line in text.splitlines():
        m = _DIAGNOSTIC.match(line)
        if not m:
            continue
        d = Diagnostic(m["severity"], m["message"], m["file"],
                       int(m["line"]) if m["line"] else None,
                       int(m["col"]) if m["col"] else None)
        if d.severity == "note" and found:
            found[-1].notes.append(d)
        else:
            found.append(d)
    return found


def _raise_for(tool: str, command: Sequence[str], stderr: str, status: int):
    diagnostics = parse_diagnostics(stderr)
    errors = [d for d in diagnostics if d.severity == "error"]
    if errors:
        first = errors[0]
        notes = [str(n) for n in first.notes]
        notes += [str(d) for d in errors[1:]]
        raise CompileError(first.message, first.filename, first.line,
                           first.column, notes, diagnostics=stderr,
                           tool=" ".join(command))
    raise CompileError(f"{tool} failed (exit status {status}): "
                       + (stderr.strip() or "no message"),
                       diagnostics=stderr, tool=" ".join(command))


def _scene_text(scene, what: str) -> tuple[str, str]:
    if isinstance(scene, str):
        match = re.search(r"sim\.simulation @([A-Za-z_][\w$.]*)", scene)
        return scene, match.group(1) if match else "scene"
    if isinstance(scene, Scene):
        return scene.mlir(), scene.name
    # A path would be taken for text if it were a str; say what to pass.
    hint = (" (for a file, pass its text: open(path).read())"
            if isinstance(scene, os.PathLike) else "")
    raise TypeError(f"{what} takes a sim.Scene or a scene's MLIR text "
                    f"(str), not {type(scene).__name__}{hint}")


def _strategy_names(strategies) -> list[str]:
    """The strategies asked for, checked against the runtime's (simlists)
    before sim-translate runs: its own message for an unknown one names a
    command-line option, not the strategies there are."""
    known = ", ".join(STRATEGIES)
    if isinstance(strategies, str):
        strategies = [strategies]
    try:
        names = list(strategies)
    except TypeError:
        raise TypeError(f"strategies is a strategy's name or a list of "
                        f"them ({known}), not {strategies!r}") from None
    for name in names:
        if not isinstance(name, str):
            raise TypeError(f"a strategy is a name (str: {known}), not "
                            f"{name!r}")
        if name not in STRATEGIES:
            raise ValueError(f"unknown strategy {name!r}: the strategies "
                             f"are {known}")
        if names.count(name) > 1:
            raise ValueError(f"strategy {name!r} is asked for twice")
    return names


# The group sizes a bundle's plans can be made for (lib/Target/Bundle/
# Bundle.cpp: a multiple of a GPU warp, at most kMaxGroupSize).
_MAX_GROUP_SIZE = 1 << 16


def _check_group_size(group_size):
    """Refuses a group size sim-translate would not take, before it runs:
    int() would truncate 1.7, and the tool's message points into the
    temporary scene file."""
    if group_size is None:
        return
    if isinstance(group_size, bool) or \
            not isinstance(group_size, numbers.Integral):
        raise TypeError(f"group_size must be an int (a multiple of 32), not "
                        f"{group_size!r}")
    if group_size % 32 or not 32 <= group_size <= _MAX_GROUP_SIZE:
        raise ValueError(f"group_size must be a multiple of 32 (a GPU warp) "
                         f"from 32 to {_MAX_GROUP_SIZE}, not {group_size}")


def run_sim_opt(scene, args: Iterable[str] = ()) -> str:
    """Runs `sim-opt` on a scene (a Scene or its text) with `args`; returns
    stdout (and stderr appended when the tool prints remarks there).
    Raises CompileError on failure."""
    if isinstance(args, str):
        raise TypeError(f"args is a list of sim-opt options, not the str "
                        f"{args!r}")
    text, name = _scene_text(scene, "sim.run_sim_opt")
    tool = find_tool("sim-opt")
    with tempfile.TemporaryDirectory(prefix="sim-") as tmp:
        path = os.path.join(tmp, f"{name}.mlir")
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        command = [tool, path, *args]
        done = subprocess.run(command, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        _raise_for("sim-opt", command, done.stderr, done.returncode)
    return done.stdout


def compile(scene, strategies: Sequence[str] | str | None = None,
            group_size: int | None = None, output: str | None = None,
            args: Sequence[str] = (), verbose: bool = False,
            ftz: bool = False):
    """Compiles a scene (a Scene, or scene text) into a bundle.

    `strategies`: the strategies to compile (default, None: all five:
    simple, traditional, hip, hip-cache, lts); a name or a list (an unknown
    or repeated name, or an empty list, is a ValueError before the tool
    runs). `group_size`: the
    group size the plans are made for, a multiple of 32 from 32 to 65536
    (default 256; anything else is refused before the tool runs). `output`:
    where the bundle goes (default: a temporary file that lives as long as
    the Bundle, with CPU kernels for this machine's instruction-set level
    only, `--sim-cpu-isas=host`, since it runs nowhere else; a bundle
    written to `output` has every default level). `args`: more
    sim-translate options (a list; `--sim-cpu-isas=...` there decides the
    levels). `ftz`: flush
    subnormals to zero on every backend (`--sim-ftz`; much faster on a CPU
    once values decay below the normal range; default IEEE): True or False
    (a numpy bool too), anything else is a TypeError.
    Returns a `sim.Bundle` with `compile_seconds`, the scene's `mlir` text
    and the tool's warnings and remarks (`messages`); raises CompileError
    at the Python line of an error.
    """
    from .runtime import Bundle
    names = _strategy_names(strategies) if strategies is not None else []
    if strategies is not None and not names:
        raise ValueError(f"strategies is empty: name at least one of "
                         f"{', '.join(STRATEGIES)}, or leave it out (None) "
                         f"for all of them")
    _check_group_size(group_size)
    # Any non-empty str is true: "no" would flush.
    if not _is_bool(ftz):
        raise TypeError(f"ftz must be True or False, not {ftz!r}")
    if isinstance(args, str):
        raise TypeError(f"args is a list of sim-translate options, not the "
                        f"str {args!r}")
    text, name = _scene_text(scene, "sim.compile")
    tool = find_tool("sim-translate")
    tmp = tempfile.TemporaryDirectory(prefix="sim-")
    try:
        source = os.path.join(tmp.name, f"{name}.mlir")
        with open(source, "w", encoding="utf-8") as f:
            f.write(text)
        target = output or os.path.join(tmp.name, f"{name}.simb")
        command = [tool, source, "--sim-to-bundle", "-o", target]
        if names:
            command.append("--sim-strategies=" + ",".join(names))
        if group_size is not None:
            command.append(f"--sim-group-size={int(group_size)}")
        if ftz:
            command.append("--sim-ftz")
        if not output and not any(str(arg).startswith("--sim-cpu-isas")
                                  for arg in args):
            command.append("--sim-cpu-isas=host")
        command += list(args)
        start = time.perf_counter()
        done = subprocess.run(command, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)
        seconds = time.perf_counter() - start
        if done.returncode != 0:
            _raise_for("sim-translate", command, done.stderr, done.returncode)
        if verbose and done.stderr.strip():
            print(done.stderr.rstrip())
        bundle = Bundle(target)
    except BaseException:
        tmp.cleanup()
        raise
    bundle.compile_seconds = seconds
    bundle.mlir = text
    bundle.messages = parse_diagnostics(done.stderr)
    bundle.command = command
    if output is None:
        bundle._tmp = tmp  # removed when the bundle is closed
    else:
        tmp.cleanup()
    return bundle
