"""The exceptions of the sim package, each with the user's source location.

`TraceError`: the tracer met something it cannot express (a Python `if` on
a traced value, a data-dependent loop bound, mixed types, a value carried
out of its body by a Python side effect, an unsupported type). `CompileError`:
a sim tool (sim-opt, sim-translate) reported an error; its location is the
Python line the tracer recorded on the operation (`loc("file.py":12:9)`).
Both carry `filename`, `line` and `column` (1-based, or None) and show the
source line in their message. `RunError` (sim.runtime, with numpy): the
runtime refused a call; a SimError without a location, and a simrt.Error.

`NonFiniteWarning` (a RuntimeWarning, through the `warnings` module): a run
of a session ended with NaN or infinity in its state or totals, which
sim-run reports with warnings and exit status 3.
"""

from __future__ import annotations

import linecache

__all__ = ["SimError", "TraceError", "CompileError", "NonFiniteWarning"]


class SimError(Exception):
    """Base class: a message and the user's source location."""

    def __init__(self, message: str, filename: str | None = None,
                 line: int | None = None, column: int | None = None,
                 notes: list[str] | None = None):
        self.message = message
        self.filename = filename
        self.line = line
        self.column = column
        self.notes = list(notes or [])
        super().__init__(self._format())

    @property
    def location(self) -> str | None:
        """`file:line:col` (or None without a location)."""
        if self.filename is None:
            return None
        if self.line is None:
            return self.filename
        if self.column is None:
            return f"{self.filename}:{self.line}"
        return f"{self.filename}:{self.line}:{self.column}"

    def _format(self) -> str:
        text = self.message
        if self.location:
            text = f"{self.location}: {self.message}"
            source = (linecache.getline(self.filename, self.line).rstrip()
                      if self.line else "")
            if source.strip():
                text += "\n    " + source.strip()
        for note in self.notes:
            text += "\n  " + note
        return text


class TraceError(SimError):
    """A construct the tracer cannot turn into sim operations."""


class CompileError(SimError):
    """An error of sim-opt or sim-translate, at the Python line of the op.

    `diagnostics` holds every diagnostic line the tool printed; `tool` the
    command that failed.
    """

    def __init__(self, message, filename=None, line=None, column=None,
                 notes=None, diagnostics: str = "", tool: str = ""):
        self.diagnostics = diagnostics
        self.tool = tool
        super().__init__(message, filename, line, column, notes)


class NonFiniteWarning(RuntimeWarning):
    """A run ended with NaN or infinity in the session's state or totals.

    `buffers` maps each buffer that holds such values to how many it holds;
    `totals` names the totals that are not finite. The run itself
    completed: the session holds its state (sim-run's exit status 3).
    """

    def __init__(self, message: str, buffers: dict[str, int] | None = None,
                 totals: list[str] | None = None):
        super().__init__(message)
        self.buffers = dict(buffers or {})
        self.totals = list(totals or [])
