"""Prints how far a total of a sim-run --json report drifts from its value
at the first output time, against a relative bound.

Usage: total_drift.py REPORT.json TOTAL BOUND

Prints `TOTAL drift within BOUND over N output times` (or `BEYOND`) for
FileCheck, and the drift itself on stderr; exits 1 beyond the bound.
"""

import json
import sys


def main():
    path, total, bound = sys.argv[1], sys.argv[2], float(sys.argv[3])
    with open(path) as f:
        series = json.load(f)["totals_per_output_time"]
    first = series[0][total]
    drift = max(abs(point[total] - first) for point in series) / abs(first)
    verdict = "within" if drift <= bound else "BEYOND"
    print(f"{total} drift {verdict} {bound:g} over {len(series)} output times")
    print(f"{total}: relative drift {drift:.3e} from {first:.17g}",
          file=sys.stderr)
    return 0 if drift <= bound else 1


if __name__ == "__main__":
    sys.exit(main())
