#!/usr/bin/env bash
# Does the user's `tridem run` get the benchmark's speed? (issue 12) For each variant, the
# benchmark's dense_pile(N) is written as a scene file (tridem_write_pile_scene: the same
# triangles, imported with their overlaps kept; the walls numbered first), run by
# `tridem run` for STEPS steps with a frame every EVERY steps and the contact network
# (the scene's defaults otherwise: the formats a user gets), and measured by tridem_bench on
# dense_pile(N) with the same backend and precision. Prints both rates (triangle-steps/s),
# their ratio, the run's wall time with set-up and final outputs, and the frames' bytes per
# triangle on disk (frames/*.vtu, contacts/*.vtp, contacts/*.csv; step 0's frame, which has
# no contacts, left out). The benchmark times steps 3-32 of a fresh pile and no output;
# `tridem run` prints its rate over steps 1-STEPS and every output, from the first frame
# to the last.
#
#   bench/run_cli_vs_bench_on_device.sh OUT [N=1000000] [STEPS=3000]
# env: VARIANTS  tridem_bench's names: cuda-float, cuda, openmp, cpu (default "cuda-float cuda")
#      EVERY     steps between frames (default 1000)
#      BIN       folder with app/tridem, bench/tridem_bench, bench/tridem_write_pile_scene
#                (default .devbin, the GPU machine's bundle: scripts/device_bundle.sh; else build)
#      OUTPUT_KEYS  more [output] lines for the scene, e.g. 'contacts_csv = false'
#      REPS      the benchmark's repetitions (default 3; the median is taken)
#      SHUFFLED=1   the grains' lines of grains.csv in a random order (a fixed seed), as a
#                   user's imported pile numbered in no spatial order, measured against
#                   tridem_bench's shuffled_pile (the same grains numbered at random)
#      PARTICLE_ORDER  auto, scene or place: tridem run's --particle-order and the
#                   benchmark's --particle_order (default: neither given, i.e. auto)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:?give an output folder}"
n="${2:-1000000}"
steps="${3:-3000}"
every="${EVERY:-1000}"
variants="${VARIANTS:-cuda-float cuda}"
reps="${REPS:-3}"
if [ -z "${BIN:-}" ]; then
  if [ -d "$root/.devbin" ]; then
    source "$root/scripts/device_env.sh"
    BIN="$root/.devbin"
  else
    BIN="$root/build"
  fi
fi
tridem="$BIN/app/tridem"
bench="$BIN/bench/tridem_bench"
writer="$BIN/bench/tridem_write_pile_scene"
mkdir -p "$out"
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee "$out/gpu.txt" || true

# Median tri_steps_per_s of a tridem_bench JSON report (the one run's with one repetition).
bench_rate() {
  awk '/"name":/ { median = ($0 ~ /_median"/) }
       /"tri_steps_per_s":/ { gsub(/[^0-9.eE+-]/, "", $2); if (first == "") first = $2
                              if (median) { print $2; found = 1; exit } }
       END { if (!found) print first }' "$1"
}
# Bytes of the files matching a pattern, summed, and how many there are (besides step 0's).
sum_bytes() {
  local total=0 count=0 f
  for f in $1; do
    [ -e "$f" ] || continue
    case "$f" in *_000000000.*) continue ;; esac
    total=$((total + $(stat -c %s "$f")))
    count=$((count + 1))
  done
  echo "$total $count"
}

printf '%-11s %9s %6s %14s %14s %9s %10s %8s %8s %8s %10s\n' variant N steps bench_tri_st/s \
  run_tri_st/s run/bench run_wall_s vtu_B/tri vtp_B/tri csv_B/tri frames_B/tri | tee "$out/summary.txt"
for v in $variants; do
  backend="${v%-float}"
  precision=double
  [ "$backend" != "$v" ] && precision=float
  dir="$out/$v"
  rm -rf "$dir"
  "$writer" "$n" "$dir/scene" "$steps" "$every" "$precision"
  if [ -n "${OUTPUT_KEYS:-}" ]; then
    printf '%s\n' "$OUTPUT_KEYS" >"$dir/output_keys"
    sed -i "/^contacts = true\$/r $dir/output_keys" "$dir/scene/scene.toml"
  fi
  triangles=$(( $(wc -l <"$dir/scene/grains.csv") - 1 + 3 ))
  bench_scene=dense_pile
  if [ "${SHUFFLED:-0}" = 1 ]; then
    bench_scene=shuffled_pile
    { head -1 "$dir/scene/grains.csv"
      tail -n +2 "$dir/scene/grains.csv" | shuf --random-source=<(yes 20261207); } >"$dir/grains.shuffled"
    mv "$dir/grains.shuffled" "$dir/scene/grains.csv"
  fi
  order_flags=() bench_order_flags=()
  if [ -n "${PARTICLE_ORDER:-}" ]; then
    order_flags=(--particle-order "$PARTICLE_ORDER")
    bench_order_flags=(--particle_order="$PARTICLE_ORDER")
  fi

  t0=$(date +%s.%N)
  "$tridem" run "$dir/scene/scene.toml" --backend "$backend" "${order_flags[@]}" --out "$dir/run" --quiet \
    >"$dir/run.log" 2>&1 || { echo "$v: tridem run failed (see $dir/run.log)"; tail -5 "$dir/run.log"; continue; }
  t1=$(date +%s.%N)
  run_rate=$(sed -n 's/^done: .*steps\/s, \([0-9.eE+-]*\) triangle-steps\/s.*/\1/p' "$dir/run.log")
  run_wall=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')

  "$bench" --scenes="$bench_scene" --backends="$v" "${bench_order_flags[@]}" --min_n="$n" --max_n="$n" --benchmark_repetitions="$reps" \
    --benchmark_report_aggregates_only=true --benchmark_format=json >"$dir/bench.json" 2>"$dir/bench.err" ||
    { echo "$v: tridem_bench failed (see $dir/bench.err)"; continue; }
  bench_rate_v=$(bench_rate "$dir/bench.json")
  [ -n "$bench_rate_v" ] && bench_rate_v=$(printf '%.4g' "$bench_rate_v")

  read -r vtu frames < <(sum_bytes "$dir/run/frames/*.vtu")
  read -r vtp _ < <(sum_bytes "$dir/run/contacts/*.vtp")
  read -r csv _ < <(sum_bytes "$dir/run/contacts/*.csv")
  per() { awk -v b="$1" -v f="$frames" -v t="$triangles" 'BEGIN { if (f > 0) printf "%.1f", b / f / t; else print "-" }'; }
  printf '%-11s %9s %6s %14s %14s %9s %10s %8s %8s %8s %10s\n' "$v" "$n" "$steps" "$bench_rate_v" \
    "$run_rate" "$(awk -v a="$run_rate" -v b="$bench_rate_v" 'BEGIN { if (b > 0) printf "%.3f", a / b }')" \
    "$run_wall" "$(per "$vtu")" "$(per "$vtp")" "$(per "$csv")" "$(per $((vtu + vtp)))" | tee -a "$out/summary.txt"
  # Where tridem run says its wall time went (set-up, stepping, outputs), where it says so.
  grep -E '^(wall time|done):' "$dir/run.log" | sed "s/^/  $v: /" | tee -a "$out/summary.txt" || true
done
echo "frames_B/tri: one frame's .vtu and its contact network's .vtp per triangle (frames after step 0: $every steps apart); csv_B/tri the contacts' CSV beside them, where written" | tee -a "$out/summary.txt"
