#!/usr/bin/env bash
# A change to the frame writers, against the build before it, in one device call: the
# bundle (scripts/device_bundle.sh, carried as .devbin) is the change; the build before is
# .devextra/extra.tar.xz (carried too), holding tridem_base (its tridem) and
# tridem_frame_bench_base (its frame benchmark). Alternating rounds of
#  1. tridem_frame_bench 10^6 ... parts (a frame's parts and the VTK writer's phases), and
#  2. `tridem run` of the 10^6 pile in float, CLI_STEPS steps, a frame with its network and
#     the contacts CSV every 1000 (bench/run_cli_vs_bench_on_device.sh), against the
#     benchmark in the same round.
# Logs in OUT; the summaries on stdout.
#   bench/run_frame_writer_ab_on_device.sh OUT    env: ROUNDS (2), CLI_STEPS (10000),
#   OUTPUT_KEYS (more [output] lines for the runs, e.g. 'contacts_csv = false')
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
mkdir -p "$out"
base="$out/base_bin"
mkdir -p "$base/app" "$base/bench"
tar -C "$base" -xJf "$root/.devextra/extra.tar.xz"
mv "$base/tridem_base" "$base/app/tridem"
ln -sf "$root/.devbin/bench/tridem_bench" "$root/.devbin/bench/tridem_write_pile_scene" "$base/bench/"
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee "$out/gpu.txt"
for round in $(seq "${ROUNDS:-2}"); do
  for build in base change; do
    if [ "$build" = base ]; then
      frame_bench="$base/tridem_frame_bench_base"; bin="$base"
    else
      frame_bench="$root/.devbin/bench/tridem_frame_bench"; bin="$root/.devbin"
    fi
    log="$out/parts_${build}_$round.md"
    timeout 120 "$frame_bench" 1000000 1000 3 cuda "$root/.ab_frames" float parts >"$log" 2>&1
    echo "== round $round, $build: frame parts (exit $?)"
    grep -E '^\| (grain|\.vtu|contacts)' "$log"
    rm -rf "$root/.ab_frames"
    BIN="$bin" VARIANTS=cuda-float OUTPUT_KEYS="${OUTPUT_KEYS:-}" timeout 200 \
      "$root/bench/run_cli_vs_bench_on_device.sh" "$out/cli_${build}_$round" 1000000 \
      "${CLI_STEPS:-10000}" >"$out/cli_${build}_$round.txt" 2>&1
    echo "== round $round, $build: tridem run against the benchmark (exit $?)"
    cat "$out/cli_${build}_$round.txt"
    rm -rf "$out/cli_${build}_$round"/*/run "$out/cli_${build}_$round"/*/scene
  done
done
