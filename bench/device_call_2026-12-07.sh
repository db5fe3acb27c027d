#!/usr/bin/env bash
# One device call of 2026-12-07 (and what issue 12 still has to measure on the device):
# with LEAN_RUN=1, `tridem run` of the 10^6 float pile against the benchmark with the lean
# frames of `[output] frame_arrays` and `contact_arrays` (docs/performance.md, "Output
# frames" item 12: their bytes at 10^6 and the run's rate with them); else on an H200 the
# 10^8 pile's frames in windows (peak GPU memory); else a part of the GPU suite under
# memcheck (the tests named in FILTER_FILE, or all `Gpu*` but the slow suites; the 23 not
# yet run are bench/results/memcheck_gpu_suite_2026-12-07_*_part2/s/memcheck_not_run.list).
out="${1:?OUT}"
source "$(dirname "$0")/../scripts/device_env.sh" >/dev/null
mib=$(nvidia-smi --query-gpu=memory.total --format=csv,noheader,nounits | head -1)
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader
if [ "${LEAN_RUN:-0}" = 1 ]; then
  OUTPUT_KEYS='contacts_csv = false
vtk_encoding = "appended"
frame_arrays = ["velocity", "angular_velocity"]
contact_arrays = ["force"]' VARIANTS=cuda-float EVERY=1000 \
    bench/run_cli_vs_bench_on_device.sh "$out/lean" 1000000 "${STEPS:-10000}"
elif [ "${mib:-0}" -gt 120000 ] && [ "${SKIP_WINDOW:-0}" = 0 ]; then
  ROUNDS=1 BUILDS=windows CHECKS=0 bench/run_contact_window_on_device.sh "$out/w" 1e8
else
  # The slow validation suites (5-30 s each without the sanitizer) apart: their kernels are
  # the fast tests' kernels over more steps.
  filter="Gpu*-$slow_gpu_tests"; [ -n "${FILTER_FILE:-}" ] && filter="$(cat "$FILTER_FILE")"
  TOOLS=memcheck SHARDS="${SHARDS:-2}" LIMIT="${LIMIT:-470}" bench/gpu_sanitize.sh "$out/s" "$filter"
fi
# Written beside, then moved in: a tarball inside the folder it archives changes as tar reads.
tar czf "/tmp/all.$$.tgz" -C "$out" . && mv "/tmp/all.$$.tgz" "$out/all.tgz"
