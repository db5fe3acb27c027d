#!/usr/bin/env bash
# The CPU solvers' kept pair list (CpuSolver::kept_pair_list) on the device machine's host
# cores: tridem_bench's OpenMP cases at 10^6, dense and settled piles, with the list built
# every step (--skin=0) against kept lists of several skins, in one call; then SECOND
# (default "0.05 0") again in the other order. Writes OUT/kept_list.txt (the console tables and
# the machine) and OUT/kept_list_<skin>_<pass>.json.
#   bench/run_kept_list_on_device.sh OUT [SKINS (default "0 0.05 0.1")]
set -euo pipefail
out=${1:?usage: run_kept_list_on_device.sh OUT [SKINS]}
skins=${2:-0 0.05 0.1}
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../scripts/device_env.sh"
bench="$root/.devbin/bench/tridem_bench"
export OMP_WAIT_POLICY=passive
mkdir -p "$out"
log="$out/kept_list.txt"
{
  date -u
  nvidia-smi --query-gpu=name,driver_version --format=csv,noheader || true
  lscpu | grep -E "Model name|^CPU\(s\)" || true
  echo "commit: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
} | tee "$log"
run() {  # skin pass
  echo "=== skin $1, pass $2" | tee -a "$log"
  "$bench" --backends=openmp --scenes=dense_pile,settled_pile --min_n=1e6 --max_n=1e6 \
    --iter_scale="${ITER_SCALE:-3}" --settle_steps="${SETTLE_STEPS:-10000}" --skin="$1" \
    --benchmark_repetitions="${REPS:-3}" --benchmark_report_aggregates_only=false \
    --benchmark_out="$out/kept_list_$1_$2.json" --benchmark_out_format=json 2>&1 |
    grep -vE "^\*\*\*|^-+$" | tee -a "$log"
}
for s in $skins; do run "$s" 1; done
# The second pass, reversed: the drift of a shared host between the first and the last.
for s in ${SECOND:-0.05 0}; do run "$s" 2; done
