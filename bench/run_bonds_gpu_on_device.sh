#!/usr/bin/env bash
# Issue 14's GPU part on the GPU machine, from a bundle built here (scripts/device_bundle.sh,
# carried as .devbin): the gpu-labelled tests of cohesive bonds (parity of a loaded bonded
# disc against the serial solver on every CUDA method and precision, restart bit-identity)
# and the body-less paths they must leave unchanged, then the benchmark of N triangles
# bonded to their neighbours (bonded_pile) against N free ones (dense_pile) on cuda and
# cuda-float, with tri_steps_per_s of each and the bonded/free ratio (issue 14 asks >= 0.5
# at 10^6). Logs go to OUT.
#   bench/run_bonds_gpu_on_device.sh OUT [N] [TEST_SECONDS]      (N default 1e6)
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$1"; n="${2:-1e6}"; limit="${3:-300}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv | tee "$out/gpu.txt"
filter='Gpu/GpuBondParity.*:GpuBondParityAllPairs.*:Gpu/BondRestart.*:GpuRestart.*:GpuParity.*:Bonds.*'
timeout "$limit" stdbuf -oL "$root/.devbin/tests/tridem_tests" --gtest_filter="$filter" \
  2>&1 | tee "$out/tests.log" | grep -E '^\[  (FAILED|PASSED) |tests ran'
timeout 300 "$root/.devbin/bench/tridem_bench" --backends=cuda,cuda-float \
  --scenes=dense_pile,bonded_pile --min_n="$n" --max_n="$n" --benchmark_repetitions=3 \
  --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/bench.json" --benchmark_out_format=json >"$out/bench.txt" 2>&1
# tri_steps_per_s of each case (the median of the repetitions), and bonded / free.
python3 - "$out/bench.json" <<'PY' | tee "$out/rates.txt"
import json, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
rate = {}
for r in runs:
    if r.get("aggregate_name") == "median" and "tri_steps_per_s" in r:
        rate[r["run_name"]] = r["tri_steps_per_s"]
        print(f'{r["run_name"]}: tri_steps_per_s {r["tri_steps_per_s"]:.4g}, bonds {r.get("bonds", 0):.0f}')
for name, value in rate.items():
    if name.startswith("bonded_pile/"):
        free = rate.get(name.replace("bonded_pile/", "dense_pile/", 1))
        if free:
            print(f"{name}: bonded / free = {value / free:.3f}")
PY
