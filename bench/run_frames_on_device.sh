#!/usr/bin/env bash
# Issue 12's frame output on the GPU machine, in one device call (bundle from
# scripts/device_bundle.sh, carried as .devbin): each part under its own time limit, logs
# in OUT, summaries on stdout.
#  1. bench/run_gpu_checks_on_device.sh parts 1-2 (the CUDA state hashes, the GPU tests but
#     the slow validation suites): the contact network a snapshot takes from the GPU is
#     compared with the serial solver's in the parity suites, pinned by Gpu/StateHash;
#  2. tridem_frame_bench on dense_pile(10^6) after 1000 steps on cuda: bytes per triangle
#     and seconds per frame of each VTK format, and what the time loop waits per frame;
#  3. tridem run against the benchmark (bench/run_cli_vs_bench_on_device.sh) at 10^6,
#     3000 steps, a frame with its contact network every 1000: cuda-float with the contacts
#     CSV (the default) and without, cuda (double) without.
#   bench/run_frames_on_device.sh OUT        env: SKIP="1 2 3" (parts to leave out),
#   FRAME_PRECISION (part 2, default double), CLI_STEPS (part 3, default 3000), CLI_RUNS
#   (part 3's runs, default all three: cli_float_with_csv cli_float_no_csv cli_double_no_csv)
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"
mkdir -p "$out"
skip=" ${SKIP:-} "
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$out/gpu.txt"
echo "cores: $(nproc)"
if [[ $skip != *" 1 "* ]]; then
  # Parts 1-2 of the session's GPU checks (state hashes, the GPU tests but the slow suites).
  SKIP="3 4 5" "$root/bench/run_gpu_checks_on_device.sh" "$out/gpu_checks"
fi
if [[ $skip != *" 2 "* ]]; then
  echo "== 2 frame bench, dense_pile(10^6) after 1000 steps on cuda"
  timeout "${FRAME_SECONDS:-120}" "$root/.devbin/bench/tridem_frame_bench" 1000000 1000 3 cuda \
    "$out/frame_bench_files" "${FRAME_PRECISION:-double}" >"$out/frame_bench.md" 2>&1
  echo "exit $?"; cat "$out/frame_bench.md"; rm -rf "$out/frame_bench_files"
fi
if [[ $skip != *" 3 "* ]]; then
  echo "== 3 tridem run against the benchmark, 10^6"
  run_cli() {  # NAME VARIANTS OUTPUT_KEYS
    VARIANTS="$2" OUTPUT_KEYS="$3" timeout "${CLI_SECONDS:-150}" \
      "$root/bench/run_cli_vs_bench_on_device.sh" "$out/$1" 1000000 "${CLI_STEPS:-3000}" >"$out/$1.txt" 2>&1
    echo "-- $1 (exit $?)"; cat "$out/$1.txt"
    rm -rf "$out/$1"/*/run "$out/$1"/*/scene  # the frames themselves stay on the machine
  }
  runs=" ${CLI_RUNS:-cli_float_with_csv cli_float_no_csv cli_double_no_csv} "
  [[ $runs == *" cli_float_with_csv "* ]] && run_cli cli_float_with_csv cuda-float ""
  [[ $runs == *" cli_float_no_csv "* ]] && run_cli cli_float_no_csv cuda-float "contacts_csv = false"
  [[ $runs == *" cli_double_no_csv "* ]] && run_cli cli_double_no_csv cuda "contacts_csv = false"
  :  # a run left out is not a failure
fi
