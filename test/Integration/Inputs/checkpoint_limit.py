"""checkpoint_limit.py SIM_RUN BUNDLE FOLDER: checkpoints of --checkpoint-every
that stop fitting in the middle of a run (checkpoint-write-fails.test).

sim-run runs towards 10^9 base steps with a checkpoint at every one and
SIGXFSZ ignored. Once the first checkpoint is there, the limit on the size
of the files it writes (RLIMIT_FSIZE, set with prlimit) drops below the
checkpoint's size, so that the next write fails with EFBIG, as on a full
disk; once sim-run has said so, SIGINT stops the run. Prints sim-run's
status and standard error, the checkpoint rows of its table, the JSON's
"checkpoint", and how a run restarted from the checkpoint that stayed ends.
"""
import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import time

sim_run, bundle, folder = sys.argv[1:4]
# A checkpoint an earlier run left would pass for the first one.
shutil.rmtree(folder, ignore_errors=True)
os.makedirs(folder)
checkpoint = os.path.join(folder, "c.simc")
report = os.path.join(folder, "j.json")
errors = os.path.join(folder, "stderr")
LIMIT = 600000


def wait_for(condition, what):
    deadline = time.monotonic() + 120
    while not condition():
        if run.poll() is not None or time.monotonic() > deadline:
            sys.exit(f"sim-run ended or took too long before {what}")
        time.sleep(0.01)


def dispositions():
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    # lit's workers ignore SIGINT, and sim-run keeps a signal ignored that
    # was ignored when it started.
    signal.signal(signal.SIGINT, signal.SIG_DFL)


with open(errors, "w") as stderr:
    run = subprocess.Popen(
        [sim_run, bundle, "--backend", "cpu", "--no-init-check", "--steps",
         "1000000000", "--checkpoint", checkpoint, "--checkpoint-every", "1",
         "--json", report],
        stdout=subprocess.PIPE, stderr=stderr, text=True,
        preexec_fn=dispositions)
    try:
        wait_for(lambda: os.path.exists(checkpoint), "the first checkpoint")
        resource.prlimit(run.pid, resource.RLIMIT_FSIZE, (LIMIT, LIMIT))
        wait_for(lambda: "was not written" in open(errors).read(),
                 "a failed write")
        run.send_signal(signal.SIGINT)
        table, _ = run.communicate(timeout=120)
    finally:
        # Whatever went wrong, no run towards 10^9 base steps is left behind.
        if run.poll() is None:
            run.kill()
            run.wait()

print("status", run.returncode)
print(open(errors).read(), end="")
for line in table.splitlines():
    if line.lstrip().startswith(("checkpoint", "interrupted")):
        print(line)
stayed = json.load(open(report))["checkpoint"]
print("json", stayed["written"] > 0, [f["error"] for f in stayed["failed"]])
# The checkpoint that stayed is the last one written, whole: a run
# restarts from it.
restart = subprocess.run(
    [sim_run, bundle, "--backend", "cpu", "--no-init-check", "--steps",
     str(stayed["base_step"] + 2), "--restart", checkpoint],
    stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
print("restart", restart.returncode,
      f"restarted from checkpoint '{checkpoint}' at base step "
      f"{stayed['base_step']}\n" in restart.stdout)
