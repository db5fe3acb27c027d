#!/usr/bin/env bash
# One device call of 2026-12-07 (and what issue 12 still has to measure on the device):
# with LEAN_RUN=1, `tridem run` of the 10^6 float pile against the benchmark with the lean
# frames of `[output] frame_arrays` and `contact_arrays` (docs/performance.md, "Output
# frames" item 12: their bytes at 10^6 and the run's rate with them); else on an H200 the
# 10^8 pile's frames in windows (peak GPU memory); else a part of the GPU suite under
# memcheck (the tests named in FILTER_FILE, or all `Gpu*` but the slow suites; the 23 not
# yet run are bench/results/memcheck_gpu_suite_2026-12-07_*_part2/s/memcheck_not_run.list).
out="${1:?OUT}"
source "$(dirname "$0")/../scripts/device_env.sh" >/dev/null
mib=$(nvidia-smi --query-gpu=memory.total --format=csv,noheader,nounits | head -1)
nvidia-smi --query-gpu=name,memory.total --format=csv,noheader
if [ "${SHUFFLE:-0}" = 1 ]; then
  # What the particles' order costs the GPU: dense_pile against the same grains numbered
  # at random (shuffled_pile), both precisions, one binary, cases interleaved; the solver
  # in the scene's order (scene) and numbering by place when far (auto, the default).
  for order in ${ORDERS:-scene auto}; do
    .devbin/bench/tridem_bench --scenes=dense_pile,shuffled_pile,curve_pile --backends=cuda,cuda-float \
      --min_n="${SHUFFLE_MIN_N:-1e4}" --max_n="${SHUFFLE_MAX_N:-1e6}" --benchmark_repetitions=3 \
      --particle_order="$order" --frames="${SHUFFLE_FRAMES:-}" \
      --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
      --benchmark_out="$out/shuffle_$order.json" --benchmark_out_format=json 2>&1 |
      tee "$out/shuffle_$order.txt" | grep -E "median|scene"
  done
fi
if [ "${OMP_AB:-0}" = 1 ]; then
  # The CPU solvers' partner records (backends/cpu/partner_record.hpp) on the host's cores:
  # tridem_bench_base is the build without them; dense and shuffled piles, alternating.
  for round in 1 2; do
    for b in tridem_bench_base tridem_bench; do
      for scene in dense_pile shuffled_pile; do
        OMP_WAIT_POLICY=passive ".devbin/bench/$b" --scenes=$scene --backends=openmp --min_n=1e6 \
          --max_n=1e6 2>&1 | grep -o '^[a-z_]*/openmp/n:[0-9]*\|stage_[a-z_]*=[^ ]*\|threads=[^ ]*\|tri_steps_per_s=[^ ]*' |
          tr '\n' ' ' | sed "s/^/$round $b /; s/\$/\n/" | tee -a "$out/omp_ab.txt"
      done
    done
  done
fi
if [ "${LEAN_RUN:-0}" = 1 ]; then
  work=/tmp/lean_run; rm -rf "$work"; mkdir -p "$work"
  # Alternating rounds of the lean frames and the default ones (both without the contacts
  # CSV), so that the two are compared on one machine.
  for round in $(seq 1 "${ROUNDS:-2}"); do
    OUTPUT_KEYS='contacts_csv = false
vtk_encoding = "appended"
frame_arrays = ["velocity", "angular_velocity"]
contact_arrays = ["force"]' VARIANTS=cuda-float EVERY=1000 \
      bench/run_cli_vs_bench_on_device.sh "$work/lean_$round" "${LEAN_N:-1000000}" "${STEPS:-10000}"
    OUTPUT_KEYS='contacts_csv = false' VARIANTS=cuda-float EVERY=1000 \
      bench/run_cli_vs_bench_on_device.sh "$work/default_$round" "${LEAN_N:-1000000}" "${STEPS:-10000}"
  done
  # The runs' frames (GBs) stay on the device: what comes back is what they printed, the
  # logs and one frame's file list with sizes.
  (cd "$work" && find . \( -name summary.txt -o -name gpu.txt -o -name '*.log' -o -name bench.json \
    -o -name bench.err -o -name scene.toml \) -print0 | xargs -0 tar cf - | tar xf - -C "$out")
  (cd "$work" && find . -path '*/run/*' -name '*_000005000.*' -printf '%p %s\n') >"$out/frame_files.txt"
elif [ "${mib:-0}" -gt 120000 ] && [ "${SKIP_WINDOW:-0}" = 0 ]; then
  ROUNDS=1 BUILDS=windows CHECKS=0 bench/run_contact_window_on_device.sh "$out/w" 1e8
else
  # The slow validation suites (5-30 s each without the sanitizer) apart: their kernels are
  # the fast tests' kernels over more steps.
  filter="Gpu*-$slow_gpu_tests"; [ -n "${FILTER_FILE:-}" ] && filter="$(cat "$FILTER_FILE")"
  TOOLS=memcheck SHARDS="${SHARDS:-2}" LIMIT="${LIMIT:-470}" bench/gpu_sanitize.sh "$out/s" "$filter"
fi
# Written beside, then moved in: a tarball inside the folder it archives changes as tar reads.
tar czf "/tmp/all.$$.tgz" -C "$out" . && mv "/tmp/all.$$.tgz" "$out/all.tgz"
