#!/usr/bin/env bash
# Runs the CPU solver benchmark (tridem_bench) with repetitions and writes, into OUTDIR
# (default bench/results):
#   cpu_<YYYY-MM-DD>_<tag>.json   Google Benchmark JSON, every repetition and the aggregates
#   cpu_<YYYY-MM-DD>_<tag>.md     the table: medians per n, serial vs OpenMP, speed-up,
#                                 and the machine (CPU model, cores, nproc, compiler, load)
#
# Usage: bench/run_cpu_bench.sh [OUTDIR]
# Environment (all optional):
#   MAX_N=1e6        largest size run (1e3, 1e4, 1e5, 1e6); e.g. MAX_N=1e5 for a short budget
#   MIN_N=1e3        smallest size run
#   REPS=5           repetitions per case (the table gives their median)
#   LARGE_REPS=      repetitions for n = 1e6 only (default REPS); e.g. 3 on a slow machine
#   ITER_SCALE=1     multiplies the fixed iterations per repetition (e.g. 0.5 to halve)
#   BACKENDS=cpu,openmp
#   INTERLEAVE=1     run the repetitions of all cases in random order (0: case by case)
#   OMP_NUM_THREADS  passed through to the OpenMP solver (default: the runtime's, = nproc)
#   BUILD_DIR=build-bench   where tridem_bench is built (Release; always brought up to date)
#   NO_BUILD=1       run the binary as it is, without rebuilding
#   TAG=             file tag (default: CPU model and nproc, e.g. intel-xeon-processor-2c)
#   NOTES=           extra Markdown appended to the notes of the results file
#   WAIT_IDLE=       seconds to wait, at most, for the CPUs to be nearly idle before the run
#                    (shared machines); IDLE_BUSY_MAX=10 is the busy percent counted as idle
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
outdir="${1:-$here/results}"
build_dir="${BUILD_DIR:-$root/build-bench}"
case "$build_dir" in /*) ;; *) build_dir="$root/$build_dir" ;; esac
bin="$build_dir/bench/tridem_bench"

# Always bring the binary up to date (incremental), so that the commit recorded below is
# the code measured; NO_BUILD=1 runs the binary as it is.
if [[ "${NO_BUILD:-0}" != 1 ]]; then
  if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
    cmake -G Ninja -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >&2
  fi
  echo "run_cpu_bench: building tridem_bench in $build_dir" >&2
  cmake --build "$build_dir" --target tridem_bench >&2
fi
[[ -x "$bin" ]] || { echo "run_cpu_bench: no $bin" >&2; exit 1; }

mkdir -p "$outdir"
cpu_model="$(grep -m1 '^model name' /proc/cpuinfo | sed 's/^[^:]*:[[:space:]]*//' || true)"
cpu_model="${cpu_model:-unknown CPU}"
nproc_n="$(nproc)"
sockets="$(lscpu 2>/dev/null | awk -F: '/^Socket\(s\)/ {gsub(/ /,"",$2); print $2}')"
cores_per_socket="$(lscpu 2>/dev/null | awk -F: '/^Core\(s\) per socket/ {gsub(/ /,"",$2); print $2}')"
threads_per_core="$(lscpu 2>/dev/null | awk -F: '/^Thread\(s\) per core/ {gsub(/ /,"",$2); print $2}')"
if [[ -n "$sockets" && -n "$cores_per_socket" ]]; then
  cores="$((sockets * cores_per_socket)) cores ($sockets socket(s) × $cores_per_socket, ${threads_per_core:-?} thread(s) per core)"
else
  cores="unknown"
fi
day="$(date +%F)"
tag="${TAG:-$(echo "$cpu_model" | tr 'A-Z' 'a-z' | sed -e 's/([^)]*)//g' -e 's/cpu//g' \
  -e 's/@.*//' -e 's/[^a-z0-9]\+/-/g' -e 's/^-//' -e 's/-$//')-${nproc_n}c}"
base="$outdir/cpu_${day}_${tag}"
json="$base.json"
md="$base.md"

reps="${REPS:-5}"
args=(--benchmark_repetitions="$reps"
      --benchmark_display_aggregates_only=true
      --benchmark_out="$json" --benchmark_out_format=json
      --max_n="${MAX_N:-1e6}" --min_n="${MIN_N:-1e3}"
      --backends="${BACKENDS:-cpu,openmp}" --iter_scale="${ITER_SCALE:-1}")
[[ -n "${LARGE_REPS:-}" ]] && args+=(--large_reps="$LARGE_REPS")
# Repetitions of all cases in random order: a burst of load from other processes then
# spreads over both backends and all sizes instead of spoiling one case's every repetition.
[[ "${INTERLEAVE:-1}" == 1 ]] && args+=(--benchmark_enable_random_interleaving=true)

# Busy fraction of all CPUs over one second, in percent, from /proc/stat.
busy_percent() {
  local a b
  read -r -a a < <(grep '^cpu ' /proc/stat)
  sleep 1
  read -r -a b < <(grep '^cpu ' /proc/stat)
  local total=0 idle i
  for i in 1 2 3 4 5 6 7 8; do total=$((total + b[i] - a[i])); done
  idle=$((b[4] - a[4] + b[5] - a[5]))
  echo $(( total > 0 ? 100 * (total - idle) / total : 0 ))
}
idle_note=""
if [[ -n "${WAIT_IDLE:-}" ]]; then
  # On a shared machine: wait (up to WAIT_IDLE seconds) until the CPUs are nearly idle.
  waited=0
  while busy="$(busy_percent)"; (( busy > ${IDLE_BUSY_MAX:-10} && waited < WAIT_IDLE )); do
    echo "run_cpu_bench: CPUs ${busy}% busy, waiting for them to go idle" >&2
    sleep 4
    waited=$((waited + 5))
  done
  idle_note="CPUs ${busy}% busy just before the run (waited ${waited} s for idle)"
fi

load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
uptime_before="$(uptime)"
# CPU time of the whole machine during the run, to tell how much of it others took.
cpu_jiffies() { awk '/^cpu / {print $2+$3+$4+$7+$8+$9, $2+$3+$4+$5+$6+$7+$8+$9}' /proc/stat; }
read -r busy0 total0 < <(cpu_jiffies)
start=$(date +%s.%N)
echo "run_cpu_bench: $bin ${args[*]}" >&2
own_times="$(mktemp)"
if [[ -x /usr/bin/time ]]; then
  /usr/bin/time -f "%U %S" -o "$own_times" "$bin" "${args[@]}"
else
  "$bin" "${args[@]}"
fi
end=$(date +%s.%N)
read -r busy1 total1 < <(cpu_jiffies)
others_note="$(python3 - "$own_times" "$busy0" "$total0" "$busy1" "$total1" "$start" "$end" <<'PY'
import os, sys
path, b0, t0, b1, t1, start, end = sys.argv[1:]
try:
    own = sum(float(x) for x in open(path).read().split()[:2])
except (OSError, ValueError):
    sys.exit()
hz = os.sysconf("SC_CLK_TCK")
busy = (int(b1) - int(b0)) / hz
capacity = (int(t1) - int(t0)) / hz
if capacity > 0:
    print(f"the benchmark used {own:.0f} CPU-s, other processes about "
          f"{max(0.0, busy - own):.0f} CPU-s = {100 * max(0.0, busy - own) / capacity:.0f}% "
          f"of the machine's {capacity:.0f} CPU-s during the run")
PY
)"
rm -f "$own_times"
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

compiler="$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["context"].get("compiler","?"))' "$json")"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [[ -n "$(git -C "$root" status --porcelain -- src include CMakeLists.txt 2>/dev/null)" ]]; then
  commit="$commit (with uncommitted changes in src/ or include/)"
fi

machine="$(mktemp)"
notes="$(mktemp)"
trap 'rm -f "$machine" "$notes"' EXIT
cat >"$machine" <<EOF
- Date: $day ($(date +%T%z)), run took $(python3 -c "print(round($end - $start))") s
- Machine: **$cpu_model**, $cores, \`nproc\` = $nproc_n, $(free -g | awk '/^Mem:/ {print $2}') GiB RAM, $(uname -sr)
- Compiler: $compiler, CMake Release (tridem_core as built in \`${build_dir#$root/}\`)
- Threads: OMP_NUM_THREADS=${OMP_NUM_THREADS:-unset} (OpenMP solver uses the runtime default)
- tridem commit: $commit
- Repetitions: $reps per case${LARGE_REPS:+ ($LARGE_REPS for n = 1e6)}; sizes ${MIN_N:-1e3} to ${MAX_N:-1e6}
- Load average (1, 5, 15 min): $load_before before, $load_after after${others_note:+; $others_note}
- \`uptime\` before: \`$uptime_before\`${idle_note:+; $idle_note}
- Command: \`bench/run_cpu_bench.sh\` → \`${bin#$root/} ${args[*]//$outdir\//}\`
EOF
{
  echo "- Raw data: \`$(basename "$json")\` (Google Benchmark JSON, every repetition)."
  if [[ -n "${NOTES:-}" ]]; then echo; echo "$NOTES"; fi
} >"$notes"

python3 "$here/cpu_bench_table.py" "$json" --machine-file "$machine" --notes-file "$notes" >"$md"
echo "run_cpu_bench: wrote $md and $json" >&2
cat "$md"
