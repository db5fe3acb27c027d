#!/usr/bin/env bash
# The whole GPU suite of one carried test binary over several device calls: in one process
# it outlasts a call (over 500 s on an H100), and gtest shards run side by side on the one
# GPU do not help (tried 2026-12-05: six shards time-slice the GPU, and the latency-bound
# tests ran some 8x slower, Gpu/PrecisionTest.RestingContactFarFromOriginSettles 225 s).
# The first call (no LIST) runs the state hashes, then every test of $gpu_tests in one
# process for at most SECONDS; the tests it did not finish go to OUT/not_run.list, which
# the next call takes as LIST (copy it into the tree, which the device receives). Repeat
# until not_run.list is empty. The log goes to OUT; its summary to stdout; exit 1 on a
# failure (a test left unfinished by the time limit is not one: it is in not_run.list).
#   bench/run_gpu_suite_in_parts.sh OUT [SECONDS=520] [BINARY=tridem_tests] [LIST]
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"; seconds="${2:-520}"; name="${3:-tridem_tests}"
list="${4:-}"
mkdir -p "$out"
bin="$root/.devbin/tests/$name"
status=0
if [ -z "$list" ]; then
  check_state_hashes "$out"
  grep -q '^\[  PASSED' "$out/state_hash.log" || status=1
  "$bin" --gtest_list_tests --gtest_filter="$gpu_tests" |
    awk '/^[^ ]/{s=$1} /^  /{print s $1}' >"$out/all.list"
  list="$out/all.list"
fi
rc=0
timeout "$seconds" stdbuf -oL "$bin" --gtest_filter="$(paste -sd: "$list")" >"$out/part.log" 2>&1 || rc=$?
echo "== $name: exit $rc$([ "$rc" = 124 ] && echo ', the time limit')"
# A crash (not the time limit) fails the part, though its test is left in not_run.list.
[ "$rc" = 0 ] || [ "$rc" = 124 ] || [ "$rc" = 1 ] || status=1
grep -E '^\[       OK' "$out/part.log" | awk '{print $4}' | sort >"$out/ok.list"
grep -E '^\[  FAILED  \] ' "$out/part.log" | awk '{print $4}' | sort -u >"$out/failed.list"
[ -s "$out/failed.list" ] && status=1
sort "$list" | comm -23 - "$out/ok.list" | comm -23 - "$out/failed.list" >"$out/not_run.list"
echo "passed $(wc -l <"$out/ok.list"), not run $(wc -l <"$out/not_run.list")"
gtest_summary "$out/part.log"
exit $status
