#!/usr/bin/env python3
"""A stand-in for sim-run --json and for sim-baseline-cpu in bench/run's
tests: it runs nothing and writes the times and counters of a made-up scene,
per strategy, so that the tables bench/run prints from them are known in
advance (test/Bench/noise.test). As sim-run:

  simple       1.00 s, every run; 100 evaluations
  traditional  0.90-1.20 s (spread 30%); 50 evaluations
  hip          0.40 s, every run: 2.5x simple, above its ceiling of 2x
  hip-cache    0.60 s, every run: 1.67x simple, below its ceiling
  lts          as hip

As the baseline (--scene given): 0.50 s every run, except hip-cache at
0.50-0.60 s (spread 20%). Both dump the same observed state (--dump).

With FAKE_FMA_PEAK=F in the environment the device is a CPU ("CPU
(fake)") and --fma-peak reports a peak of F flop/s, for the "of peak"
column; without it --fma-peak fails. With FAKE_SIM_SLEEP=S a run writes
its process id into the file FAKE_SIM_STARTED names and sleeps S seconds
first (test/Bench/signal.test stops bench/run meanwhile).
"""

import json
import os
import struct
import sys
import time

TIMES = {"simple": [1.0, 1.0, 1.0], "traditional": [0.9, 1.0, 1.2],
         "hip": [0.4, 0.4, 0.4], "hip-cache": [0.6, 0.6, 0.6],
         "lts": [0.4, 0.4, 0.4]}
BASELINE_TIMES = {"hip-cache": [0.5, 0.55, 0.6]}

args = sys.argv[1:]
if "--help" in args:
    print("OVERVIEW: hand-written CPU code (a stand-in for bench/run's tests)")
    sys.exit(0)
if "--fma-peak" in args:
    if "FAKE_FMA_PEAK" not in os.environ:
        sys.exit("fake_sim_run.py: no FAKE_FMA_PEAK")
    with open(args[args.index("--json") + 1], "w") as f:
        json.dump({"fma_peak_flops": float(os.environ["FAKE_FMA_PEAK"])}, f)
    sys.exit(0)
if "FAKE_SIM_SLEEP" in os.environ:
    with open(os.environ["FAKE_SIM_STARTED"], "w") as f:
        f.write(str(os.getpid()))
    time.sleep(float(os.environ["FAKE_SIM_SLEEP"]))
baseline = "--scene" in args
strategy = args[args.index("--strategy") + 1]
out = args[args.index("--json") + 1]
times = (BASELINE_TIMES.get(strategy, [0.5] * 3) if baseline
         else TIMES[strategy])
evaluations = 100 if strategy == "simple" else 50
with open(out, "w") as f:
    json.dump({"device": "CPU (fake)" if "FAKE_FMA_PEAK" in os.environ
               else "fake", "backend": "cpu",
               "kernel_seconds_runs": times, "wall_seconds_runs": times,
               "evaluations": {"C0": evaluations}, "big_steps": 10,
               "big_step_histogram": {"1": 10}, "launches": 20,
               "host_syncs": 2}, f)
if "--dump" in args:
    folder = args[args.index("--dump") + 1]
    os.makedirs(folder, exist_ok=True)
    header = "{'descr': '<f4', 'fortran_order': False, 'shape': (1, 4), }"
    header += " " * (63 - (10 + len(header)) % 64) + "\n"
    with open(os.path.join(folder, "B2.npy"), "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) +
                header.encode() + struct.pack("<4f", 0.5, -0.5, 0.25, 0.0))
