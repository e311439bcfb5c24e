#!/usr/bin/env bash
# Builds sim with AddressSanitizer and UndefinedBehaviorSanitizer (and
# libFuzzer's coverage instrumentation) in build-sanitize/, then:
#
#   utils/sanitize.sh check [LIT ARGS]   runs the whole test suite there
#                                        (check-sim: lit, the compiler's and
#                                        the runtime's gtests); any report
#                                        fails the test it happens in
#   utils/sanitize.sh fuzz [SECONDS] [TARGET...]
#                                        runs each fuzzer (bundle: the bundle
#                                        reader; checkpoint: the checkpoint
#                                        reader and restarts; compile: the
#                                        compiler's front end and lowering;
#                                        default all three) for
#                                        SECONDS (default 600),
#                                        seeded with the examples and the
#                                        kept corpora; crashes land in
#                                        build-sanitize/fuzz/<target>/
#   utils/sanitize.sh mutate [SECONDS] [ARGS...]
#                                        runs utils/mutate-scenes.py with the
#                                        sanitized sim-translate and sim-run
#                                        for SECONDS (default 600), so that a
#                                        mutated scene that makes our code
#                                        touch memory it must not fails with
#                                        the report even where the process
#                                        survives; failures land in
#                                        build-sanitize/mutate/
#   utils/sanitize.sh build              only builds
#
# It needs Debian's libclang-rt-22-dev (the sanitizer runtimes and
# libFuzzer). The first build takes about 20 minutes on two cores. Run
# `check` before each release, and `fuzz` after changing the bundle reader, the verifier,
# the parser or the front end; docs/Testing.md says what to do with what
# they find. Set SIM_SANITIZE_BUILD_DIR to build elsewhere.
set -euo pipefail

if [[ "${1:-}" == "--help" || "${1:-}" == "-h" || $# -eq 0 ]]; then
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
  exit 0
fi

cd "$(dirname "$0")/.."
root=$PWD
build="${SIM_SANITIZE_BUILD_DIR:-build-sanitize}"
command=$1
shift

flags="-fsanitize=address,undefined -fsanitize=fuzzer-no-link"
flags+=" -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g1"

configure() {
  # The sanitizer runtimes are Debian's libclang-rt-22-dev, which
  # utils/setup.sh does not install: the ordinary build needs none.
  if ! echo 'int main(void) { return 0; }' |
    clang-22 -x c -fsanitize=address,undefined,fuzzer-no-link - \
      -o /dev/null 2>/dev/null; then
    echo "sanitize.sh: clang-22 cannot link -fsanitize=address,undefined:" \
      "install the sanitizer runtimes (apt-get install libclang-rt-22-dev)" >&2
    exit 1
  fi
  cmake -G Ninja -S . -B "$build" \
    -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_C_COMPILER=clang-22 -DCMAKE_CXX_COMPILER=clang++-22 \
    -DLLVM_USE_LINKER=lld \
    -DMLIR_DIR=/usr/lib/llvm-22/lib/cmake/mlir \
    -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DSIM_ENABLE_FUZZERS=ON -DSIM_SANITIZE=ON >/dev/null
}

# Sanitizer reports end the process with a non-zero status; leaks too (the
# tools free what they allocate). The UBSan checks print a stack. Debian's
# MLIR and LLVM libraries are not instrumented, but LLVM's headers poison
# the unused part of an allocator's slab in instrumented code, which the
# libraries' own copies of those functions then touch: allow_user_poisoning=0
# turns off those annotations (and nothing else). lit passes both variables
# to every test.
export ASAN_OPTIONS="allow_user_poisoning=0:detect_leaks=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

case "$command" in
build)
  configure
  cmake --build "$build"
  ;;
check)
  configure
  cmake --build "$build"
  cmake --build "$build" --target check-sim -- "$@"
  ;;
fuzz)
  seconds=${1:-600}
  shift || true
  targets=("$@")
  ((${#targets[@]})) || targets=(bundle checkpoint compile)
  configure
  cmake --build "$build" --target sim-bundle-fuzzer sim-checkpoint-fuzzer \
    sim-checkpoint-fuzz-replay sim-compile-fuzzer sim-translate
  out="$build/fuzz"
  for target in "${targets[@]}"; do
    rm -rf "${out:?}/$target"
    mkdir -p "$out/$target/seeds" "$out/$target/new"
  done
  # Seeds: the kept corpora, and every example scene as a compiler input
  # under each strategy and path, and as bundles (the payload mode: the
  # fuzzer writes the header and CRC itself).
  mkdir -p "$out/bundle/seeds" "$out/checkpoint/seeds" "$out/compile/seeds"
  cp runtime/fuzz/corpus/bundle/* "$out/bundle/seeds/" 2>/dev/null || true
  cp runtime/fuzz/corpus/checkpoint/* "$out/checkpoint/seeds/" 2>/dev/null ||
    true
  # A good checkpoint of each of the target's sessions, in this build.
  SIM_CHECKPOINT_FUZZ_SEEDS="$out/checkpoint/seeds" \
    "$build/bin/sim-checkpoint-fuzz-replay" /dev/null >/dev/null
  cp test/Fuzz/corpus-compile/* "$out/compile/seeds/" 2>/dev/null || true
  for scene in examples/paper/*.mlir examples/physics/*.mlir \
    test/Integration/Inputs/*.mlir; do
    name=$(basename "$scene" .mlir)
    for mode in 0 5 10 131; do
      { printf "\\$(printf '%03o' "$mode")"; cat "$scene"; } \
        >"$out/compile/seeds/$name-$mode"
    done
    if "$build/bin/sim-translate" "$scene" --sim-to-bundle \
      --sim-strategies=simple,hip -o "$out/$name.simb" 2>/dev/null; then
      { printf '\001'; tail -c +33 "$out/$name.simb"; } \
        >"$out/bundle/seeds/$name-payload"
      { printf '\000'; cat "$out/$name.simb"; } \
        >"$out/bundle/seeds/$name-file"
    fi
  done
  status=0
  for target in "${targets[@]}"; do
    echo "fuzz: sim-$target-fuzzer for $seconds s"
    (cd "$out/$target" &&
      "$root/$build/bin/sim-$target-fuzzer" new seeds \
        -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 \
        -max_len=400000 -print_final_stats=1 \
        -artifact_prefix="$root/$out/$target/" 2>&1 |
      tee "$root/$out/$target.log" | grep -E "^#[0-9]+.*(NEW|REDUCE|DONE)|ERROR|SUMMARY|stat::" |
      tail -20) || status=1
    if ls "$out/$target"/crash-* "$out/$target"/timeout-* \
      "$out/$target"/oom-* >/dev/null 2>&1; then
      echo "fuzz: sim-$target-fuzzer found inputs that fail:" \
        "$out/$target/{crash,timeout,oom}-*"
      status=1
    fi
  done
  exit $status
  ;;
mutate)
  seconds=${1:-600}
  shift || true
  configure
  cmake --build "$build" --target sim-translate sim-run
  rm -rf "$build/mutate"
  # Leaks are not what this looks for, and an error exit of a refused
  # scene must stay a clean error.
  ASAN_OPTIONS="allow_user_poisoning=0:detect_leaks=0" \
    python3 utils/mutate-scenes.py --budget "$seconds" --seeds 1-1000000 \
    --sim-translate "$build/bin/sim-translate" --sim-run "$build/bin/sim-run" \
    --timeout 600 --keep "$build/mutate" "$@"
  ;;
*)
  echo "sanitize.sh: unknown command '$command' (see --help)" >&2
  exit 2
  ;;
esac
