"""Checks that the kernels of sim-run --json add up to the run's launches
and kernel time (kernel-profile.test)."""
import json
import sys

for name, path in zip(("lts", "simple"), sys.argv[1:]):
    run = json.load(open(path))
    kernels = run["kernels"]
    launches = sum(k["launches"] for k in kernels)
    seconds = sum(k["seconds"] for k in kernels)
    # With --repeat, kernel_seconds is the median of the runs; the kernels
    # are the last run's, whose time is the last of kernel_seconds_runs.
    last = run["kernel_seconds_runs"][-1]
    print(f"{name}: {len(kernels)} kernels, launches add up: "
          f"{launches == run['launches']}, seconds add up: "
          f"{abs(seconds - last) <= 1e-9 * max(1.0, last)}")
