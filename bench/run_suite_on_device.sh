#!/usr/bin/env bash
# On the GPU machine, from a bundle built here (scripts/device_bundle.sh, carried as
# .devbin): the CUDA state hashes twice (Gpu/StateHash prints each; two runs show they are
# reproducible), then every other GPU test in one process, each under its own time limit.
# Logs go to OUT; the summary lines to stdout.
#   bench/run_suite_on_device.sh OUT [SUITE_SECONDS]      (default 330)
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"; limit="${2:-330}"
mkdir -p "$out"
bin="$root/.devbin/tests/tridem_tests"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv | tee "$out/gpu.txt"
timeout 150 stdbuf -oL "$bin" --gtest_filter='Gpu/StateHash.*' --gtest_repeat=2 >"$out/state_hash.log" 2>&1
echo "== state hashes: exit $?"
grep -iE 'hash|FAILED' "$out/state_hash.log" | sort | uniq -c | head -40
start=$(date +%s)
timeout "$limit" stdbuf -oL "$bin" --gtest_filter="$gpu_tests" >"$out/tests.log" 2>&1
echo "== suite: exit $? after $(( $(date +%s) - start )) s"
grep -E '^\[  (PASSED|FAILED|SKIPPED) |tests? from .* ran|FAILED TEST' "$out/tests.log" | sort -u | head -60
