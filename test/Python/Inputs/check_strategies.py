"""Checks python/simlists.py's STRATEGIES against the runtime's C API
(sim_strategy_name through simrt) and the bundle schema's `enum Strategy`:
the same names with the same values. Also that simrt takes a strategy by the
runtime's own parser.

Usage: check_strategies.py BUNDLE_FBS BUNDLE
"""
import re
import sys

import simlists
import simrt

failed = False


def compare(what, names, expected):
    global failed
    failed |= names != expected
    print("%s: %s" % (what, "as in simlists" if names == expected else
                      "DIFFERENT: %s, simlists says %s" % (names, expected)))


compare("C API sim_strategy_name", simrt.strategies(),
        list(simlists.STRATEGIES))

schema = open(sys.argv[1]).read()
enum = re.search(r"enum Strategy\s*:\s*\w+\s*\{([^}]*)\}", schema).group(1)
values = {int(value): name for name, value in
          re.findall(r"(\w+)\s*=\s*(\d+)", enum)}
compare("schema enum Strategy", [values.get(v) for v in range(len(values))],
        [simlists.schema_name(s) for s in simlists.STRATEGIES])

with simrt.Bundle(sys.argv[2]) as bundle:
    print("bundle has", " ".join(s for s in simlists.STRATEGIES
                                 if bundle.has_strategy(s)))
    try:
        simrt.Session(bundle, strategy="fastest")
    except simrt.Error as error:
        print("error:", error)
sys.exit(1 if failed else 0)
