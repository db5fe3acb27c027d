#!/usr/bin/env bash
# The float32 contacts CSV (2026-12-06) on the GPU machine, in one device call: the CUDA
# state hashes; the GPU tests of the contact network (its copy beside the steps, which
# carries the float precision's mark); tridem_frame_bench in float at 10^6; and `tridem run`
# of a 10^6 pile in float, 10 000 steps, a frame with its network every 1000, with and
# without the contacts CSV, each against tridem_benchmark in the same call. Logs in OUT.
#   bench/run_float_csv_on_device.sh OUT     env: FRAME_SECONDS, CLI_SECONDS, CLI_RUNS
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
mkdir -p "$out"
check_state_hashes "$out"
timeout 120 "$root/.devbin/tests/tridem_tests" --gtest_filter='Gpu/ContactCopy*:Gpu/*Contact*' \
  >"$out/contact_tests.log" 2>&1
echo "== contact GPU tests: exit $?"
gtest_summary "$out/contact_tests.log"
SKIP="1" FRAME_PRECISION=float FRAME_SECONDS="${FRAME_SECONDS:-100}" CLI_STEPS=10000 \
  CLI_SECONDS="${CLI_SECONDS:-170}" CLI_RUNS="${CLI_RUNS:-cli_float_with_csv cli_float_no_csv}" \
  "$root/bench/run_frames_on_device.sh" "$out/frames"
