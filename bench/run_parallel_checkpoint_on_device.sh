#!/usr/bin/env bash
# The ranks' checkpoint written side by side (docs/scaling.md, "Checkpoints") at 10^6
# triangles: one GPU rank, then 2 and 4 GPU ranks sharing the device's GPU, each writing a
# checkpoint every 10 of 20 steps; the checkpoints must equal one rank's byte for byte, and
# the ranks' summary says how long theirs took. Correctness and an order of magnitude only:
# the ranks share one GPU and one disk.
#   bench/run_parallel_checkpoint_on_device.sh OUT [N=1000000]
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}" n="${2:-1000000}"
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
tridem="$root/.devbin/app/tridem"
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader | sed 's/^/# /'
"$root/.devbin/bench/tridem_write_pile_scene" "$n" "$out/pile" 20 1000 double >/dev/null
sed -i '/^\[output\]/a checkpoint_every = 10' "$out/pile/scene.toml"
for np in 1 2 4; do
  start=$(date +%s.%N)
  if [ "$np" = 1 ]; then
    "$tridem" run "$out/pile/scene.toml" --backend cuda --out "$out/np1" >"$out/np1.log" 2>&1
  else
    mpirun --oversubscribe -np "$np" "$tridem" run "$out/pile/scene.toml" --backend cuda \
      --out "$out/np$np" >"$out/np$np.log" 2>&1
  fi
  code=$?
  end=$(date +%s.%N)
  echo "np $np: exit $code, $(awk -v a="$start" -v b="$end" "BEGIN{printf \"%.2f\", b - a}") s in all, checkpoint $(stat -c %s "$out/np$np/checkpoint.ckpt" 2>/dev/null) bytes"
  grep -o "[0-9]* checkpoints\? written by[^;]*" "$out/np$np.log"
  [ "$np" = 1 ] || { cmp "$out/np1/checkpoint.ckpt" "$out/np$np/checkpoint.ckpt" && echo "np $np: checkpoint equals one rank's"; }
done
grep -h -i "output\|set-up\|stepping" "$out/np1.log" | head -8
rm -rf "$out/pile" "$out"/np?/
