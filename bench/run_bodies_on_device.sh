#!/usr/bin/env bash
# Issue 13 on the GPU machine, from a bundle built here (scripts/device_bundle.sh, carried as
# .devbin): the GPU tests of bodies and of the body-less paths they must leave unchanged,
# then the benchmark of 10^6 triangles in 10^5 bodies (body_pile) against 10^6 free
# triangles (dense_pile), double and mixed float, one run. Logs go to OUTDIR.
#   bench/run_bodies_on_device.sh OUTDIR [TEST_SECONDS]
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$1"; limit="${2:-300}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv | tee "$out/gpu.txt"
filter='Gpu/GpuBodyParity.*:GpuBodyParityAllPairs.*:Gpu/BodyRestart.*:Gpu/StateHash.*:GpuRestart.*:GpuParity.*:Gpu/SolverStateLoad.*'
timeout "$limit" stdbuf -oL "$root/.devbin/tests/tridem_tests" --gtest_filter="$filter" \
  2>&1 | tee "$out/tests.log" | grep -E '^\[  (FAILED|PASSED) |tests ran'
timeout 240 "$root/.devbin/bench/tridem_bench" --backends=cuda,cuda-float \
  --scenes=dense_pile,body_pile --min_n=1e6 --max_n=1e6 --benchmark_repetitions=5 \
  --benchmark_out="$out/bench.json" --benchmark_out_format=json 2>&1 | tee "$out/bench.txt" |
  grep -E 'median|^dense|^body' | head -20
