#!/usr/bin/env bash
# Issue 12's table row at 10^8 triangles (dense_pile, the benchmark's scene), on the GPU
# machine from a bundle (scripts/device_bundle.sh, carried as .devbin): tridem_bench at
# --min_n=--max_n=N for each of BACKENDS (default cuda-float: at 10^8 the double pairs
# and the CPU solvers' arrays do not fit, `tridem info` on the pile says how much each
# needs), with the command's peak host memory and the peak GPU memory
# (gpu_watch_*: nvidia-smi every 100 ms, less what was in use before). Logs go to OUT.
#   bench/run_largest_on_device.sh OUT [N=1e8]     env: BACKENDS, REPS (default 1)
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"; n="${2:-1e8}"
mkdir -p "$out"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$out/gpu.txt"
for backend in ${BACKENDS:-cuda-float}; do
  gpu_watch_start "$out/gpu_mem_$backend"
  # The child's peak resident memory and wall time, without relying on GNU time.
  python3 - "$root/.devbin/bench/tridem_bench" --backends="$backend" --min_n="$n" --max_n="$n" \
    --benchmark_repetitions="${REPS:-1}" --benchmark_out="$out/$backend.json" \
    --benchmark_out_format=json >"$out/$backend.txt" 2>"$out/$backend.time" <<'PY'
import resource, subprocess, sys, time
t0 = time.time()
rc = subprocess.call(sys.argv[1:])
peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
print(f"exit {rc}, wall {time.time() - t0:.1f} s, peak host memory {peak / 2**20:.2f} GiB", file=sys.stderr)
sys.exit(rc)
PY
  echo "$backend: exit $?"
  gpu_watch_peak "$out/gpu_mem_$backend"
  grep -E 'n:|rror' "$out/$backend.txt" | head -6
  tail -3 "$out/$backend.time"
done
