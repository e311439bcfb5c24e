#!/usr/bin/env bash
# Runs sim's GPU checks and benchmarks on a machine with a GPU and no MLIR,
# from a folder utils/gpu-pack.sh filled on the build machine. Every stage
# writes its log (and tables) under $OUT (default: gpu-results) and the run
# goes on after a failing stage; the exit status says whether any failed.
#
# Usage: utils/gpu-check.sh PACK [STAGE...]
#   device      nvidia-smi and the CUDA driver sim-run finds
#   crosscheck  sim-run --check on CUDA over every suite of the cross-check
#               matrix that runs there (the pack's copy of
#               test/Integration/crosscheck-matrix.json)
#   sanitize    compute-sanitizer racecheck and memcheck of every strategy of
#               both paper scenes, sim's kernels and the hand-written ones
#   targets     bench/run at the issue's setting: |R| 65536, L 1024, dist
#               0-2, linear, against sim-baseline-cuda
#   sizes       bench/run over every size, load and interpolation
#               (long: give it a call of its own)
#   profile     ncu of the hip kernels, sim's and the hand-written ones
#   default: device crosscheck sanitize targets profile
set -uo pipefail

if [[ $# -lt 1 || "$1" == "--help" || "$1" == "-h" ]]; then
  sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'
  exit $([[ $# -lt 1 ]] && echo 2 || echo 0)
fi

cd "$(dirname "$0")/.."
pack="$1"
shift
stages=("$@")
((${#stages[@]})) || stages=(device crosscheck sanitize targets profile)
out="${OUT:-gpu-results}"
mkdir -p "$out"
run="$pack/bin/sim-run"
baseline="$pack/bin/sim-baseline-cuda"
cuda_bin=/usr/local/cuda/bin
export PATH="$PATH:$cuda_bin"
failed=()

stage() {
  local name="$1"
  shift
  echo "== $name" >&2
  local start=$SECONDS
  if "$@" > "$out/$name.log" 2>&1; then
    echo "   ok ($((SECONDS - start)) s): $out/$name.log" >&2
  else
    echo "   FAILED ($((SECONDS - start)) s): $out/$name.log" >&2
    tail -5 "$out/$name.log" >&2
    failed+=("$name")
  fi
}

device() {
  nvidia-smi || true
  "$run" "$pack/crosscheck/gravity_like.simb" --backend cuda --steps 1
}

crosscheck() {
  python3 test/Integration/Inputs/crosscheck.py run --backend cuda \
    --matrix "$pack/crosscheck/matrix.json" --bundles "$pack/crosscheck" \
    --out "$out/crosscheck" --sim-run "$run"
}

sanitize() {
  local status=0 tool scene strategy
  for tool in racecheck memcheck; do
    for scene in gravity_like pbd_like; do
      for strategy in $(python3 python/simlists.py strategies); do
        local settings=(--strategy "$strategy" --steps 6 --set range=1000
                        --set L=8 --set dist=2 --group-size 256)
        echo "-- $tool $scene $strategy (sim)"
        compute-sanitizer --tool "$tool" --error-exitcode 3 \
          "$run" "$pack/bench/$scene-linear-g256.simb" --backend cuda \
          "${settings[@]}" | tail -3 || status=1
        echo "-- $tool $scene $strategy (hand-written)"
        compute-sanitizer --tool "$tool" --error-exitcode 3 \
          "$baseline" --scene "$scene" "${settings[@]}" | tail -3 || status=1
      done
    done
  done
  return $status
}

study() {
  python3 bench/run --backend cuda --bundles "$pack/bench" --sim-run "$run" \
    --baseline "$baseline" "$@"
}

targets() {
  study --sizes 65536 --loads 1024 --dists 0,1,2 --interps linear \
    --repeat 10 --out "$out/targets"
}

sizes() {
  study --repeat 5 --out "$out/sizes"
}

profile() {
  command -v ncu > /dev/null || { echo "ncu not found"; return 1; }
  local scene settings=(--strategy hip --steps 3 --set range=65536 --set L=1024
                        --set dist=0 --group-size 256)
  for scene in gravity_like pbd_like; do
    ncu --section SpeedOfLight --section Occupancy --section LaunchStats \
      --section ComputeWorkloadAnalysis -k "regex:substep|evaluate" -c 12 \
      "$run" "$pack/bench/$scene-linear-g256.simb" --backend cuda "${settings[@]}" \
      > "$out/ncu-$scene-sim.txt" 2>&1 || return 1
    ncu --section SpeedOfLight --section Occupancy --section LaunchStats \
      --section ComputeWorkloadAnalysis -k "regex:substep|evaluate" -c 12 \
      "$baseline" --scene "$scene" "${settings[@]}" \
      > "$out/ncu-$scene-hand-written.txt" 2>&1 || return 1
  done
  grep -h -E "^  [a-zA-Z_]+.*\(|Registers Per Thread|Achieved Occupancy|Compute \(SM\) Throughput|Duration" \
    "$out"/ncu-*.txt
}

for name in "${stages[@]}"; do
  case "$name" in
  device | crosscheck | sanitize | targets | sizes | profile)
    stage "$name" "$name" ;;
  *)
    echo "gpu-check: unknown stage '$name' (see --help)" >&2
    exit 2 ;;
  esac
done
if ((${#failed[@]})); then
  echo "gpu-check: failed: ${failed[*]}" >&2
  exit 1
fi
echo "gpu-check: every stage passed; results in $out" >&2
