#!/usr/bin/env bash
# Sets up sim on Debian 12 (run as root): installs the toolchain and the test
# tools from Debian's packages when they are missing, then configures and
# builds everything in build/ (the compiler, the tools and the unit tests).
#
# Usage: utils/setup.sh [--help]
#   SIM_BUILD_DIR   build directory (default: build)
#   SIM_BUILD_TYPE  CMake build type (default: Release)
set -euo pipefail

if [[ "${1:-}" == "--help" || "${1:-}" == "-h" ]]; then
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi

cd "$(dirname "$0")/.."
build_dir="${SIM_BUILD_DIR:-build}"
build_type="${SIM_BUILD_TYPE:-Release}"

# MLIR/LLVM 22 (headers, CMake package, mlir-tblgen, FileCheck, lit), the
# compiler and linker, the build tools, GoogleTest, sim-run's header-only
# libraries (CLI11 for its command line, nlohmann-json for its JSON), what
# the bundle format needs (FlatBuffers' schema compiler and headers, zlib for
# its CRC-32), zlib's minizip for sim-run's .npz files (linked statically),
# Python for lit and the scene generator with numpy and matplotlib for the
# Python package python/sim (numpy arrays in and out of runs, plots) and
# the tests that read sim-run's .npy and .npz files, Graphviz to render
# dependency graphs in tests, clang-22's OpenMP runtime for the
# hand-written CPU baseline of the benchmarks (bench/cpu), and Open MPI for
# distributed runs (sim-run --distributed under mpirun; docs/Distributed.md).
packages=(
  libmlir-22-dev mlir-22-tools llvm-22-dev llvm-22-tools clang-22 lld-22
  libomp-22-dev libopenmpi-dev openmpi-bin
  cmake ninja-build libgtest-dev libcli11-dev nlohmann-json3-dev
  libflatbuffers-dev flatbuffers-compiler zlib1g-dev libminizip-dev python3
  python3-numpy python3-matplotlib graphviz
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed" \
    || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# The tests run Debian's Python (/usr/bin/python3), the one the packages
# above install numpy and matplotlib for, whatever python3 comes first on
# PATH.
cmake -G Ninja -S . -B "$build_dir" \
  -DCMAKE_BUILD_TYPE="$build_type" \
  -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DCMAKE_C_COMPILER=clang-22 -DCMAKE_CXX_COMPILER=clang++-22 \
  -DLLVM_USE_LINKER=lld \
  -DMLIR_DIR=/usr/lib/llvm-22/lib/cmake/mlir
cmake --build "$build_dir"
