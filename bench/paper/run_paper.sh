#!/usr/bin/env bash
# Reruns the seed paper's experiments on the GPU machine, from a bundle built here
# (scripts/device_bundle.sh, carried as .devbin), and makes the tables and figures:
#   bench/paper/run_paper.sh OUTDIR [EXTRA tridem_paper_bench FLAGS]
# OUTDIR gets paper_bench.json (Google Benchmark), paper_bench.txt (console), gpu.txt and,
# where Python has matplotlib, paper_tables.md and the PNGs; elsewhere run
#   bench/paper/make_figures.py OUTDIR/paper_bench.json OUTDIR
# on a machine that has it (Debian: python3-matplotlib).
set -uo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:?give an output folder}"
shift
mkdir -p "$out"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv | tee "$out/gpu.txt"
"$root/.devbin/bench/tridem_paper_bench" --benchmark_out="$out/paper_bench.json" \
  --benchmark_out_format=json "$@" 2>&1 | tee "$out/paper_bench.txt"
status=${PIPESTATUS[0]}
for py in python3 /usr/bin/python3; do
  if "$py" -c "import matplotlib" 2>/dev/null; then
    "$py" "$root/bench/paper/make_figures.py" "$out/paper_bench.json" "$out" >/dev/null
    exit $status
  fi
done
echo "no matplotlib here: make the figures with bench/paper/make_figures.py elsewhere"
exit $status
