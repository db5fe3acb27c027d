# Sourced by the scripts that run on the GPU machine: unpacks the carried libraries
# (device_unpack.sh), puts them on the loader's path, and makes the tests' compiled-in
# source path (/work/main) point at this checkout. Sets `root`, gpu_tests and slow_gpu_tests;
# defines gtest_summary, check_state_hashes and the GPU memory watch (gpu_watch_*).
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/device_unpack.sh"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ ! -e /work/main/tests ]; then mkdir -p /work && ln -sfn "$root" /work/main; fi

# The pass/fail lines of a gtest log.
gtest_summary() {
  grep -E '^\[  (PASSED|FAILED|SKIPPED) |tests? from .* ran|FAILED TEST' "$1" | sort -u | head -40
}

# The GPU's name into OUT/gpu.txt, then the CUDA state hashes (Gpu/StateHash: the GPU's
# arithmetic, bit for bit) into OUT/state_hash.log, with their summary.
check_state_hashes() {  # OUT
  nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$1/gpu.txt"
  timeout 60 "$root/.devbin/tests/tridem_tests" --gtest_filter='Gpu/StateHash.*' \
    >"$1/state_hash.log" 2>&1
  echo "== state hashes: exit $?"
  gtest_summary "$1/state_hash.log"
}

# The GPU tests (state hashes apart), and the slow validation suites among them (5-30 s
# each), whose GPU arithmetic the state hashes pin.
gpu_tests="Gpu*:*Cuda*:*Gpu*:Bonds.*:*StateCopy*-Gpu/StateHash.*"
slow_gpu_tests='Gpu/Incline.*:Gpu/PrecisionTest.*:Gpu/StepStability.*:Gpu/Friction.*:Gpu/MotionTest.*:Gpu/MotionProgramTest.*:Gpu/Resting.*'

# The GPU's memory in use now, MiB.
gpu_used() { nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits | head -1; }

# gpu_watch_start FILE: nvidia-smi samples the GPU's memory every GPU_WATCH_MS ms (default
# 100; 10 catches a frame's transient scratch) into FILE from now;
# gpu_watch_peak FILE: stops it and prints the peak less what was in use at the start.
gpu_watch_start() {
  gpu_watch_before=$(gpu_used)
  nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits -lms "${GPU_WATCH_MS:-100}" >"$1" &
  gpu_watch_pid=$!
}
gpu_watch_peak() {
  kill "$gpu_watch_pid" 2>/dev/null; wait "$gpu_watch_pid" 2>/dev/null
  sort -n "$1" | tail -1 | awk -v b="$gpu_watch_before" \
    '{printf "gpu memory peak: %d MiB (%d MiB in use before)\n", $1 - b, b}'
}
