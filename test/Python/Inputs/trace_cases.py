"""What the tracer's error tests share: a list of cases, each a function
that traces a scene, and a runner that prints one line per case for
FileCheck: `name: file:line:col: message` for its TraceError, else
`name: ` and `ok` (nothing for the cases in `quiet`, which print their own
lines). Other exceptions propagate, or with `report_others` print as
`name: Type: message` (a test that no internal error leaks out)."""
import os

import sim

cases = []


def case(fn):
    cases.append(fn)
    return fn


def run(ok="no error", quiet=(), report_others=False):
    for fn in cases:
        try:
            fn()
        except sim.TraceError as error:
            print(f"{fn.__name__}: {os.path.basename(error.filename)}:"
                  f"{error.line}:{error.column}: {error.message}")
        except Exception as error:
            if not report_others:
                raise
            print(f"{fn.__name__}: {type(error).__name__}: {error}")
        else:
            if fn not in quiet:
                print(f"{fn.__name__}: {ok}")
