#!/usr/bin/env bash
# On the GPU machine: named GPU tests one process at a time (several processes on one GPU
# time-slice, which makes latency-bound small scenes many times slower), then
# compute-sanitizer memcheck and racecheck over short GPU tests. Logs go to OUTDIR.
#   bench/gpu_remaining.sh OUTDIR 'FILTER_FOR_TESTS' 'FILTER_FOR_SANITIZER' [TEST_SECONDS]
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$1"; tests="$2"; sanitized="$3"; limit="${4:-300}"
mkdir -p "$out"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ ! -e /work/main/tests ]; then mkdir -p /work && ln -sfn "$root" /work/main; fi
bin="$root/.devbin/tests/tridem_tests"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv | tee "$out/gpu.txt"
if [ -n "$tests" ]; then
  timeout "$limit" stdbuf -oL "$bin" --gtest_filter="$tests" 2>&1 | tee "$out/tests.log"
fi
if [ -n "$sanitized" ]; then
  cs="$(command -v compute-sanitizer || ls /usr/local/cuda*/bin/compute-sanitizer 2>/dev/null | head -1)"
  echo "compute-sanitizer: ${cs:-not found}" | tee "$out/sanitizer.log"
  if [ -n "$cs" ]; then
    for tool in memcheck racecheck; do
      echo "== $tool" | tee -a "$out/sanitizer.log"
      timeout 240 stdbuf -oL "$cs" --tool "$tool" --error-exitcode 9 "$bin" --gtest_brief=1 \
        --gtest_filter="$sanitized" 2>&1 | tail -40 | tee -a "$out/sanitizer.log"
      echo "exit ${PIPESTATUS[0]}" | tee -a "$out/sanitizer.log"
    done
  fi
fi
