"""output_save.py FOLDER: Output.save writes a whole file or none
(sim-output-save.test).

It writes under a temporary name in the destination's folder and renames
that onto the destination once complete. A write that fails midway (here
a file size limit, RLIMIT_FSIZE, in a child process; a full disk is the
same) raises one OSError that says so, leaves a good file that was there
as it was and no temporary file behind, and prints nothing else (numpy's
savez left its zip archive to the garbage collector: "Exception ignored in
ZipFile.__del__"). An exception that is no OSError (here from pickling an
object array, as numpy.savez does) comes through as it is, with no
temporary left either.
"""
import os
import resource
import signal
import stat
import subprocess
import sys

import numpy as np

import sim

folder = sys.argv[1]
path = os.path.join(folder, "run.npz")


def output(items):
    t = np.arange(0, 50, 10)
    phase = np.arange(items)[None, :] * 0.1 + t[:, None] * 1e-3
    return sim.Output(t, t * 1e-3, {"X": np.sin(phase)},
                      {"Energy": np.ones(len(t))}, meta={"scene": "save"})


if len(sys.argv) > 2 and sys.argv[2] == "child":
    # A file size limit well below the size of the file: the write fails
    # midway, with EFBIG (not the signal, which is ignored as the shell's
    # `ulimit -f` users see it once).
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (20000, 20000))
    try:
        output(4096).save(path)
        print("saved?")
    except OSError as error:
        print(f"{type(error).__name__} errno {error.errno}: {error}")
    sys.exit(0)


def listing():
    return sorted(os.listdir(folder))


def state():
    data = open(path, "rb").read()
    with np.load(path) as npz:
        shape = npz["buffer/X"].shape
    return len(data), shape


good = output(16)
print("saved:", good.save(path) == path, "files:", listing())
before = open(path, "rb").read()
os.chmod(path, 0o640)

child = subprocess.run([sys.executable, __file__, folder, "child"],
                       capture_output=True, text=True)
print("child:", child.stdout.strip().replace(folder + os.sep, ""))
print("child stderr:", repr(child.stderr))
print("file unchanged:", open(path, "rb").read() == before,
      "files:", listing())
print("loads:", sim.Output.load(path).buffers["X"].shape)

# The same limit with no file there before: none is made.
os.remove(path)
child = subprocess.run([sys.executable, __file__, folder, "child"],
                       capture_output=True, text=True)
print("child:", child.stdout.strip().replace(folder + os.sep, ""))
print("files:", listing())

# A save that succeeds replaces the file whole and keeps the mode of the
# file it replaces (as open() writing over it would); a new file has
# open()'s mode, not a temporary file's 0600.
old_umask = os.umask(0o022)
good.save(path)
print("new file mode:", oct(stat.S_IMODE(os.stat(path).st_mode)))
os.chmod(path, 0o640)
output(32).save(path)
print("replaced:", sim.Output.load(path).buffers["X"].shape, "mode:",
      oct(stat.S_IMODE(os.stat(path).st_mode)))
os.umask(old_umask)

# Through a symbolic link: the link stays, its target is written.
link = os.path.join(folder, "link.npz")
os.symlink("run.npz", link)
good.save(link)
print("link kept:", os.path.islink(link), "target:",
      sim.Output.load(path).buffers["X"].shape)
os.remove(link)

# A folder that does not exist.
try:
    good.save(os.path.join(folder, "none", "run.npz"))
except OSError as error:
    print(f"{type(error).__name__}: "
          f"{str(error).replace(folder + os.sep, '')}")


class Unpicklable:
    def __reduce__(self):
        raise RuntimeError("no pickling")


bad = sim.Output([0], [0.0], {"X": np.array([Unpicklable()], dtype=object)},
                 {})
try:
    bad.save(path)
except RuntimeError as error:
    print("RuntimeError:", error)
print("file unchanged:", sim.Output.load(path).buffers["X"].shape,
      "files:", listing())
