#!/usr/bin/env bash
# Runs the CPU benchmark on the lent GPU machine (16 cores) from a binary built here:
# the machine has no package registry, so the binary and the libraries it needs travel in
# .devbin/ (bench/ stays as it is). Writes the results into $OUT (or the first argument).
#   .devbin/bench/tridem_bench   cp build-bench/bench/tridem_bench
#   .devbin/lib/                 libbenchmark, libfmt, libgomp from this machine
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-${OUT:?give an output folder}}"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
gpu="$(nvidia-smi --query-gpu=name --format=csv,noheader 2>/dev/null | head -1 || true)"
NO_BUILD=1 BUILD_DIR="$root/.devbin" NOTES="${NOTES:-}${gpu:+Run on the GPU machine ($gpu); CPU solvers only.}" \
  "$root/bench/run_cpu_bench.sh" "$out"
