#!/usr/bin/env bash
# GPU ranks' split step (docs/scaling.md, "Overlap") in one device call: the GPU state
# hashes and GPU tests (the pair kernel's slot filter touches every GPU path:
# run_gpu_checks_on_device.sh parts 1-2), the GPU ranks' cases against one GPU rank
# (run_mpi_gpu_on_device.sh, the overlap cases included), and the single-GPU pair kernel's
# speed at 10^6 (tridem_bench, dense pile, double and float). Logs in OUT; a summary in
# OUT/summary.txt.
#   bench/run_gpu_overlap_on_device.sh OUT
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out="${1:?give an output folder}"
mkdir -p "$out"
{
  SKIP="3 4 5" timeout 200 "$here/run_gpu_checks_on_device.sh" "$out/checks"
  timeout 300 "$here/run_mpi_gpu_on_device.sh" "$out/mpi"
  source "$here/../scripts/device_env.sh"
  timeout 60 "$root/.devbin/bench/tridem_bench" --backends=cuda,cuda-float --min_n=1e6 \
    --max_n=1e6 --benchmark_repetitions=3 --benchmark_report_aggregates_only=true 2>&1 |
    grep -E "median" | sed -E 's/ +/ /g' | cut -c1-200
} 2>&1 | tee "$out/summary.txt"
