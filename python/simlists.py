#!/usr/bin/env python3
"""The lists that several tests, scripts and benchmarks share, in one place.

STRATEGIES: the runtime's strategies, in the order of their values in the C
API (`sim_strategy`, runtime/include/sim/Runtime/sim_runtime.h) and the
bundle schema (`enum Strategy`, runtime/schema/bundle.fbs), so that a
strategy's value is its index. test/Python/strategies.test checks this list
against both, so that it cannot drift from the runtime; read it from here
instead of writing the names again:

  - Python: `from simlists import STRATEGIES` (python/ on sys.path);
  - lit tests: the substitution `%sim_strategies` (test/lit.cfg.py), the
    names separated by spaces, for shell loops;
  - shell scripts: `python3 python/simlists.py strategies`.

The cross-check matrix (which scenes, variants, ranges and tolerances) is
the data file test/Integration/crosscheck-matrix.json, which
test/Integration/Inputs/crosscheck.py reads.

Standard library only; it loads nothing (no runtime library).
"""

import sys

STRATEGIES = ("simple", "traditional", "hip", "hip-cache", "lts")


def schema_name(strategy):
    """The name of a strategy in the bundle schema's enum (`hip-cache` is
    `HipCache`), as flatc writes it in a bundle's JSON."""
    return "".join(part.capitalize() for part in strategy.split("-"))


def main(argv):
    if argv == ["strategies"]:
        print(" ".join(STRATEGIES))
        return 0
    print("usage: simlists.py strategies   (prints the strategies, "
          "separated by spaces)", file=sys.stderr)
    return 0 if argv in (["-h"], ["--help"]) else 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
