#!/usr/bin/env bash
# On the GPU machine, from a bundle (.devbin): the `gpu` tests under compute-sanitizer's
# memcheck (with leak check) and racecheck. Logs go to OUTDIR; exit 1 if either reports.
#   bench/gpu_sanitize.sh OUTDIR [GTEST_FILTER]      (default filter: Gpu*)
# env: TOOLS (default "memcheck racecheck"); LIMIT, seconds a tool may run (default none):
# a tool cut off by it has checked the tests its log marks OK, and any error it met is in
# its log, but it gives no summary (the exit says "cut off"; the tests it did not reach are
# in OUTDIR/TOOL_not_run.list); SHARDS, how many sanitizer processes share the GPU at once
# (default 1), each running its part of the tests (gtest's sharding): the instrumented
# kernels leave most of the GPU and the host's cores idle, so parts finish in about the time
# of the longest.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?give an output folder}"
filter="${2:-Gpu*}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ ! -e /work/main/tests ]; then mkdir -p /work && ln -sfn "$root" /work/main; fi
tests="$root/.devbin/tests/tridem_tests"
"$tests" --gtest_list_tests --gtest_filter="$filter" |
  awk '/^[^ ]/{s=$1} /^  /{print s $1}' | sort >"$out/all.list"
status=0
for tool in ${TOOLS:-memcheck racecheck}; do
  options=(--tool "$tool" --error-exitcode 1)
  [ "$tool" = memcheck ] && options+=(--leak-check full)
  limit=(); [ -n "${LIMIT:-}" ] && limit=(timeout "$LIMIT")
  shards=${SHARDS:-1}
  pids=()
  for ((i = 0; i < shards; i++)); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i "${limit[@]}" compute-sanitizer \
      "${options[@]}" "$tests" --gtest_filter="$filter" >"$out/$tool.$i.log" 2>&1 &
    pids+=($!)
  done
  # The worst exit of the parts: an error (1 or other) over a cut-off (124) over success.
  rc=0
  for pid in "${pids[@]}"; do
    wait "$pid"; part=$?
    if [ "$part" != 0 ] && { [ "$rc" = 0 ] || [ "$rc" = 124 ]; }; then rc=$part; fi
  done
  for ((i = 0; i < shards; i++)); do cat "$out/$tool.$i.log"; done >"$out/$tool.log"
  rm -f "$out/$tool".[0-9]*.log
  grep -E '^\[       OK' "$out/$tool.log" | awk '{print $4}' | sort >"$out/${tool}_ok.list"
  comm -23 "$out/all.list" "$out/${tool}_ok.list" >"$out/${tool}_not_run.list"
  errors=$(grep -cE '^========= (Invalid|Race|Leaked|Program hit|Error)' "$out/$tool.log")
  if [ "$rc" = 124 ]; then
    echo "$tool: cut off after ${LIMIT} s" >>"$out/$tool.log"
  else
    echo "$tool rc=$rc" >>"$out/$tool.log"
  fi
  echo "== $tool: exit $rc$([ "$rc" = 124 ] && echo ' (cut off)'), tests OK $(wc -l <"$out/${tool}_ok.list") of $(wc -l <"$out/all.list"), error lines $errors"
  { [ "$rc" = 0 ] || [ "$rc" = 124 ]; } && [ "$errors" = 0 ] || status=1
  tail -n 3 "$out/$tool.log"
done
exit $status
