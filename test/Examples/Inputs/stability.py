#!/usr/bin/env python3
"""Hard cases of the physics scenes on one backend, with stated bounds.

Each case runs `sim-run --check-finite --json` and checks the totals the
scene declares (relative change from T = 0 to the end) or its error against
the exact solution. Prints one line per case; exits with 1 when a bound is
missed. The bounds sit above what was measured (docs/accuracy.md) so that
they catch a regression, not rounding.

Usage: stability.py SIM_RUN EXAMPLES_DIR OUTDIR [--backend cpu]
"""

import json
import os
import subprocess
import sys

sim_run, examples, outdir = sys.argv[1:4]
backend = sys.argv[5] if len(sys.argv) > 5 and sys.argv[4] == "--backend" else "cpu"
os.makedirs(outdir, exist_ok=True)
failures = 0


def run(name, scene, steps, sets=(), extra=()):
    out = os.path.join(outdir, name + ".json")
    command = [sim_run, os.path.join(examples, scene), "--backend", backend,
               "--strategy", "hip", "--steps", str(steps), "--group-size", "32",
               "--check-finite", "--json", out] + list(extra)
    for s in sets:
        command += ["--set", s]
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT)
    return result.returncode, result.stdout.decode(errors="replace"), out


def drift(out, total):
    series = json.load(open(out))["totals_per_output_time"]
    first, last = series[0][total], series[-1][total]
    return abs(last - first) / abs(first)


def check(label, value, bound):
    global failures
    ok = value <= bound
    failures += not ok
    print("%s %.2e <= %.0e: %s" % (label, value, bound, "ok" if ok else "MISSED"))


def finite_case(label, name, scene, steps, sets=(), extra=()):
    """Runs a case that must stay finite; the output's JSON, or None."""
    status, text, out = run(name, scene, steps, sets, extra)
    print("%s: exit %d%s" % (label, status,
                             ", finite" if status == 0 else "\n" + text))
    if status != 0:
        global failures
        failures += 1
        return None
    return out


# Kepler, e = 0.6: 10^4 base steps (1.6 orbits) in big steps of max_steps
# (8), pericentre passages at 1 base step.
out = finite_case("kepler 10000 base steps", "kepler", "physics/kepler.mlir",
                  10000, extra=["--report-every", "10000"])
if out:
    check("kepler energy drift", drift(out, "Energy"), 1e-7)
    check("kepler angular momentum drift", drift(out, "AngularMomentum"), 1e-12)

# Plummer N-body with close encounters: 10^4 base steps.
out = finite_case("nbody 10000 base steps", "nbody", "physics/nbody.mlir",
                  10000, extra=["--report-every", "10000"])
if out:
    check("nbody energy drift", drift(out, "Energy"), 2e-3)
    check("nbody momentum drift", drift(out, "MomentumX"), 1e-12)

# KPR at omega = 1000 (dt 5e-5 resolves the fast mode): one time unit.
out = finite_case("kpr omega 1000 20000 base steps", "kpr", "physics/kpr.mlir",
                  20000, sets=["omega=1000", "dt=5e-5"],
                  extra=["--reference", "exact"])
if out:
    error = json.load(open(out))["error"]
    check("kpr omega 1000 U rms-rel", error["U"]["rms_rel"], 1e-4)
    check("kpr omega 1000 V rms-rel", error["V"]["rms_rel"], 2e-3)

# A blow-up: the stiff spring chain at dt = 0.05, beyond Verlet's limit
# 2 / sqrt(K) = 0.02 for K = 1e4. --check-finite must stop it and name the
# base step, component and item.
status, text, out = run("springs-blowup", "physics/springs.mlir", 2000,
                        sets=["dt=0.05"])
print("springs dt 0.05: exit %d: %s" % (status, text.strip().splitlines()[-1]))

sys.exit(1 if failures else 0)
