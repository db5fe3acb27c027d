#!/usr/bin/env bash
# A/B of several builds of tridem_bench in one run on one GPU (the way a lever is kept or
# dropped: medians and ratios measured side by side, docs/performance.md). Each NAME is a
# binary .devbin/bench/tridem_bench_NAME carried from scripts/device_bundle.sh; the runs
# alternate between builds, repetition by repetition, so that clock drift hits them alike.
#   bench/compare_builds.sh OUTDIR NAME...    env: BENCH_ARGS (default: dense_pile 10^4..10^6,
#                                             cuda and cuda-float), ROUNDS (3)
set -euo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
shift
mkdir -p "$out"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv >"$out/gpu.txt"
args=${BENCH_ARGS:---backends=cuda,cuda-float --min_n=1e4 --max_n=1e6 --scenes=dense_pile}
for round in $(seq 1 "${ROUNDS:-3}"); do
  for name in "$@"; do
    # shellcheck disable=SC2086
    "$root/.devbin/bench/tridem_bench_$name" $args --benchmark_repetitions=1 \
      --benchmark_out="$out/${name}_$round.json" --benchmark_out_format=json \
      >"$out/${name}_$round.txt" 2>&1
  done
done
python3 "$root/bench/compare_builds_table.py" "$out" "$@" | tee "$out/table.md"
