#!/usr/bin/env bash
# Second device call of 2026-12-07: the host's CPU (lscpu), the place tests on the GPU,
# OpenMP at 10^6 on 16 and 8 threads (double and float), and `tridem run` of the 10^6 pile
# imported from a shuffled CSV against the benchmark's shuffled_pile, numbered by place
# (auto) and in the scene's order (bench/run_cli_vs_bench_on_device.sh, SHUFFLED=1).
# Results: bench/results/place_numbering_gpu_2026-12-07_nvidia-h100-80gb-hbm3/.
#   bash bench/device_call_2026-12-07b.sh     (on the device; $OUT set by the device tool)
set -u
source scripts/device_env.sh >/dev/null
lscpu | grep -E "Model name|^CPU\(s\)|Thread|Core|Socket|NUMA node|L3" | tee $OUT/lscpu.txt
timeout 60 .devbin/tests/tridem_tests --gtest_filter='PlaceNumbering.AFramesContactCopy*:GpuPlaceNumbering*' >$OUT/place_tests.log 2>&1; echo "place tests exit $?"; gtest_summary $OUT/place_tests.log
for th in 16 8; do for b in openmp openmp-float; do
  OMP_NUM_THREADS=$th OMP_WAIT_POLICY=passive timeout 120 .devbin/bench/tridem_bench --scenes=dense_pile --backends=$b --min_n=1e6 --max_n=1e6 2>&1 | grep -o '^[a-z_]*/[a-z-]*/n:[0-9]*\|stage_[a-z_]*=[^ ]*\|threads=[^ ]*\|tri_steps_per_s=[^ ]*' | tr '\n' ' ' | sed "s/^/th=$th /; s/\$/\n/" | tee -a $OUT/omp_threads.txt
done; done
for order in auto scene; do
  SHUFFLED=1 PARTICLE_ORDER=$order VARIANTS="cuda-float cuda" OUTPUT_KEYS='contacts_csv = false' EVERY=1000 REPS=3 timeout 200 bench/run_cli_vs_bench_on_device.sh /tmp/cvb_$order 1000000 5000 2>&1 | tail -6
  mkdir -p $OUT/cvb_$order; (cd /tmp/cvb_$order && find . \( -name summary.txt -o -name '*.log' -o -name bench.json \) -print0 | xargs -0 tar cf - | tar xf - -C $OUT/cvb_$order)
done
