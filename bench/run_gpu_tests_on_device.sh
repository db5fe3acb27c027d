#!/usr/bin/env bash
# The GPU tests of each carried test binary (.devbin/tests/tridem_tests*), each under its own
# filter and time limit; the summary lines of each go to stdout, the logs to OUTDIR.
#   bench/run_gpu_tests_on_device.sh OUTDIR NAME=FILTER=SECONDS...
#   (NAME: tridem_tests or tridem_tests_X; e.g. tridem_tests='*Gpu*'=400)
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
shift
mkdir -p "$out"
status=0
for spec in "$@"; do
  IFS='=' read -r name filter seconds <<<"$spec"
  rc=0
  timeout "$seconds" "$root/.devbin/tests/$name" --gtest_filter="$filter" >"$out/$name.log" 2>&1 || rc=$?
  echo "== $name ($filter): exit $rc$([ "$rc" = 124 ] && echo ', timed out')"
  grep -E "^\[  (PASSED|FAILED|SKIPPED) |tests? from .* ran|FAILED TEST" "$out/$name.log" | sort -u | head -40
  [ "$rc" = 0 ] || status=1
done
exit $status
