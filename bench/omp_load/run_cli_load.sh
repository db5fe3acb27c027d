#!/usr/bin/env bash
# The user's command on busy cores (issue 12): `tridem run` of a scene for STEPS steps with
# the serial solver, with OpenMP as the program runs it now (passive waiting unless told),
# and with OpenMP under the runtime's default (GOMP_SPINCOUNT=300000, what the program ran
# with before), while BUSY competing loops run. Prints each run's "done:" line and the
# load average.
#   bench/omp_load/run_cli_load.sh TRIDEM SCENE [STEPS=2000] [ROUNDS=2]
set -euo pipefail
tridem=$1
scene=$2
steps=${3:-2000}
rounds=${4:-2}
busy=${BUSY:-2}
out=$(mktemp -d)
loops=()
for ((k = 0; k < busy; ++k)); do
  timeout 600 sh -c 'while :; do :; done' &
  loops+=($!)
done
trap 'for p in "${loops[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$out"' EXIT
sleep 1
for ((r = 1; r <= rounds; ++r)); do
  for way in cpu openmp openmp-runtime-default; do
    case $way in
      cpu) cmd=(env "$tridem" run "$scene" --backend cpu) ;;
      openmp) cmd=(env "$tridem" run "$scene" --backend openmp --threads 2) ;;
      openmp-runtime-default) cmd=(env GOMP_SPINCOUNT=300000 "$tridem" run "$scene" --backend openmp --threads 2) ;;
    esac
    line=$("${cmd[@]}" --steps "$steps" --quiet --out "$out/$way" | grep -E '^done:')
    printf '%s\t%s\t%s\tload %s\n' "$r" "$way" "$line" "$(cut -d' ' -f1 /proc/loadavg)"
  done
done
