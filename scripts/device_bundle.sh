#!/usr/bin/env bash
# Packs what the GPU machine needs to run tridem built here into .devbin/ (git-ignored;
# name it in the device tool's `carry`): the programs and every shared library they load
# except the C library's own, which the machine has in a newer version. The CUDA runtime is
# linked statically, so a recent driver is all the GPU side needs. The libraries go in
# lib.tar.xz (Gmsh's bring ~110 MiB, over the device's 64 MiB carry; xz makes them ~31 MiB),
# the programs in programs.tar.xz: scripts/device_unpack.sh, on the device, unpacks them.
#   scripts/device_bundle.sh [BUILD_DIR]      (default build/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
dest="$root/.devbin"
rm -rf "$dest"
mkdir -p "$dest/lib" "$dest/app" "$dest/bench" "$dest/tests"
cp "$build/app/tridem" "$dest/app/"
cp "$build/bench/tridem_bench" "$build/bench/tridem_paper_bench" "$dest/bench/"
# Tuning builds of the benchmark put beside it by hand (bench/compare_builds.sh NAME...).
for variant in "$build"/bench/tridem_bench_*; do
  if [ -x "$variant" ]; then cp "$variant" "$dest/bench/"; fi
done
# The live view's benchmark client (bench/live/run_live_bench.sh), where the build has it.
if [ -x "$build/bench/tridem_live_client" ]; then cp "$build/bench/tridem_live_client" "$dest/bench/"; fi
# The frame output benchmark (bench/frame_bench.cpp), where the build has it.
if [ -x "$build/bench/tridem_frame_bench" ]; then cp "$build/bench/tridem_frame_bench" "$dest/bench/"; fi
# The pile as a scene file for tridem run (bench/run_cli_vs_bench_on_device.sh), where the build has it.
if [ -x "$build/bench/tridem_write_pile_scene" ]; then cp "$build/bench/tridem_write_pile_scene" "$dest/bench/"; fi
# What numbering the particles by place again mid-run costs (bench/renumber), where built.
if [ -x "$build/bench/tridem_renumber_cost" ]; then cp "$build/bench/tridem_renumber_cost" "$dest/bench/"; fi
# What one live frame costs the stepping thread (bench/live/frame_cost.cpp), where built.
if [ -x "$build/bench/tridem_live_frame_cost" ]; then cp "$build/bench/tridem_live_frame_cost" "$dest/bench/"; fi
cp "$build/tests/tridem_tests" "$dest/tests/"
# And their test programs, where scripts/build_variant.sh made them (TESTS=1).
for variant in "$build"/tests/tridem_tests_*; do
  if [ -x "$variant" ]; then cp "$variant" "$dest/tests/"; fi
done
# The Gmsh module, which the programs dlopen from lib/tridem/ beside their directory.
gmsh_module="$build/lib/tridem/libtridem_gmsh.so"
for bin in "$dest"/app/tridem "$dest"/bench/tridem_bench "$dest"/bench/tridem_paper_bench "$dest"/tests/tridem_tests $([ -f "$gmsh_module" ] && echo "$gmsh_module"); do
  ldd "$bin" | awk '/=> \// {print $3}'
done | sort -u | grep -vE '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so' |
  while read -r lib; do cp -L "$lib" "$dest/lib/"; done
if [ -f "$gmsh_module" ]; then mkdir -p "$dest/lib/tridem" && cp "$gmsh_module" "$dest/lib/tridem/"; fi
# Stripped and packed too: the programs unstripped (some 50 MiB) and the libraries' 31 MiB
# went over the 64 MiB carry. scripts/device_unpack.sh, on the device, unpacks both.
strip --strip-unneeded "$dest"/app/* "$dest"/bench/* "$dest"/tests/* "$dest"/lib/*.so* \
  $([ -d "$dest/lib/tridem" ] && echo "$dest"/lib/tridem/*.so) 2>/dev/null || true
tar -C "$dest" -cf - lib | xz -T0 -6 >"$dest/lib.tar.xz"
tar -C "$dest" -cf - app bench tests | xz -T0 -6 >"$dest/programs.tar.xz"
rm -rf "$dest/lib" "$dest/app" "$dest/bench" "$dest/tests"
du -sh "$dest"
