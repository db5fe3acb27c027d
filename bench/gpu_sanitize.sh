#!/usr/bin/env bash
# On the GPU machine, from a bundle (.devbin): the `gpu` tests under compute-sanitizer's
# memcheck (with leak check) and racecheck. Logs go to OUTDIR; exit 1 if either reports.
#   bench/gpu_sanitize.sh OUTDIR [GTEST_FILTER]      (default filter: Gpu*)
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?give an output folder}"
filter="${2:-Gpu*}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ ! -e /work/main/tests ]; then mkdir -p /work && ln -sfn "$root" /work/main; fi
tests="$root/.devbin/tests/tridem_tests"
status=0
compute-sanitizer --tool memcheck --leak-check full --error-exitcode 1 \
  "$tests" --gtest_filter="$filter" --gtest_brief=1 >"$out/memcheck.log" 2>&1
rc=$?; echo "memcheck rc=$rc" >>"$out/memcheck.log"; [ $rc = 0 ] || status=1
compute-sanitizer --tool racecheck --error-exitcode 1 \
  "$tests" --gtest_filter="$filter" --gtest_brief=1 >"$out/racecheck.log" 2>&1
rc=$?; echo "racecheck rc=$rc" >>"$out/racecheck.log"; [ $rc = 0 ] || status=1
tail -n 3 "$out/memcheck.log" "$out/racecheck.log"
exit $status
