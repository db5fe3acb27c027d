#!/usr/bin/env bash
# The live view's benchmark (issue 18's targets): for each size, the frames per second the
# server delivers to a client (tridem_live_client, no browser, asking for the next frame as
# soon as it has one, at the frame-rate limit 120) and the stepping rate of the same run
# without --live, with --live and no client, and with that client watching from the start
# to the end. Writes a Markdown table to bench/results/ and checks issue 18's targets:
# >= 30 frames/s at 10^5 triangles, >= 5 at 10^6, stepping at most 5 % slower with a client.
#   bench/live/run_live_bench.sh [BUILD_DIR]
# Environment: BACKEND (cuda), SIZES (the lattices' triangle counts; "100000 1000000" on
# cuda, "10000 100000" otherwise), STEPS (steps of each size's runs, in SIZES' order),
# TRIDEM, CLIENT, COST (the binaries; without COST the frame cost columns say ?), PORT,
# WORK (the runs' folder), OUT (the table).
# On the H200, one call (the device bundle's binaries, the runs' logs kept beside the table):
#   COST=.devbin/bench/tridem_live_frame_cost TRIDEM=.devbin/app/tridem \
#   CLIENT=.devbin/bench/tridem_live_client WORK=/tmp/lw OUT=$OUT/live_bench.md \
#   bench/live/run_live_bench.sh; cp /tmp/lw/*.log /tmp/lw/*.json $OUT/
set -euo pipefail
BUILD=${1:-build}
TRIDEM=${TRIDEM:-$BUILD/app/tridem}
CLIENT=${CLIENT:-$BUILD/bench/tridem_live_client}
COST=${COST:-$BUILD/bench/tridem_live_frame_cost}  # optional: what a frame costs the stepping
BACKEND=${BACKEND:-cuda}
if [ "$BACKEND" = cuda ]; then
  SIZES=${SIZES:-"100000 1000000"}; STEPS=${STEPS:-"60000 6000"}
else
  SIZES=${SIZES:-"10000 100000"}; STEPS=${STEPS:-"4000 300"}
fi
PORT=${PORT:-18765}
WORK=${WORK:-$(mktemp -d)}
mkdir -p "$WORK"
HOST=$(hostname -s 2>/dev/null || echo host)
OUT=${OUT:-bench/results/live_$(date +%F)_${BACKEND}_${HOST}.md}
[ -x "$TRIDEM" ] || { echo "no $TRIDEM (build it first)"; exit 1; }
[ -x "$CLIENT" ] || { echo "no $CLIENT (cmake --build $BUILD --target tridem_live_client)"; exit 1; }
read -r -a SIZE_LIST <<< "$SIZES"
read -r -a STEP_LIST <<< "$STEPS"
[ "${#SIZE_LIST[@]}" = "${#STEP_LIST[@]}" ] || { echo "SIZES and STEPS differ in length"; exit 1; }

# A lattice of about N equilateral triangles of edge 1 cm (gap 0.1) above a fixed floor.
write_scene() {  # N FILE
  python3 - "$1" "$2" "$BACKEND" <<'PY'
import math, sys
n, path, backend = int(sys.argv[1]), sys.argv[2], sys.argv[3]
size, gap = 0.01, 0.1
a = size * (1 + gap * math.sqrt(3))
side = math.sqrt(n * math.sqrt(3) / 4) * a   # a tile pair covers sqrt(3)/2 a^2
open(path, "w").write(f"""[simulation]
steps = 1000
gravity = [0.0, -9.81]
backend = "{backend}"
[output]
dir = "out"
every = 0
[[material]]
name = "sand"
density = 2650.0
penalty = 1e6
friction = 0.5
restitution = 0.37
[[triangle]]
material = "sand"
vertices = [[{-0.1*side}, -0.02], [{1.1*side}, -0.02], [{0.5*side}, -0.5]]
fixed = true
[[generate]]
kind = "lattice"
material = "sand"
region = [[0, 0], [{side}, {side}]]
size = {size}
gap = {gap}
""")
PY
}

rate() { sed -n 's/.* steps in .*: \([0-9.e+]*\) steps\/s.*/\1/p' "$1" | tail -1; }
json() { python3 -c "import json,sys;print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2" 2>/dev/null || echo "?"; }

LOAD_BEFORE=$(uptime)
{
  echo "# Live view benchmark, $(date +%F), backend $BACKEND, $HOST"
  echo
  echo "$TRIDEM; load before: $LOAD_BEFORE"
  echo
  echo "| triangles | steps | steps/s without --live | with --live, no client | with a client | overhead with a client | steps/s while watched | frames/s delivered | MB/s | stepping thread per frame, old path / now (ms, min of 20) | server thread per frame (ms, min) |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
} > "$OUT"
CHECKS=()
for k in "${!SIZE_LIST[@]}"; do
  N=${SIZE_LIST[$k]}; STEPS_N=${STEP_LIST[$k]}
  SCENE=$WORK/lattice_$N.toml
  write_scene "$N" "$SCENE"
  "$TRIDEM" run "$SCENE" --out "$WORK/plain_$N" --steps "$STEPS_N" --quiet > "$WORK/plain_$N.log"
  "$TRIDEM" run "$SCENE" --out "$WORK/idle_$N" --steps "$STEPS_N" --quiet --live "$PORT" > "$WORK/idle_$N.log"
  "$TRIDEM" run "$SCENE" --out "$WORK/watched_$N" --steps "$STEPS_N" --quiet --live "$PORT" > "$WORK/watched_$N.log" &
  RUN=$!
  until grep -q "live view on" "$WORK/watched_$N.log" 2>/dev/null; do
    kill -0 "$RUN" 2>/dev/null || { echo "the watched run did not start:"; cat "$WORK/watched_$N.log"; exit 1; }
    sleep 0.02
  done
  # The client watches until the run ends and the server closes.
  "$CLIENT" 127.0.0.1 "$PORT" 3600 120 > "$WORK/client_$N.json" || true
  wait $RUN
  PLAIN=$(rate "$WORK/plain_$N.log"); IDLE=$(rate "$WORK/idle_$N.log"); WATCHED=$(rate "$WORK/watched_$N.log")
  FPS=$(json "$WORK/client_$N.json" fps); MBS=$(json "$WORK/client_$N.json" mb_per_s)
  WINDOW=$(json "$WORK/client_$N.json" steps_per_s)
  OVER=$(python3 -c "print(f'{100*(1-$WATCHED/$PLAIN):.1f}')")
  TRI=$(sed -n 's/^tridem [^:]*: \([0-9]*\) triangles.*/\1/p' "$WORK/plain_$N.log")
  OLD_MS="?"; NEW_MS="?"; SERVER_MS="?"
  if [ -x "$COST" ] && "$COST" "$SCENE" 20 > "$WORK/cost_$N.json"; then
    OLD_MS=$(json "$WORK/cost_$N.json" old_stepping_ms_min); NEW_MS=$(json "$WORK/cost_$N.json" new_stepping_ms_min)
    SERVER_MS=$(json "$WORK/cost_$N.json" server_ms_min)
  fi
  echo "| $TRI | $STEPS_N | $PLAIN | $IDLE | $WATCHED | $OVER % | $WINDOW | $FPS | $MBS | $OLD_MS / $NEW_MS | $SERVER_MS |" >> "$OUT"
  cat "$WORK/client_$N.json"
  TARGET=$(case "$N" in 100000) echo 30;; 1000000) echo 5;; *) echo "";; esac)
  if [ -n "$TARGET" ]; then
    CHECKS+=("$(python3 -c "
fps, over, target = float('$FPS' if '$FPS' != '?' else 'nan'), float('$OVER'), $TARGET
met = lambda ok: 'met' if ok else 'NOT met'
print(f'$TRI triangles: {fps:.1f} frames/s (target >= {target}: {met(fps >= target)}); '
      f'stepping {over:.1f} % slower with a client (target <= 5 %: {met(over <= 5)})')")")
  fi
done
{
  echo
  echo "load after: $(uptime)"
  if [ "${#CHECKS[@]}" -gt 0 ]; then
    echo
    echo "Issue 18's targets:"
    for c in "${CHECKS[@]}"; do echo "- $c"; done
  fi
} >> "$OUT"
cat "$OUT"
echo "(logs in $WORK)"
