#!/usr/bin/env bash
# The live view's benchmark (issue 18's targets): for 10^5 and 10^6 triangles, the frames
# per second the server delivers to a client (tridem_live_client, no browser) and the
# stepping rate of the run without --live, with --live and no client, and with a client
# asking for frames as fast as it gets them. Writes a Markdown table to bench/results/.
#   bench/live/run_live_bench.sh [BUILD_DIR]      (BACKEND=cuda by default; STEPS_1E5, STEPS_1E6)
set -euo pipefail
BUILD=${1:-build}
TRIDEM=${TRIDEM:-$BUILD/app/tridem}
CLIENT=${CLIENT:-$BUILD/bench/tridem_live_client}
BACKEND=${BACKEND:-cuda}
PORT=${PORT:-18765}
WORK=${WORK:-$(mktemp -d)}
HOST=$(hostname -s 2>/dev/null || echo host)
OUT=${OUT:-bench/results/live_$(date +%F)_${BACKEND}_${HOST}.md}
[ -x "$TRIDEM" ] || { echo "no $TRIDEM (build it first)"; exit 1; }
[ -x "$CLIENT" ] || { echo "no $CLIENT (cmake --build $BUILD --target tridem_live_client)"; exit 1; }

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

{
  echo "# Live view benchmark, $(date +%F), backend $BACKEND, $HOST"
  echo
  echo "| triangles | steps | steps/s without --live | with --live, no client | with a client | overhead with a client | frames/s delivered | MB/s |"
  echo "|---|---|---|---|---|---|---|---|"
} > "$OUT"
for N in 100000 1000000; do
  STEPS=$([ "$N" = 100000 ] && echo "${STEPS_1E5:-3000}" || echo "${STEPS_1E6:-600}")
  SCENE=$WORK/lattice_$N.toml
  write_scene "$N" "$SCENE"
  "$TRIDEM" run "$SCENE" --out "$WORK/plain_$N" --steps "$STEPS" --quiet > "$WORK/plain_$N.log"
  "$TRIDEM" run "$SCENE" --out "$WORK/idle_$N" --steps "$STEPS" --quiet --live "$PORT" > "$WORK/idle_$N.log"
  "$TRIDEM" run "$SCENE" --out "$WORK/watched_$N" --steps "$STEPS" --quiet --live "$PORT" > "$WORK/watched_$N.log" &
  RUN=$!
  until grep -q "live view on" "$WORK/watched_$N.log" 2>/dev/null; do sleep 0.1; done
  # The client watches until the run is nearly over (it stops with the server).
  "$CLIENT" 127.0.0.1 "$PORT" "${CLIENT_SECONDS:-20}" 120 > "$WORK/client_$N.json" || true
  wait $RUN
  PLAIN=$(rate "$WORK/plain_$N.log"); IDLE=$(rate "$WORK/idle_$N.log"); WATCHED=$(rate "$WORK/watched_$N.log")
  FPS=$(python3 -c "import json;print(json.load(open('$WORK/client_$N.json'))['fps'])" 2>/dev/null || echo "?")
  MBS=$(python3 -c "import json;print(json.load(open('$WORK/client_$N.json'))['mb_per_s'])" 2>/dev/null || echo "?")
  OVER=$(python3 -c "print(f'{100*(1-$WATCHED/$PLAIN):.1f} %')")
  TRI=$(sed -n 's/^tridem [^:]*: \([0-9]*\) triangles.*/\1/p' "$WORK/plain_$N.log")
  echo "| $TRI | $STEPS | $PLAIN | $IDLE | $WATCHED | $OVER | $FPS | $MBS |" >> "$OUT"
  cat "$WORK/client_$N.json"
done
cat "$OUT"
echo "(logs in $WORK)"
