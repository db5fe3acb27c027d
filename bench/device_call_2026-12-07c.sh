#!/usr/bin/env bash
# Third device call of 2026-12-07: the renumbering tests on the GPU (GpuRenumbering and
# the place, contact copy, restart and checkpoint tests around it, the state hashes);
# what a flow's mixing costs the GPU (sheared_pile: dense_pile numbered along the curve
# through where its grains were a strain ago, against curve_pile and shuffled_pile, in
# the scene's order, with counters `apart` and `blocks`); what a look at the order and a
# renumbering cost a step at 10^6 (tridem_renumber_cost); with CLI_RUN=1 `tridem run` of
# the ordered 10^6 pile over 10 000 steps with frames (a look at step 10 000).
#   bash bench/device_call_2026-12-07c.sh     (on the device; $OUT set by the device tool)
set -u
source scripts/device_env.sh >/dev/null
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$OUT/gpu.txt"
timeout 400 .devbin/tests/tridem_tests \
  --gtest_filter='GpuRenumbering*:GpuPlaceNumbering*:Gpu/StateHash.*:*ContactCopy*:Gpu*Restart*:*Checkpoint*:Renumbering*:PlaceNumbering*:NeighbourBlocks*' \
  >"$OUT/tests.log" 2>&1
echo "tests exit $?"
gtest_summary "$OUT/tests.log"
for strain in ${STRAINS:-1 3 10 30 100}; do
  .devbin/bench/tridem_bench --scenes=sheared_pile --backends=cuda-float,cuda --min_n=1e6 --max_n=1e6 \
    --order_strain="$strain" --particle_order=scene --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true 2>&1 | grep median |
    grep -o '^[a-z_]*/[a-z-]*/n:[0-9]*\|apart=[^ ]*\|blocks=[^ ]*\|stage_pair_forces=[^ ]*\|tri_steps_per_s=[^ ]*' |
    paste - - - - - | sed "s/^/strain=$strain /" | tee -a "$OUT/sheared.txt"
done
.devbin/bench/tridem_bench --scenes=curve_pile,shuffled_pile --backends=cuda-float,cuda --min_n=1e6 --max_n=1e6 \
  --particle_order=scene --benchmark_repetitions=3 --benchmark_report_aggregates_only=true 2>&1 | grep median |
  grep -o '^[a-z_]*/[a-z-]*/n:[0-9]*\|apart=[^ ]*\|blocks=[^ ]*\|stage_pair_forces=[^ ]*\|tri_steps_per_s=[^ ]*' |
  paste - - - - - | tee -a "$OUT/sheared.txt"
for precision in float double; do
  timeout 120 .devbin/bench/tridem_renumber_cost 1e6 cuda "$precision" 200 2>&1 | tee -a "$OUT/renumber_cost.txt"
done
if [ "${CLI_RUN:-0}" = 1 ]; then
  VARIANTS=cuda-float OUTPUT_KEYS='contacts_csv = false' EVERY=1000 REPS=3 timeout 150 \
    bench/run_cli_vs_bench_on_device.sh /tmp/cvb_dense 1000000 10000 2>&1 | tail -4
  cp /tmp/cvb_dense/summary.txt "$OUT/dense_summary.txt"
  cp /tmp/cvb_dense/cuda-float/run.log "$OUT/dense_run.log"
fi
