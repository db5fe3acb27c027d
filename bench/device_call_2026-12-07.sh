#!/usr/bin/env bash
# One device call of 2026-12-07: on an H200 the 10^8 pile's frames in windows (peak GPU
# memory), else a part of the GPU suite under memcheck (the tests named in FILTER_FILE, or
# all `Gpu*`).
out="${1:?OUT}"
source "$(dirname "$0")/../scripts/device_env.sh" >/dev/null
mib=$(nvidia-smi --query-gpu=memory.total --format=csv,noheader,nounits | head -1)
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader
if [ "${mib:-0}" -gt 120000 ] && [ "${SKIP_WINDOW:-0}" = 0 ]; then
  ROUNDS=1 BUILDS=windows CHECKS=0 bench/run_contact_window_on_device.sh "$out/w" 1e8
else
  # The slow validation suites (5-30 s each without the sanitizer) apart: their kernels are
  # the fast tests' kernels over more steps.
  filter="Gpu*-$slow_gpu_tests"; [ -n "${FILTER_FILE:-}" ] && filter="$(cat "$FILTER_FILE")"
  TOOLS=memcheck SHARDS="${SHARDS:-2}" LIMIT="${LIMIT:-470}" bench/gpu_sanitize.sh "$out/s" "$filter"
fi
# Written beside, then moved in: a tarball inside the folder it archives changes as tar reads.
tar czf "/tmp/all.$$.tgz" -C "$out" . && mv "/tmp/all.$$.tgz" "$out/all.tgz"
