#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) in build-fuzz/ and runs each for
# a bounded time from its seed corpus in tests/fuzz/corpus/. New inputs go to
# build-fuzz/corpus/ (not the repository); a crash leaves its input in build-fuzz/artifacts/
# and fails the script: turn it into a regression test, and add it to the seed corpus.
# usage: scripts/run-fuzzers.sh [SECONDS_PER_TARGET (default 60)]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
cxx=${TRIDEM_FUZZ_CXX:-clang++-14}
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
  -DTRIDEM_BUILD_FUZZERS=ON -DTRIDEM_BUILD_TESTS=OFF -DTRIDEM_BUILD_BENCH=OFF \
  -DTRIDEM_ENABLE_CUDA=OFF -DTRIDEM_WITH_MPI=OFF >/dev/null
cmake --build build-fuzz --target scene_reader_fuzz checkpoint_reader_fuzz
mkdir -p build-fuzz/artifacts
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=detect_leaks=1:${ASAN_OPTIONS:-}
# The targets run side by side: each fuzzer is one process on one core, so on CI's two
# cores both get their whole time in the wall time of one.
fuzz() {
  local target=$1 corpus=build-fuzz/corpus/$1
  mkdir -p "$corpus"
  echo "fuzzing $target for $seconds s"
  # -timeout: an input taking over 10 s counts as a hang; -rss_limit_mb: as a memory blow-up.
  build-fuzz/tests/fuzz/${target}_fuzz "$corpus" "tests/fuzz/corpus/$target" \
    -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix=build-fuzz/artifacts/${target}- -print_final_stats=1 2>build-fuzz/$target.log
}
targets=(scene_reader checkpoint_reader)
pids=()
for target in "${targets[@]}"; do
  fuzz "$target" &
  pids+=($!)
done
failed=0
for i in "${!targets[@]}"; do
  target=${targets[$i]}
  if ! wait "${pids[$i]}"; then
    tail -60 "build-fuzz/$target.log"
    echo "FAIL: $target fuzzer found a problem"
    failed=1
  fi
  grep -E "^stat::number_of_executed_units|^stat::new_units_added" "build-fuzz/$target.log" || true
done
[ "$failed" = 0 ] || exit 1
echo "fuzzers: no crash, hang or leak in ${seconds} s each"
