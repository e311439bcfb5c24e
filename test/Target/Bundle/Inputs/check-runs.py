#!/usr/bin/env python3
"""Checks sim-run --json reports: each run ended at exactly its base steps.

For each report, the big steps of each size m (the clock's histogram) must
add up to the base steps asked for, and their count to the big steps taken.
Prints one line per report; exits with 1 after the first one that fails.
Standard library only.

Usage: check-runs.py REPORT.json...
"""

import json
import sys

for path in sys.argv[1:]:
    report = json.load(open(path))
    histogram = {int(m): count
                 for m, count in report["big_step_histogram"].items()}
    covered = sum(m * count for m, count in histogram.items())
    taken = sum(histogram.values())
    print("%s %s: %d base steps in %d big steps" %
          (report["scene"], report["strategy"], covered, taken))
    if covered != report["steps"] or taken != report["big_steps"]:
        print("error: %s asked for %d base steps in %d big steps" %
              (path, report["steps"], report["big_steps"]))
        sys.exit(1)
