#!/usr/bin/env bash
# From a fresh checkout: install the dependencies and build everything (Release) in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release ${TRIDEM_CMAKE_ARGS:-}
cmake --build build
