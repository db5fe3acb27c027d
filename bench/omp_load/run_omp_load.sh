#!/usr/bin/env bash
# The OpenMP solver on idle and on busy cores (issue 12): wall time of the same steps on
# the serial solver and on OpenMP threads, with no competing process and while BUSY
# competing loops (`while :; do :; done`) share the cores, under several OpenMP wait
# policies. Every run prints the load average (uptime) beside its time; rounds repeat the
# whole set, and bench/omp_load/medians.py takes the medians.
#
# Usage: bench/omp_load/run_omp_load.sh OUT.tsv [ROUNDS]
#   env: TIMERS  "label=path ..." of tridem_step_timer binaries, e.g. builds before and after
#                a change: each round runs them in turn, under the same load (default
#                build=build/bench/tridem_step_timer)
#        CASES   "scene:steps ..." (default: the bundled example, 1000 steps, and
#                dense_pile:100000, 6 steps)
#        THREADS OpenMP threads (default 2)  BUSY competing loops (default 2)
#        POLICIES wait policies of the OpenMP runs: default passive active, or
#                spin=N for GOMP_SPINCOUNT=N (default "default passive")
set -euo pipefail
out=$1
rounds=${2:-3}
timers=${TIMERS:-build=build/bench/tridem_step_timer}
threads=${THREADS:-2}
busy=${BUSY:-2}
cases=${CASES:-"examples/settling_pile.toml:1000 dense_pile:100000:6"}
policies=${POLICIES:-"default passive"}

printf 'round\tlabel\tload\tscene\tbackend\tpolicy\tsteps\tseconds\ts_per_step\tload1\n' > "$out"
loops=()
start_load() {
  for ((k = 0; k < busy; ++k)); do
    timeout 600 sh -c 'while :; do :; done' &
    loops+=($!)
  done
  sleep 1
}
stop_load() {
  for p in "${loops[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${loops[@]}"; do wait "$p" 2>/dev/null || true; done
  loops=()
}
trap stop_load EXIT

run_one() {  # round load label timer scene steps backend policy
  local round=$1 load=$2 label=$3 timer=$4 scene=$5 steps=$6 backend=$7 policy=$8
  local -a env_set=(env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT)
  case $policy in
    default) ;;
    passive | active) env_set+=(OMP_WAIT_POLICY=$policy) ;;
    spin=*) env_set+=(GOMP_SPINCOUNT=${policy#spin=}) ;;
  esac
  local th=$threads omp=$threads
  [[ $backend == cpu ]] && th=0 omp=1  # the serial solver takes no thread count
  local line
  line=$("${env_set[@]}" OMP_NUM_THREADS="$omp" "$timer" "$scene" "$backend" "$th" "$steps")
  local seconds s_per_step load1
  seconds=$(sed -n 's/.* seconds=\([^ ]*\).*/\1/p' <<<"$line")
  s_per_step=$(sed -n 's/.* s_per_step=\([^ ]*\).*/\1/p' <<<"$line")
  load1=$(cut -d' ' -f1 /proc/loadavg)
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$round" "$label" "$load" "$scene" "$backend" \
    "$policy" "$steps" "$seconds" "$s_per_step" "$load1" | tee -a "$out"
}

for ((r = 1; r <= rounds; ++r)); do
  for load in idle busy; do
    [[ $load == busy ]] && start_load
    for c in $cases; do
      scene=${c%:*}
      steps=${c##*:}
      for t in $timers; do
        label=${t%%=*}
        timer=${t#*=}
        run_one "$r" "$load" "$label" "$timer" "$scene" "$steps" cpu default
        for policy in $policies; do
          run_one "$r" "$load" "$label" "$timer" "$scene" "$steps" openmp "$policy"
        done
      done
    done
    [[ $load == busy ]] && stop_load
  done
done
