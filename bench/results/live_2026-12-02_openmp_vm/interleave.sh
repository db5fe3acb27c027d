#!/usr/bin/env bash
# Interleaved repetitions: for each size and repetition, plain (new binary), --live idle and
# watched for the base and the new binary, one after another, so that the machine's load
# (other agents' builds) falls on all of them alike.
set -u
C=/work/wt-live-async/build/bench/tridem_live_client
cd /tmp/la_w
rate() { sed -n 's/.* steps in .*: \([0-9.e+]*\) steps\/s.*/\1/p' "$1" | tail -1; }
PORT=18900
for spec in "10000 s1e4.toml 4000" "100000 s1e5.toml 300"; do
  set -- $spec; N=$1; SCENE=$2; STEPS=$3
  for rep in 1 2 3; do
    for v in base new; do
      T=/tmp/la_$v/tridem
      D=/tmp/la_w/il/$N/$rep/$v; mkdir -p $D
      echo "uptime $(uptime)" > $D/uptime
      $T run $SCENE --out $D/plain --steps $STEPS --quiet > $D/plain.log 2>&1
      $T run $SCENE --out $D/idle --steps $STEPS --quiet --live $PORT > $D/idle.log 2>&1
      PORT=$((PORT+1))
      $T run $SCENE --out $D/watched --steps $STEPS --quiet --live $PORT > $D/watched.log 2>&1 &
      RUN=$!
      until grep -q "live view on" $D/watched.log 2>/dev/null; do sleep 0.02; done
      $C 127.0.0.1 $PORT 3600 120 > $D/client.json
      wait $RUN
      PORT=$((PORT+1))
      echo "$N rep $rep $v: plain $(rate $D/plain.log) idle $(rate $D/idle.log) watched $(rate $D/watched.log) client $(cat $D/client.json) | $(uptime | sed 's/.*load/load/')"
    done
  done
done
