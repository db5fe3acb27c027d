#!/usr/bin/env bash
# On the GPU machine: Nsight Compute on the pair-force kernel of the benchmark's dense pile
# (one launch each in double and in mixed precision, after the warm-up's launches), with
# the sections that say what holds it: throughput against the floors, the warps' stall
# reasons, occupancy, memory and the instruction mix. What to try next comes from here.
#   bench/profile_pair_kernel_on_device.sh OUTDIR [BENCH_BINARY] [N]   (default tridem_bench, 1e6)
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
bin="$root/.devbin/bench/${2:-tridem_bench}"
n="${3:-1e6}"
mkdir -p "$out"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv >"$out/gpu.txt"
ncu_bin=$(command -v ncu || ls /usr/local/cuda*/bin/ncu 2>/dev/null | head -1)
if [ -z "$ncu_bin" ]; then echo "no ncu on this machine"; exit 1; fi
"$ncu_bin" --version | tail -1
status=0
for backend in cuda cuda-float; do
  # One profiled launch into a report, then its summary and its SASS page from the report.
  "$ncu_bin" --kernel-name regex:pair_forces_kernel --launch-skip 20 --launch-count 1 \
    --section SpeedOfLight --section WarpStateStats --section SchedulerStats \
    --section Occupancy --section MemoryWorkloadAnalysis --section ComputeWorkloadAnalysis \
    --section InstructionStats --section LaunchStats --section SourceCounters \
    -f -o "$out/sass_$backend" \
    "$bin" --backends="$backend" --min_n="$n" --max_n="$n" --scenes=dense_pile \
    --benchmark_repetitions=1 >"$out/ncu_run_$backend.txt" 2>&1 || status=1
  "$ncu_bin" -i "$out/sass_$backend.ncu-rep" --page details >"$out/ncu_$backend.txt" 2>&1 || status=1
  grep -E "Duration|Registers Per|Achieved Occupancy|Compute \(SM\) Throughput|Memory Throughput|Warp Cycles Per Issued|Stall|Issue Slots|Executed Ipc|Local|Spill|Theoretical Occ|Block Limit" \
    "$out/ncu_$backend.txt" | head -60
  # Per SASS instruction: executions and stall samples, summed by opcode (what the
  # instructions are, beyond the pipes' totals).
  "$ncu_bin" -i "$out/sass_$backend.ncu-rep" --page source --print-source sass --csv \
    >"$out/sass_$backend.csv" 2>&1 || status=1
  python3 "$root/bench/sass_opcode_table.py" "$out/sass_$backend.csv" | tee "$out/opcodes_$backend.txt" | head -40
done
exit $status
