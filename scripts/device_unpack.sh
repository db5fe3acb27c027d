#!/usr/bin/env bash
# On the GPU machine: unpacks the libraries scripts/device_bundle.sh packed into
# .devbin/lib.tar.xz and the programs of .devbin/programs.tar.xz, once (a warm machine
# keeps them).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
if [ -f "$root/.devbin/lib.tar.xz" ] && [ ! -d "$root/.devbin/lib" ]; then
  tar -C "$root/.devbin" -xJf "$root/.devbin/lib.tar.xz"
fi
if [ -f "$root/.devbin/programs.tar.xz" ] && [ ! -d "$root/.devbin/tests" ]; then
  tar -C "$root/.devbin" -xJf "$root/.devbin/programs.tar.xz"
fi
