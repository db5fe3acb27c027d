#!/usr/bin/env bash
# One device call for a speed lever: the A/B benchmark of the carried builds
# (bench/compare_builds.sh) and the GPU tests of each carried test binary
# (.devbin/tests/tridem_tests*), whose results must hold before a lever is kept.
#   bench/run_lever_check_on_device.sh OUTDIR NAME...   env: GTEST_FILTER (default: *Gpu*)
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?give an output folder}"
shift
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# The tests read data files through the source path compiled into them.
if [ ! -e /work/main/tests ]; then mkdir -p /work && ln -sfn "$root" /work/main; fi
status=0
"$root/bench/compare_builds.sh" "$out/ab" "$@" || status=1
for t in "$root"/.devbin/tests/tridem_tests*; do
  name=$(basename "$t")
  timeout 240 "$t" --gtest_filter="${GTEST_FILTER:-*Gpu*}" --gtest_brief=1 >"$out/$name.log" 2>&1 || status=1
  tail -n 25 "$out/$name.log"
done
exit $status
