#!/usr/bin/env python3
"""Starts bench/run with the arguments after SIGNAL, its runs done by
fake_sim_run.py sleeping (FAKE_SIM_SLEEP), sends SIGNAL (TERM or INT) to it
while a run is in flight, and prints how it ended: its status, what it
wrote to stderr, whether the run in flight is still there and how many
temporary folders are left in TMPDIR (bench/run's go there).

Usage: stop_bench.py TMPDIR SIGNAL BENCH_RUN ARGS...
"""

import os
import signal
import subprocess
import sys
import time

tmp, name, command = sys.argv[1], sys.argv[2], sys.argv[3:]
os.makedirs(tmp, exist_ok=True)
started = os.path.join(tmp, "..", os.path.basename(tmp) + ".started")
if os.path.exists(started):
    os.remove(started)
env = dict(os.environ, TMPDIR=tmp, FAKE_SIM_SLEEP="60",
           FAKE_SIM_STARTED=started)
bench = subprocess.Popen([sys.executable] + command, env=env,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
deadline = time.time() + 30
while not os.path.exists(started) or not open(started).read():
    if time.time() > deadline or bench.poll() is not None:
        bench.kill()
        sys.exit("stop_bench.py: no run started")
    time.sleep(0.05)
fake = int(open(started).read())
print("temporary folders while it runs: %d" % len(os.listdir(tmp)))
bench.send_signal(getattr(signal, "SIG" + name))
try:
    _, err = bench.communicate(timeout=30)
except subprocess.TimeoutExpired:
    bench.kill()
    sys.exit("stop_bench.py: bench/run did not stop")
print("status %d" % bench.returncode)
sys.stdout.write(err.decode(errors="replace"))
try:
    os.kill(fake, 0)
    alive = "yes"
except ProcessLookupError:
    alive = "no"
print("run in flight still there: %s" % alive)
print("temporary folders left: %d" % len(os.listdir(tmp)))
