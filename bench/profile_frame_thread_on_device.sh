#!/usr/bin/env bash
# Where a 10^6 frame's time goes on the GPU machine's host (issue 12: on the H200 host the
# frame thread lags the steps when the contacts CSV is on, and its .vtp did not scale with
# the threads). The machine has no perf, so: the host's cores, memory and file systems; the
# bytes a second a file system takes (dd, with and without a flush to the disk); and
# `tridem_frame_bench ... parts` (a frame's parts and the VTK writer's phases: pack,
# compress, encode, write) at 16, 4 and 1 OpenMP threads, into /dev/shm and into the disk
# the checkout is on. One device call, from a bundle (scripts/device_bundle.sh).
#   bench/profile_frame_thread_on_device.sh OUT [N=1e6]     env: THREADS ("16 4 1")
set -uo pipefail
source "$(dirname "$0")/../scripts/device_env.sh"
out="${1:?give an output folder}"; n="${2:-1000000}"
mkdir -p "$out"
{
  nvidia-smi --query-gpu=name --format=csv,noheader
  echo "cores: $(nproc)"
  lscpu | grep -E 'Model name|^CPU\(s\)|Thread|Core|Socket|NUMA node|MHz' || true
  free -g
  df -h "$root" /tmp /dev/shm 2>&1
  mount | grep -E ' on (/|/tmp|/dev/shm|/work) ' || true
  echo "dirty_ratio $(cat /proc/sys/vm/dirty_ratio) dirty_background_ratio $(cat /proc/sys/vm/dirty_background_ratio)"
  echo "transparent huge pages: $(cat /sys/kernel/mm/transparent_hugepage/enabled 2>&1)"
} 2>&1 | tee "$out/host.txt"
disk="$root/.frame_disk"
mkdir -p "$disk"
echo "== dd 2 GiB of zeros (the last line of each: bytes a second)"
for dir in /dev/shm "$disk"; do
  for flush in none fdatasync; do
    opt=(); [ "$flush" = fdatasync ] && opt=(conv=fdatasync)
    echo "-- $dir, flush $flush: $(dd if=/dev/zero of="$dir/dd.bin" bs=1M count=2048 "${opt[@]}" 2>&1 | tail -1)"
    rm -f "$dir/dd.bin"
  done
done | tee "$out/dd.txt"
for dir in /dev/shm/frames "$disk/frames"; do
  for threads in ${THREADS:-16 4 1}; do
    log="$out/parts_$(basename "$(dirname "$dir")")_t$threads.md"
    OMP_NUM_THREADS=$threads timeout 120 "$root/.devbin/bench/tridem_frame_bench" "$n" 1000 3 \
      cuda "$dir" float parts >"$log" 2>&1
    echo "== parts into $dir, $threads threads (exit $?)"
    grep -E '^\| (grain|\.vtu|contacts|snapshot)' "$log"
    rm -rf "$dir"
  done
done
