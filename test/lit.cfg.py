# -*- Python -*-
# The sim lit suite: FileCheck, --verify-diagnostics and tool tests. The unit
# tests run from test/Unit and the runtime's tests from test/Runtime, each
# with its own configuration.

import os
import subprocess
import sys

import lit.formats
from lit.llvm import llvm_config
from lit.llvm.subst import ToolSubst

config.name = "SIM"
config.test_format = lit.formats.ShTest(not llvm_config.use_lit_shell)
config.suffixes = [".mlir", ".test"]
config.test_source_root = os.path.dirname(__file__)
config.test_exec_root = os.path.join(config.sim_obj_root, "test")
config.excludes = ["Inputs", "corpus-compile", "CMakeLists.txt", "README.txt", "lit.cfg.py",
                   "lit.site.cfg.py", "Unit", "Runtime"]

llvm_config.use_default_substitutions()
llvm_config.with_environment("PATH", config.llvm_tools_dir, append_path=True)

tool_dirs = [config.sim_tools_dir, config.llvm_tools_dir]
tools = [
    "sim-opt",
    "sim-translate",
    "sim-lsp-server",
    "sim-reduce",
    "sim-run",
    "sim-bundle-fuzz-replay",
    "sim-checkpoint-fuzz-replay",
    "sim-compile-fuzz-replay",
    # Upstream's tools, for tests that run transformed IR on the CPU.
    "mlir-opt",
    "mlir-runner",
    ToolSubst("%python", config.python_executable, unresolved="fatal"),
]
llvm_config.add_tool_substitutions(tools, tool_dirs)

config.substitutions.append(("%sim_src_root", config.sim_src_root))
# MLIR's runtime libraries (libmlir_c_runner_utils.so) for mlir-runner.
config.substitutions.append(
    ("%mlir_lib_dir",
     os.path.join(os.path.dirname(config.llvm_tools_dir), "lib")))
config.substitutions.append(("%sim_obj_root", config.sim_obj_root))
# The C compiler of the build, for programs that use the runtime's C API as
# a user's would (%cc); in a sanitizer build (utils/sanitize.sh) with the
# sanitizers the runtime library was built with.
config.substitutions.append((
    "%cc", config.c_compiler +
    (" -fsanitize=address,undefined" if config.sim_asan_runtime else "")))
config.substitutions.append(("%examples", os.path.join(config.sim_src_root,
                                                        "examples")))
# The strategies, separated by spaces, for shell loops: python/simlists.py
# holds the one list the tests and scripts read.
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(config.sim_src_root, "python"))
from simlists import STRATEGIES  # noqa: E402
sys.path.pop(0)
config.substitutions.append(("%sim_strategies", " ".join(STRATEGIES)))
# The FlatBuffers schema compiler the build generated the bundle schema's
# C++ with, and the schema: tests decode bundles to JSON with them.
config.substitutions.append(("%flatc", config.flatc))

# Python loads the runtime with ctypes (python/simrt.py): in a sanitizer
# build (utils/sanitize.sh) the ASan runtime must come first, and the
# interpreter's own allocations are not ours to report.
ctypes_env = ""
if config.sim_asan_runtime:
    config.available_features.add("asan")
    ctypes_env = ("LD_PRELOAD=%s ASAN_OPTIONS=allow_user_poisoning=0:"
                  "detect_leaks=0" % config.sim_asan_runtime)
config.substitutions.append(("%ctypes_env", ctypes_env))
config.substitutions.append(("%bundle_schema", os.path.join(
    config.sim_src_root, "runtime", "schema", "bundle.fbs")))

# The Python package python/sim runs bundles with numpy and plots with
# matplotlib (utils/setup.sh installs Debian's python3-numpy and
# python3-matplotlib and configures the tests with /usr/bin/python3): tests
# that need them say `REQUIRES: numpy` or `REQUIRES: matplotlib`.
# Tests import python/sim and python/examples; keep the source tree free of
# __pycache__ folders.
config.environment["PYTHONDONTWRITEBYTECODE"] = "1"
for module in ("numpy", "matplotlib"):
    if subprocess.run([config.python_executable, "-c", "import " + module],
                      stdout=subprocess.DEVNULL,
                      stderr=subprocess.DEVNULL).returncode == 0:
        config.available_features.add(module)

# `cpu-baseline`: the hand-written CPU baseline of the benchmarks
# (bench/cpu) was built, which needs OpenMP (libomp-22-dev).
if config.sim_cpu_baseline:
    config.available_features.add("cpu-baseline")

# `dot` renders the dependency graph in tests when Graphviz is installed.
if lit.util.which("dot"):
    config.available_features.add("dot")

# The CUDA toolkit, found as the GPU back end finds it: $CUDA_ROOT,
# $CUDA_HOME, $CUDA_PATH, then /usr/local/cuda. The tools see the same
# variables, so `libdevice` means "the pipelines will link libdevice".
cuda_variables = ["CUDA_ROOT", "CUDA_HOME", "CUDA_PATH"]
llvm_config.with_system_environment(cuda_variables)
cuda_root = next((os.environ[v] for v in cuda_variables if os.environ.get(v)),
                 "/usr/local/cuda")
if os.path.isfile(os.path.join(cuda_root, "nvvm", "libdevice",
                               "libdevice.10.bc")):
    config.available_features.add("libdevice")


def runs(command):
    try:
        return subprocess.run(command, stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, timeout=60,
                              check=True).stdout.decode(errors="replace")
    except (OSError, subprocess.SubprocessError):
        return None


# `ptxas` assembles the PTX the compiler emits (tests check that it is valid
# and does not spill).
for ptxas in [os.path.join(cuda_root, "bin", "ptxas"),
              "/usr/local/cuda/bin/ptxas", lit.util.which("ptxas")]:
    if ptxas and os.path.isfile(ptxas) and runs([ptxas, "--version"]):
        config.available_features.add("ptxas")
        config.substitutions.append(("%ptxas", ptxas))
        break

# `nvcc` compiles the hand-written CUDA baseline of bench/cuda (a test
# checks that the register counts test/Target/PTX compares with are
# current).
for nvcc in [os.path.join(cuda_root, "bin", "nvcc"), lit.util.which("nvcc")]:
    if nvcc and os.path.isfile(nvcc) and runs([nvcc, "--version"]):
        config.available_features.add("nvcc")
        config.substitutions.append(("%nvcc", nvcc))
        break

# `mpi`: sim-run was built with --distributed and mpirun is here. %mpirun
# runs N ranks on this machine whatever its cores (--oversubscribe), also
# as root (the CI containers).
# In a sanitizer build the ranks leave Open MPI's own allocations to
# LeakSanitizer, suppressed by utils/lsan-openmpi.supp (which says why the
# other two settings).
mpirun = lit.util.which("mpirun")
if config.sim_mpi and mpirun:
    config.available_features.add("mpi")
    leak_env = ""
    if config.sim_asan_runtime:
        leak_env = ("LSAN_OPTIONS=suppressions=%s:fast_unwind_on_malloc=0 "
                    "OMPI_MCA_mca_component_disable_dlclose=1 " %
                    os.path.join(config.sim_src_root, "utils",
                                 "lsan-openmpi.supp"))
    config.substitutions.append((
        "%mpirun", "env OMPI_ALLOW_RUN_AS_ROOT=1 "
        "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 "
        "%s%s --oversubscribe" % (leak_env, mpirun)))

# `sim-distributed`: sim-translate compiles plans for many processes
# (--sim-distributed, docs/Distributed.md).
translate = os.path.join(config.sim_tools_dir, "sim-translate")
if "sim-distributed" in (runs([translate, "--help"]) or ""):
    config.available_features.add("sim-distributed")

# `cuda`: a CUDA driver and at least one GPU, for execution tests.
smi = lit.util.which("nvidia-smi")
if smi and "GPU " in (runs([smi, "-L"]) or ""):
    config.available_features.add("cuda")


# `numpy`: a Python that imports NumPy, to read sim-run's .npy and .npz
# files as users do (%numpy_python). The build's Python first, then Debian's
# (python3-numpy, which utils/setup.sh installs).
for python in [config.python_executable, "/usr/bin/python3",
               lit.util.which("python3")]:
    if python and runs([python, "-c", "import numpy"]) is not None:
        config.available_features.add("numpy")
        config.substitutions.append(("%numpy_python", python))
        break
