#!/usr/bin/env bash
# The GPU benchmark of issue 3, on the GPU machine from a bundle built here
# (scripts/device_bundle.sh, carried as .devbin): serial and OpenMP (all cores) and the CUDA
# solver in double and float on dense_pile(n), n = 10^3 .. 10^7, in one run, plus the
# cost of one output frame. Writes JSON, logs and the Markdown table into OUTDIR.
# SERIAL_MAX_N caps the serial solver's sizes (a serial step of 10^7 takes ~40 s); LARGEST
# adds bench/run_largest_on_device.sh's row (e.g. 1e8, mixed precision: it needs an H200)
# to the GPU's, in OUTDIR/largest (gpu.json keeps 10^3..MAX_N, gpu_all.json both).
#   bench/run_gpu_bench.sh OUTDIR     env: MAX_N (1e7), SERIAL_MAX_N (MAX_N), CPU_REPS (3),
#                                          GPU_REPS (5), LARGEST (none)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?give an output folder}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
bench="$root/.devbin/bench/tridem_bench"
max_n="${MAX_N:-1e7}"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.max.mem --format=csv >"$out/gpu.txt"
# CPU solvers: one repetition at 10^6 and above (a serial step of 10^7 takes ~40 s).
for backend in cpu openmp; do
  name=openmp n="$max_n"
  [ "$backend" = cpu ] && name=serial n="${SERIAL_MAX_N:-$max_n}"
  "$bench" --backends="$backend" --max_n="$n" --benchmark_repetitions="${CPU_REPS:-3}" \
    --large_reps=1 --benchmark_out="$out/$name.json" --benchmark_out_format=json \
    >"$out/$name.txt" 2>&1
done
python3 "$root/bench/merge_bench_json.py" "$out/cpu.json" "$out/serial.json" "$out/openmp.json"
"$bench" --backends=cuda,cuda-float --max_n="$max_n" --frames=1 \
  --benchmark_repetitions="${GPU_REPS:-5}" --benchmark_out="$out/gpu.json" \
  --benchmark_out_format=json >"$out/gpu_run.txt" 2>&1
gpu_json="$out/gpu.json"
if [ -n "${LARGEST:-}" ]; then
  BACKENDS=cuda-float "$root/bench/run_largest_on_device.sh" "$out/largest" "$LARGEST" || true
  python3 "$root/bench/merge_bench_json.py" "$out/gpu_all.json" "$out/gpu.json" \
    "$out/largest/cuda-float.json" && gpu_json="$out/gpu_all.json"
fi
python3 "$root/bench/gpu_bench_table.py" "$out/cpu.json" "$gpu_json" | tee "$out/table.md"
