#!/usr/bin/env bash
# Issue 10's precision target on the GPU machine: the CUDA solver in double and in
# precision = "float" (the mixed mode: double state, float pairs) at n = 10^6, beside the
# same two of a baseline build (main before mixed precision, whose float was pure float),
# so that the mixed mode's throughput reads as a fraction of the old float's. Both binaries
# come from bundles built here (scripts/device_bundle.sh); copy the baseline's tridem_bench
# to .devbin/bench/baseline_tridem_bench before carrying .devbin.
#   bench/run_mixed_bench.sh OUTDIR     env: N (1e6), GPU_REPS (5), BASELINE (that path)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?give an output folder}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
n="${N:-1e6}"
baseline="${BASELINE:-$root/.devbin/bench/baseline_tridem_bench}"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm,clocks.max.mem --format=csv >"$out/gpu.txt"
run() {  # binary, name
  "$1" --backends=cuda,cuda-float --min_n="$n" --max_n="$n" \
    --benchmark_repetitions="${GPU_REPS:-5}" --benchmark_out="$out/$2.json" \
    --benchmark_out_format=json >"$out/$2.txt" 2>&1
}
run "$root/.devbin/bench/tridem_bench" mixed
if [ -x "$baseline" ]; then run "$baseline" baseline; fi
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
def medians(name):
    path = os.path.join(out, name + ".json")
    if not os.path.exists(path): return {}
    rows = json.load(open(path))["benchmarks"]
    # dense_pile/<variant>/n:<n>: the median of the repetitions
    return {r["run_name"].split("/")[1]: r["tri_steps_per_s"] for r in rows
            if r["run_name"].startswith("dense_pile/") and r.get("aggregate_name") == "median"}
new, old = medians("mixed"), medians("baseline")
print("| build | CUDA double | CUDA float |")
print("| --- | --- | --- |")
for label, m in (("baseline (pure float)", old), ("this (mixed float)", new)):
    if m: print(f"| {label} | {m.get('cuda', 0):.3g} | {m.get('cuda-float', 0):.3g} |")
if old.get("cuda-float") and new.get("cuda-float"):
    print(f"\nmixed float / old float: {new['cuda-float'] / old['cuda-float']:.3f} (target >= 0.90)")
PY
