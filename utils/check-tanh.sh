#!/bin/sh
# Checks that the CPU kernels' f32 tanh (--sim-expand-tanh: glibc's tanhf
# algorithm in SIMD arithmetic) returns the bits of this machine's libm
# tanhf on all 2^32 inputs, NaN patterns as infinities: 64 runs of 2^26
# inputs of test/Integration/Inputs/tanh-inputs.mlir, each compared byte
# for byte with the reference executor's (which calls libm). About five
# minutes on 2 cores; test/Integration/tanh-glibc.test runs every 257th input.
#
# usage: utils/check-tanh.sh [BUILD_DIR]   (default: build)
set -eu
case "${1:-}" in -h|--help) sed -n '2,9p' "$0"; exit 0 ;; esac
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
case "$build" in /*) ;; *) build=$PWD/$build ;; esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bin/sim-translate" "$root/test/Integration/Inputs/tanh-inputs.mlir" \
  --sim-to-bundle --sim-strategies=simple -o "$work/tanh.simb"
run=0
while [ $run -lt 64 ]; do
  offset=$((run * 67108864))
  # The scene's parameters are i32: offsets past 2^31 wrap.
  [ $offset -ge 2147483648 ] && offset=$((offset - 4294967296))
  for backend in cpu reference; do
    rm -rf "$work/$backend"
    "$build/bin/sim-run" "$work/tanh.simb" --strategy simple \
      --backend $backend --steps 1 --set range=4194304 --set stride=1 \
      --set offset=$offset --dump "$work/$backend" > /dev/null \
      2> "$work/$backend.log" || { cat "$work/$backend.log"; exit 1; }
  done
  if ! cmp -s "$work/cpu/T.npy" "$work/reference/T.npy"; then
    echo "check-tanh: inputs $offset .. +2^26 differ from libm's tanhf" >&2
    exit 1
  fi
  run=$((run + 1))
  echo "check-tanh: $run of 64 (2^26 inputs each) agree bit for bit" >&2
done
echo "check-tanh: all 2^32 inputs agree bit for bit with libm's tanhf"
