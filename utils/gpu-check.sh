#!/usr/bin/env bash
# Runs sim's GPU checks and benchmarks on a machine with a GPU and no MLIR,
# from a folder utils/gpu-pack.sh filled on the build machine. Every stage
# writes its log (and tables) under $OUT (default: gpu-results) and the run
# goes on after a failing stage; the exit status says whether any failed.
#
# Usage: utils/gpu-check.sh PACK [STAGE...]
#   device      nvidia-smi and the CUDA driver sim-run finds
#   crosscheck  sim-run --check on CUDA over the cross-check matrix and the
#               physics scenes (test/Integration/crosscheck-*.test)
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
  sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'
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
  "$run" "$pack/crosscheck/gravity.simb" --backend cuda --steps 1
}

crosscheck() {
  local cc="python3 test/Integration/Inputs/crosscheck.py $run $out/crosscheck --backend cuda"
  local b="$pack/crosscheck" p="$pack/physics" d="dist=0;dist=1;dist=2;dist=3;dist=4"
  mkdir -p "$out/crosscheck"
  $cc --steps 24 \
    --scene gravity_like "$b/gravity.simb" "$d" \
    --scene pbd_like "$b/pbd.simb" "$d" \
    --scene boundary_window "$b/boundary-window.simb" "force=0;force=1" \
    --scene grid_sync "$b/grid-sync.simb" "force=0;force=1;ns=3" \
    --scene wide_window_chain "$b/wide-window-chain.simb" "force=0;force=1" \
    --scene hermite "$b/hermite.simb" "force=0;force=1" \
    --scene backedge_and_interp "$b/backedge-and-interp.simb" "force=0;force=1" \
    --scene f64_vec3 "$b/f64-vec3.simb" "force=0;force=1" \
    --scene num_steps_clamp "$b/num-steps-clamp.simb" "mode=0;mode=1;force=1" \
    --scene none_backedge "$b/none-backedge.simb" "force=0;force=1" \
    --scene mixed "$b/mixed.simb" "as-is;steps=1" || return 1
  $cc --steps 24 \
    --scene harmonic "$p/harmonic.simb" "as-is" \
    --scene kpr "$p/kpr.simb" "as-is;omega=10;omega=1000" \
    --scene kepler "$p/kepler.simb" "as-is" \
    --scene nbody "$p/nbody.simb" "as-is" \
    --scene pbd "$p/pbd.simb" "as-is" \
    --scene interp_probe "$p/interp_probe.simb" "as-is" || return 1
  # springs divides by range - 1: NaN at one item, which --check fails.
  $cc --steps 24 --ranges 2,20,101 \
    --scene springs "$p/springs.simb" "as-is"
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
