#!/usr/bin/env bash
# Issue 12's "the set-up and final outputs of a 10^7 run take under 5 s", on the GPU
# machine from a bundle (scripts/device_bundle.sh, carried as .devbin): a lattice of about
# N triangles of edge 1 m (gap 0.1) under gravity, run for STEPS steps on BACKEND and
# PRECISION with no frames, so its outputs are the step-0 log row, final.csv and bodies.csv.
# Prints tridem run's own lines (the "wall time:" line splits set-up, stepping and
# outputs), the command's wall time and peak memory, the GPU memory `tridem info` estimates
# and the peak the GPU reports while it runs (nvidia-smi every 100 ms, less what was in use
# before), and the output sizes. Logs go to OUT.
#   bench/run_large_setup_on_device.sh OUT [N=1e7] [STEPS=20] [BACKEND=cuda] [PRECISION=float]
# env: GAP (between the lattice's triangles, default 0.1; 0: a touching lattice), TRIDEM (the
# program, default the bundle's), TAG (added to the log names).
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"; n="${2:-1e7}"; steps="${3:-20}"
backend="${4:-cuda}"; precision="${5:-float}"
gap="${GAP:-0.1}"; tridem="${TRIDEM:-$root/.devbin/app/tridem}"; tag="${TAG:-}"
mkdir -p "$out"
# 993 082 triangles fill a 770 m square at this edge and gap; the side scales with sqrt(N).
side=$(python3 -c "print(round(770 * (float('$n') / 993082) ** 0.5, 3))")
scene="$out/lattice_$n$tag.toml"
cat >"$scene" <<TOML
[simulation]
steps = $steps
gravity = [0, -9.81]
backend = "$backend"
precision = "$precision"

[[material]]
name = "rock"
density = 2500
penalty = 1e9
friction = 0.5

[[generate]]
kind = "lattice"
material = "rock"
region = [[0, 0], [$side, $side]]
size = 1
gap = $gap

[output]
dir = "$out/run_$n$tag"
TOML
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee "$out/gpu.txt"
nproc | sed 's/^/cores: /'
log="$out/run_$n$tag.log"
"$tridem" info "$scene" | grep -E '^(triangles|gpu memory)' | tee "$log.info"
gpu_watch_start "$log.gpu_mem"
if [ -x /usr/bin/time ]; then
  /usr/bin/time -f 'command: %e s wall, %M kB peak resident' \
    "$tridem" run "$scene" --quiet 2>&1 | tee "$log"
else
  TIMEFORMAT='command: %R s wall'
  { time "$tridem" run "$scene" --quiet; } 2>&1 | tee "$log"
fi
gpu_watch_peak "$log.gpu_mem" | tee -a "$log"
ls -l "$out/run_$n$tag" | awk 'NR > 1 {print $5, $9}'
rm -rf "$out/run_$n$tag"  # final.csv and bodies.csv are gigabytes: keep only the sizes
