#!/usr/bin/env bash
# The GPU benchmark of issue 3, on the GPU machine from a bundle built here
# (scripts/device_bundle.sh, carried as .devbin): serial and OpenMP (all cores) and the CUDA
# solver in double and float on dense_pile(n), n = 10^3 .. 10^7, in one run, plus the
# cost of one output frame. Writes JSON, logs and the Markdown table into OUTDIR.
#   bench/run_gpu_bench.sh OUTDIR     env: MAX_N (1e7), CPU_REPS (3), GPU_REPS (5)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?give an output folder}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
bench="$root/.devbin/bench/tridem_bench"
max_n="${MAX_N:-1e7}"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.max.mem --format=csv >"$out/gpu.txt"
# CPU solvers: one repetition at 10^6 and above (a serial step of 10^7 takes ~30 s).
"$bench" --backends=cpu,openmp --max_n="$max_n" --benchmark_repetitions="${CPU_REPS:-3}" \
  --large_reps=1 --benchmark_out="$out/cpu.json" --benchmark_out_format=json >"$out/cpu.txt" 2>&1
"$bench" --backends=cuda,cuda-float --max_n="$max_n" --frames=1 \
  --benchmark_repetitions="${GPU_REPS:-5}" --benchmark_out="$out/gpu.json" \
  --benchmark_out_format=json >"$out/gpu_run.txt" 2>&1
python3 "$root/bench/gpu_bench_table.py" "$out/cpu.json" "$out/gpu.json" | tee "$out/table.md"
