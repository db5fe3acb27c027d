#!/usr/bin/env bash
# Run-ahead (CudaSolver::advance_ahead, docs/performance.md "Run-ahead") on the GPU machine,
# from a bundle (scripts/device_bundle.sh, carried as .devbin), in one call:
#  1. the CUDA state hashes (run-ahead must not change a bit) and the run-ahead tests;
#  2. tridem_bench on the dense pile at 10^3 to 10^6 (MAX_N), cuda and cuda-float, with and
#     without run-ahead (--run_ahead=0), ROUNDS alternating rounds (default 3), so that the
#     ratio is measured in one run on one machine; both with the stage clock off
#     (--stage_timing=0: it runs its sampled steps staged) and, last round, on.
# Logs and JSON go to OUT; the table of medians over the rounds, each build's s/step and
# run-ahead's speed-up, to stdout and OUT/table.md (bench/compare_builds_table.py).
#   bench/run_run_ahead_on_device.sh OUT
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
mkdir -p "$out"
tests="$root/.devbin/tests/tridem_tests"
bench="$root/.devbin/bench/tridem_bench"
check_state_hashes "$out"
timeout 120 "$tests" --gtest_filter='*RunAhead*:GpuBlowUp.*:GpuStageTimes.*' >"$out/run_ahead_tests.log" 2>&1
echo "== run-ahead tests: exit $?"; gtest_summary "$out/run_ahead_tests.log"
for round in $(seq 1 "${ROUNDS:-3}"); do
  for ahead in 1 0; do
    name="ahead${ahead}_$round"
    timeout 120 "$bench" --backends=cuda,cuda-float --min_n=1e3 --max_n="${MAX_N:-1e6}" \
      --run_ahead="$ahead" --stage_timing=0 --benchmark_repetitions=1 \
      --benchmark_out="$out/$name.json" --benchmark_out_format=json >"$out/$name.txt" 2>&1
    echo "round $round, run_ahead=$ahead: exit $?"
  done
done
timeout 120 "$bench" --backends=cuda,cuda-float --min_n=1e3 --max_n=1e5 --run_ahead=1 \
  --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/timed_ahead1.json" --benchmark_out_format=json >"$out/timed_ahead1.txt" 2>&1
echo "run_ahead=1 with the stage clock: exit $?"
python3 "$root/bench/compare_builds_table.py" "$out" ahead0 ahead1 | tee "$out/table.md"
