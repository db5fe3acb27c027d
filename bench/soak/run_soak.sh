#!/usr/bin/env bash
# The soak run of docs/reliability.md, on the GPU machine from a bundle (.devbin):
# 10^5 grains for 10^6 steps on the CUDA backend, with a checkpoint every 10^5 steps,
# stopped by SIGINT part-way and continued with --restart, while the GPU memory of the
# process and its resident memory are sampled every second. check_soak.py then checks
# energy and momentum bounds, flat memory and complete outputs.
#   bench/soak/run_soak.sh OUTDIR [STEPS]
set -uo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:?give an output folder}"
steps="${2:-1000000}"
work="${SOAK_WORK:-/tmp/soak_work}"
mkdir -p "$out" "$work"
export LD_LIBRARY_PATH="$root/.devbin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
tridem="$root/.devbin/app/tridem"
scene="$root/bench/soak/soak.toml"
cd "$work" && rm -rf soak_out step1
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader | tee "$out/gpu.txt"
"$tridem" info "$scene" >"$out/info.txt" 2>&1

# The state after one step: the energy every later state is bounded by.
"$tridem" run "$scene" --quiet --steps 1 --out step1 >"$out/step1.log" 2>&1 || exit 1

sample() {  # pid -> appends "seconds,gpu_mib,rss_kib" every second while pid lives
  local pid=$1 t0=$SECONDS
  while kill -0 "$pid" 2>/dev/null; do
    local gpu rss
    gpu=$(nvidia-smi --query-compute-apps=pid,used_memory --format=csv,noheader,nounits |
          awk -F', ' -v p="$pid" '$1 == p {print $2}')
    rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null)
    [ -n "$gpu" ] && [ -n "$rss" ] && echo "$((SECONDS - t0)),$gpu,$rss,$pid" >>"$out/memory.csv"
    sleep 1
  done
}
echo "seconds,gpu_mib,rss_kib,pid" >"$out/memory.csv"

# Part 1: interrupted by SIGINT after SOAK_INTERRUPT_AFTER seconds (60).
"$tridem" run "$scene" --steps "$steps" --out soak_out >"$out/part1.log" 2>&1 &
pid=$!
sample "$pid" &
sampler=$!
sleep "${SOAK_INTERRUPT_AFTER:-60}"
kill -INT "$pid"
wait "$pid"
echo "part 1 exit code $? (130 expected: SIGINT)" | tee -a "$out/part1.log"
tail -n 4 "$out/part1.log"
wait "$sampler"

# Part 2: continue from the checkpoint the interruption wrote, to the end.
"$tridem" run "$scene" --steps "$steps" --out soak_out --restart soak_out/checkpoint.ckpt \
  >"$out/part2.log" 2>&1 &
pid=$!
sample "$pid" &
sampler=$!
wait "$pid"
echo "part 2 exit code $? (0 expected)" | tee -a "$out/part2.log"
tail -n 4 "$out/part2.log"
wait "$sampler"

cp soak_out/energy.csv "$out/energy.csv"
ls -l soak_out soak_out/frames >"$out/files.txt"
python3 "$root/bench/soak/check_soak.py" --scene "$scene" --steps "$steps" --run soak_out \
  --step1 step1/final.csv --memory "$out/memory.csv" --logs "$out" | tee "$out/check.txt"
exit "${PIPESTATUS[0]}"
