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
#   loops       the targets' dist 0 with 32-bit loop counters
#               (sim-translate --sim-gpu-narrow-loops), and those unrolled
#               twice (--sim-gpu-unroll=2), against the default, in
#               alternating rounds; prints each strategy's time ratios
#   profile     ncu of the hip kernels, sim's and the hand-written ones
#   distributed sim-run --distributed on CUDA, 2 and 3 ranks sharing the GPUs,
#               against one process, bit for bit (needs mpirun, or the pack's
#               mpi/openmpi.tar and SIM_GPU_INSTALL_MPI=1 to install it)
#   default: device crosscheck sanitize targets profile distributed
#   SIM_GPU_STAGE_LIMIT  seconds a stage may run before it is stopped and
#                        counted as failed (default: no limit)
#   SIM_GPU_JOBS         sanitizer runs at a time (default: 8)
set -uo pipefail

if [[ $# -lt 1 || "$1" == "--help" || "$1" == "-h" ]]; then
  sed -n '2,29p' "$0" | sed 's/^# \{0,1\}//'
  exit $([[ $# -lt 1 ]] && echo 2 || echo 0)
fi

cd "$(dirname "$0")/.."
pack="$1"
shift
stages=("$@")
((${#stages[@]})) || stages=(device crosscheck sanitize targets profile distributed)
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
  local start=$SECONDS limit="${SIM_GPU_STAGE_LIMIT:-0}"
  # The stage runs in a child shell so that `timeout` can stop all of it.
  if timeout "$limit" bash -c "$*" > "$out/$name.log" 2>&1; then
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
  # One compute-sanitizer run per tool, scene, strategy and program, up to
  # SIM_GPU_JOBS at a time on the one GPU; each writes its own log.
  local tool scene strategy jobs="${SIM_GPU_JOBS:-8}" logs="$out/sanitize"
  mkdir -p "$logs"
  for tool in racecheck memcheck; do
    for scene in gravity_like pbd_like; do
      for strategy in $(python3 python/simlists.py strategies); do
        local settings="--strategy $strategy --steps 6 --set range=1000 --set L=8 --set dist=2 --group-size 256"
        echo "$tool $scene $strategy sim $run $pack/bench/$scene-linear-g256.simb --backend cuda $settings"
        echo "$tool $scene $strategy hand-written $baseline --scene $scene $settings"
      done
    done
  done | xargs -P "$jobs" -L 1 sh -c '
    log="$0/$1-$2-$3-$4.log"; tool="$1"; shift 4
    if compute-sanitizer --tool "$tool" --error-exitcode 3 "$@" > "$log" 2>&1
    then echo "clean: $(basename "$log" .log)"
    else echo "FOUND (exit $?): $(basename "$log" .log)"; tail -20 "$log"; exit 1; fi' "$logs"
}

study() {
  python3 bench/run --backend cuda --bundles "$pack/bench" --sim-run "$run" \
    --baseline "$baseline" "$@"
}

targets() {
  study --sizes 65536 --loads 1024 --dists 0,1,2 --interps linear \
    --repeat 10 --out "$out/targets"
}

loops() {
  local round variant status=0
  for round in 1 2; do
    for variant in default narrow narrow-u2; do
      local flags=()
      [[ "$variant" == default ]] || flags=(--variant "$variant")
      study --sizes 65536 --loads 1024 --dists 0 --interps linear \
        --algorithms simple,hip,hip-cache,lts --repeat 10 "${flags[@]}" \
        --out "$out/loops/$variant-round$round" || status=1
    done
  done
  python3 - "$out/loops" <<'PY' || status=1
import json, statistics, sys
from pathlib import Path
times = {}
for path in sorted(Path(sys.argv[1]).glob("*-round*/bench.json")):
    variant = path.parent.name.rsplit("-round", 1)[0]
    for row in json.load(open(path))["runs"]:
        key = (row["scenario"], row["algorithm"])
        times.setdefault(key, {}).setdefault(variant, []).append(
            row["kernel_seconds"])
print("scenario algorithm: ms (median of rounds) default, narrow, "
      "narrow-u2; default over each")
for (scenario, algorithm), by in sorted(times.items()):
    ms = [1e3 * statistics.median(by.get(v, [float("nan")]))
          for v in ("default", "narrow", "narrow-u2")]
    print("%s %s: %.3f, %.3f, %.3f; %.3fx, %.3fx" % (
        scenario, algorithm, *ms, ms[0] / ms[1], ms[0] / ms[2]))
PY
  return $status
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

distributed() {
  [[ -f "$pack/lib/libsim_mpi.so" ]] || {
    echo "the pack has no MPI plugin (sim-run was built without MPI)"
    return 1
  }
  if ! command -v mpirun > /dev/null; then
    [[ "${SIM_GPU_INSTALL_MPI:-0}" == 1 && -f "$pack/mpi/openmpi.tar" ]] || {
      echo "no mpirun here (pack one with SIM_GPU_PACK_MPI=1 and install it" \
        "with SIM_GPU_INSTALL_MPI=1)"
      return 1
    }
    echo "installing the pack's Open MPI (files already here are kept)"
    tar -xPf "$pack/mpi/openmpi.tar" --skip-old-files || return 1
    ln -sf "$(cat "$pack/mpi/mpirun")" /usr/local/bin/mpirun
    ldconfig
  fi
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl=self,vader \
    OMPI_MCA_pml=ob1 OMPI_MCA_btl_vader_single_copy_mechanism=none \
    OMPI_MCA_mca_base_component_show_load_errors=0
  local status=0 scene
  for scene in gravity_like pbd_like; do
    python3 test/Integration/Inputs/distributed.py --sim-run "$run" \
      --mpirun mpirun --backend cuda --bundle "$pack/distributed/$scene.simb" \
      --out "$out/distributed/$scene" --steps 40 --set range=100000 \
      --set dist=2 --group-size 256 \
      --strategies simple traditional hip hip-cache lts || status=1
  done
  return $status
}

export -f device crosscheck sanitize study targets loops sizes profile distributed
export run baseline pack out
for name in "${stages[@]}"; do
  case "$name" in
  device | crosscheck | sanitize | targets | loops | sizes | profile | distributed)
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
