#!/usr/bin/env bash
# Issue 12's "the set-up and final outputs of a 10^7 run take under 5 s", on the GPU
# machine from a bundle (scripts/device_bundle.sh, carried as .devbin): a lattice of about
# N triangles of edge 1 m (gap 0.1) under gravity, run for STEPS steps on BACKEND and
# PRECISION with no frames, so its outputs are the step-0 log row, final.csv and bodies.csv.
# Prints tridem run's own lines (the "wall time:" line splits set-up, stepping and
# outputs), the command's wall time and peak memory, and the output sizes. Logs go to OUT.
#   bench/run_large_setup_on_device.sh OUT [N=1e7] [STEPS=20] [BACKEND=cuda] [PRECISION=float]
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"; n="${2:-1e7}"; steps="${3:-20}"
backend="${4:-cuda}"; precision="${5:-float}"
mkdir -p "$out"
# 993 082 triangles fill a 770 m square at this edge and gap; the side scales with sqrt(N).
side=$(python3 -c "print(round(770 * (float('$n') / 993082) ** 0.5, 3))")
scene="$out/lattice_$n.toml"
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
gap = 0.1

[output]
dir = "$out/run_$n"
TOML
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | tee "$out/gpu.txt"
nproc | sed 's/^/cores: /'
if [ -x /usr/bin/time ]; then
  /usr/bin/time -f 'command: %e s wall, %M kB peak resident' \
    "$root/.devbin/app/tridem" run "$scene" --quiet 2>&1 | tee "$out/run_$n.log"
else
  TIMEFORMAT='command: %R s wall'
  { time "$root/.devbin/app/tridem" run "$scene" --quiet; } 2>&1 | tee "$out/run_$n.log"
fi
ls -l "$out/run_$n" | awk 'NR > 1 {print $5, $9}'
rm -rf "$out/run_$n"/final.csv "$out/run_$n"/bodies.csv  # gigabytes: keep only the sizes
