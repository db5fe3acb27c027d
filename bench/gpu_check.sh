#!/usr/bin/env bash
# On the GPU machine, from a bundle built here (scripts/device_bundle.sh, carried as
# .devbin): the whole test suite with the GPU tests, the CLI checks, then a quick GPU
# benchmark. Logs go to OUTDIR (default $OUT).
#   bench/gpu_check.sh [OUTDIR]    env: BENCH_ARGS (extra tridem_bench flags), NO_BENCH=1
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-${OUT:?give an output folder}}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# The tests read data files through the source path compiled into them.
if [ ! -e /work/main/tests ]; then mkdir -p /work && ln -sfn "$root" /work/main; fi
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv | tee "$out/gpu.txt"
status=0
"$root/.devbin/tests/tridem_tests" --gtest_brief=1 2>&1 | tee "$out/tests.log" || status=1
grep -E "^(jostling|all-pairs)" "$out/tests.log" || true
bash "$root/tests/cli/cli_test.sh" "$root/.devbin/app/tridem" "$root" /tmp/cli_work 2>&1 |
  tee "$out/cli.log" || status=1
if [ "${NO_BENCH:-0}" != 1 ]; then
  "$root/.devbin/bench/tridem_bench" --backends=cuda,cuda-float --max_n=1e6 \
    --benchmark_repetitions=3 --benchmark_report_aggregates_only=true ${BENCH_ARGS:-} \
    --benchmark_out="$out/gpu_bench.json" --benchmark_out_format=json 2>&1 |
    tee "$out/gpu_bench.txt" || status=1
fi
exit $status
