# Runs Inputs/edge-cases.mlir's bundle (argv[2]; argv[1] is sim-run) with each set of
# parameters on the reference executor and the CPU backend at every
# instruction-set level, prints the reference's results of a few items and
# whether every run gave the same bits (for ../edge-cases.test).
import os
import subprocess
import sys

import numpy as np

sim_run, bundle, out = sys.argv[1:4]
runs = [("reference", None), ("cpu", "x86-64"), ("cpu", "x86-64-v3"),
        ("cpu", "x86-64-v4")]
cases = [
    dict(d="0", s="32", x="nan", step="0"),
    dict(d="-1", s="40", x="inf", step="-2"),
    dict(d="3", s="31", x="-inf", step="1"),
    dict(d="3", s="2", x="-3000000000", step="3"),
    dict(d="3", s="2", x="4294967040", step="4"),
    dict(d="3", s="2", x="-0.9", step="5"),
]
for number, case in enumerate(cases):
    print(" ".join(f"{k}={v}" for k, v in case.items()))
    results = []
    for backend, isa in runs:
        folder = os.path.join(out, f"{number}-{backend}-{isa}")
        env = dict(os.environ)
        if isa:
            env["SIM_CPU_ISA"] = isa
        command = [sim_run, bundle, "--backend", backend, "--steps", "1",
                   "--no-init-check", "--dump", folder]
        for name, value in case.items():
            command += ["--set", f"{name}={value}"]
        subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
        results.append(np.load(os.path.join(folder, "R.npy")))
    for item in (0, 1, 5, 8):
        values = " ".join(str(int(v)) for v in results[0][item])
        print(f"item {item}: {values}")
    same = all(r.tobytes() == results[0].tobytes() for r in results)
    print("every backend and level agrees" if same else "backends differ")
