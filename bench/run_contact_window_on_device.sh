#!/usr/bin/env bash
# A frame's contact network compacted and downloaded a window of rows at a time
# (SolverConfig::gpu_contact_rows_per_copy, backends/cuda/touching_pairs.cuh), on the GPU
# machine from a bundle (scripts/device_bundle.sh, carried as .devbin):
#  1. the peak GPU memory of tridem_bench's frame_with_contacts case at N (dense_pile, mixed
#     precision: three snapshots with the contact network after the warm-up steps),
#     nvidia-smi every 10 ms (at 100 ms it missed the scratch's ~0.1 s at 10^7), with all
#     the contacts in one piece, as before windows (--contact_rows_per_copy=2e9), and in the
#     default windows, in alternating order; and the seconds a frame takes either way;
#  2. its tests, the contact copy's and the state hashes (tridem_tests);
#  3. compute-sanitizer's memcheck (with leak check) on the window test and the state hashes.
#   bench/run_contact_window_on_device.sh OUT [N]    env: ROUNDS (2); BUILDS ("whole windows":
#   either alone, e.g. windows at 10^8, whose whole buffer table_2026-12-06 measured); CHECKS=0 leaves out 2
#   and 3 (at 10^8 the measurement alone fills most of a device call)
# N (a power of ten: the benchmark's sizes) defaults to 10^8 on a GPU of over 120 GB (an
# H200: the issue's measurement), else 10^7.
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
mkdir -p "$out"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$out/gpu.txt"
mib=$(nvidia-smi --query-gpu=memory.total --format=csv,noheader,nounits | head -1)
n="${2:-$([ "${mib:-0}" -gt 120000 ] && echo 1e8 || echo 1e7)}"
echo "== N = $n"
# A run at 10^8 took 91 s without frames (table_2026-12-06); three frames add some 20 s each.
limit=$([ "$n" = 1e8 ] && echo 280 || echo 200)
tests="$root/.devbin/tests/tridem_tests"
export GPU_WATCH_MS=10
for round in $(seq "${ROUNDS:-2}"); do
  for build in ${BUILDS:-whole windows}; do
    rows=(); [ "$build" = whole ] && rows=(--contact_rows_per_copy=2e9)
    gpu_watch_start "$out/gpu_mem_${build}_$round"
    timeout "$limit" "$root/.devbin/bench/tridem_bench" --backends=cuda-float --min_n="$n" \
      --max_n="$n" --frames=1 "${rows[@]}" --benchmark_filter=frame_with_contacts \
      >"$out/bench_${build}_$round.txt" 2>&1
    echo "== round $round, $build: exit $?"
    gpu_watch_peak "$out/gpu_mem_${build}_$round" | tee "$out/peak_${build}_$round.txt"
    grep -oE 's_per_frame=[0-9.]+s|contacts=[0-9.]+M|rror.*' "$out/bench_${build}_$round.txt" | head -3
  done
done
[ "${CHECKS:-1}" = 0 ] && exit 0
check_state_hashes "$out"
filter='GpuContactWindows.*:*ContactCopy*:GpuMemory.*'
timeout 200 "$tests" --gtest_filter="$filter" >"$out/tests.log" 2>&1
echo "== window and copy tests: exit $?"; gtest_summary "$out/tests.log"
timeout 180 compute-sanitizer --tool memcheck --leak-check full --error-exitcode 1 \
  "$tests" --gtest_filter="GpuContactWindows.*:Gpu/StateHash.*" --gtest_brief=1 \
  >"$out/memcheck.log" 2>&1
echo "== memcheck: exit $?"; tail -n 4 "$out/memcheck.log"
