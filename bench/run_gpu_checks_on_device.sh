#!/usr/bin/env bash
# A session's GPU checks in one device call, from a bundle (scripts/device_bundle.sh,
# carried as .devbin), each part under its own time limit so that one slow part cannot
# take the others' time; logs go to OUT, summaries to stdout:
#  1. the CUDA state hashes (Gpu/StateHash: the non-periodic GPU arithmetic, bit for bit);
#  2. the GPU tests but the slow validation suites (Incline, PrecisionTest, StepStability,
#     Friction, MotionTest, MotionProgramTest, Resting: 5-30 s each), whose GPU arithmetic
#     the hashes pin: run them with FULL=1 when the kernels change what the hashes miss;
#  3. tridem run against the benchmark at 10^6 (bench/run_cli_vs_bench_on_device.sh, float);
#  4. OpenMP at 10^6 on the host's cores, the runtime's wait policy and passive;
#  5. the live view's frame rates and stepping overhead (bench/live/run_live_bench.sh).
#   bench/run_gpu_checks_on_device.sh OUT      env: FULL=1, SKIP="3 4 5" (parts to leave out)
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
mkdir -p "$out"
bin="$root/.devbin/tests/tridem_tests"
skip=" ${SKIP:-} "
echo "== 1"
check_state_hashes "$out"
filter="$gpu_tests"
[ "${FULL:-0}" = 1 ] || filter="$filter:$slow_gpu_tests"
start=$(date +%s)
timeout "${TEST_SECONDS:-200}" stdbuf -oL "$bin" --gtest_filter="$filter" >"$out/tests.log" 2>&1
echo "== 2 GPU tests: exit $? after $(( $(date +%s) - start )) s"; gtest_summary "$out/tests.log"
# A diagnostic a session may have compiled in (DISABLED_ tests of GpuServoDiag), if any.
timeout 60 "$bin" --gtest_filter='GpuServoDiag.*' --gtest_also_run_disabled_tests >"$out/diag.log" 2>&1
grep -E '^follow|FAILED|PASSED' "$out/diag.log" | head -40
if [[ $skip != *" 3 "* ]]; then
  echo "== 3 tridem run against the benchmark"
  VARIANTS="${VARIANTS:-cuda-float}" timeout "${CLI_SECONDS:-150}" \
    "$root/bench/run_cli_vs_bench_on_device.sh" "$out/cli_vs_bench" 1000000 3000 2>&1 | tail -25
fi
if [[ $skip != *" 4 "* ]]; then
  echo "== 4 OpenMP at 10^6 on $(nproc) cores"
  for policy in default passive; do
    ( [ $policy = passive ] && export OMP_WAIT_POLICY=passive
      timeout 60 "$root/.devbin/bench/tridem_bench" --backends=openmp --min_n=1e6 --max_n=1e6 \
        --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
        --benchmark_out="$out/openmp_$policy.json" --benchmark_out_format=json \
        >"$out/openmp_$policy.txt" 2>&1 )
    echo "wait policy $policy: exit $?"; grep -E 'median' "$out/openmp_$policy.txt" | head -4
  done
fi
if [[ $skip != *" 5 "* ]]; then
  echo "== 5 live view"
  COST="$root/.devbin/bench/tridem_live_frame_cost" OUT="$out/live.md" WORK="$out/live_work" \
    timeout "${LIVE_SECONDS:-150}" "$root/bench/live/run_live_bench.sh" "$root/.devbin" 2>&1 |
    tail -30
fi
