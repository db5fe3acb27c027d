#!/usr/bin/env bash
# One device call for a speed lever: the A/B benchmark of the carried builds
# (bench/compare_builds.sh) and the GPU tests of each carried test binary
# (.devbin/tests/tridem_tests*), whose results must hold before a lever is kept.
#   bench/run_lever_check_on_device.sh OUTDIR NAME...   env: GTEST_FILTER (default: *Gpu*)
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
shift
mkdir -p "$out"
status=0
"$root/bench/compare_builds.sh" "$out/ab" "$@" || status=1
specs=()
for t in "$root"/.devbin/tests/tridem_tests*; do specs+=("$(basename "$t")=${GTEST_FILTER:-*Gpu*}=240"); done
"$root/bench/run_gpu_tests_on_device.sh" "$out/tests" "${specs[@]}" || status=1
exit $status
