#!/usr/bin/env bash
# Packs what a GPU machine without MLIR needs to check and benchmark sim: the
# runtime's sim-run, the hand-written baseline sim-baseline-cuda, and the
# bundles of the cross-check matrix (every scene of
# test/Integration/crosscheck-matrix.json that runs on CUDA, beside a copy of
# the matrix they were compiled from) and of the benchmark study, compiled
# here, and, where sim-run was built with MPI, its MPI plugin and the
# distributed bundles of the paper scenes. The folder is listed in
# .git/info/exclude, so the `device` tool carries it when asked (carry:
# ["gpu-pack"]); there, utils/gpu-check.sh runs the checks and the study.
#
# Usage: utils/gpu-pack.sh [--help]
#   SIM_BUILD_DIR     build directory with sim-translate, sim-opt, sim-run and
#                     sim-baseline-cuda (default: build)
#   SIM_GPU_PACK      the folder to fill (default: gpu-pack)
#   SIM_GPU_PACK_MPI  1: also pack this machine's Open MPI runtime (Debian's
#                     packages, about 13 MiB) as mpi/openmpi.tar, for a GPU
#                     machine without MPI (gpu-check.sh's distributed stage
#                     installs it there when SIM_GPU_INSTALL_MPI=1)
set -euo pipefail

if [[ "${1:-}" == "--help" || "${1:-}" == "-h" ]]; then
  sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi

cd "$(dirname "$0")/.."
build="${SIM_BUILD_DIR:-build}"
pack="${SIM_GPU_PACK:-gpu-pack}"
for tool in sim-translate sim-opt sim-run sim-baseline-cuda; do
  [[ -x "$build/bin/$tool" ]] || {
    echo "gpu-pack: $build/bin/$tool is missing (build it first; sim-baseline-cuda needs nvcc)" >&2
    exit 1
  }
done

mkdir -p .git/info
for ignored in "/$pack/" /gpu-results/; do
  grep -qx "$ignored" .git/info/exclude 2>/dev/null || echo "$ignored" >> .git/info/exclude
done
rm -rf "$pack"
mkdir -p "$pack/bin" "$pack/crosscheck" "$pack/bench"
cp "$build/bin/sim-run" "$build/bin/sim-baseline-cuda" "$pack/bin/"

# The cross-check matrix, with the copy of it that gpu-check.sh runs.
cp test/Integration/crosscheck-matrix.json "$pack/crosscheck/matrix.json"
python3 test/Integration/Inputs/crosscheck.py compile --backend cuda \
  --matrix "$pack/crosscheck/matrix.json" --bundles "$pack/crosscheck" \
  --sim-translate "$build/bin/sim-translate" --sim-opt "$build/bin/sim-opt"

# The benchmark study (group size 256, both interpolations).
python3 bench/run --make-bundles --bundles "$pack/bench" \
  --sim-translate "$build/bin/sim-translate" 2>&1 | grep -v '^compiling' || true
# The loop shapes that gpu-check.sh stage loops measures against the
# default: 32-bit counters, and those unrolled twice.
python3 bench/run --make-bundles --bundles "$pack/bench" --interps linear \
  --variant narrow --translate-flag=--sim-gpu-narrow-loops \
  --sim-translate "$build/bin/sim-translate" 2>&1 | grep -v '^compiling' || true
python3 bench/run --make-bundles --bundles "$pack/bench" --interps linear \
  --variant narrow-u2 --translate-flag=--sim-gpu-narrow-loops \
  --translate-flag=--sim-gpu-unroll=2 \
  --sim-translate "$build/bin/sim-translate" 2>&1 | grep -v '^compiling' || true
rm -f "$pack"/bench/*.mlir

# Distributed runs on CUDA (test/Integration/distributed-cuda.test at a
# larger size): the MPI plugin where sim-run looks for it (../lib) and the paper scenes' bundles.
if [[ -f "$build/lib/libsim_mpi.so" ]]; then
  mkdir -p "$pack/lib"
  cp "$build/lib/libsim_mpi.so" "$pack/lib/"
  mkdir -p "$pack/distributed"
  for scene in gravity_like pbd_like; do
    "$build/bin/sim-translate" "examples/paper/$scene.mlir" --sim-to-bundle \
      --sim-distributed -o "$pack/distributed/$scene.simb"
  done
fi
if [[ "${SIM_GPU_PACK_MPI:-0}" == 1 ]]; then
  # The Open MPI that libsim_mpi.so was linked against, with what its
  # libraries and its PMIx need, as Debian installed them (absolute paths,
  # since Open MPI finds its components and help files there).
  mkdir -p "$pack/mpi"
  dpkg -L openmpi-bin openmpi-common libopenmpi3 libpmix2 libhwloc15 \
    libevent-core-2.1-7 libevent-pthreads-2.1-7 libmunge2 |
    grep -v -E '^/usr/share/(doc|man|lintian)/' |
    while read -r path; do [[ -f "$path" || -L "$path" ]] && echo "$path"; done \
    > "$pack/mpi/files"
  tar -cf "$pack/mpi/openmpi.tar" -P -T "$pack/mpi/files"
  # The alternatives links (mpirun -> orterun) Debian makes at install.
  echo "$(readlink -f "$(command -v mpirun)")" > "$pack/mpi/mpirun"
fi

du -sh "$pack"
echo "gpu-pack: wrote $pack; carry it and run: utils/gpu-check.sh $pack"
