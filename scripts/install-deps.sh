#!/usr/bin/env bash
# Installs tridem's build dependencies from Debian's packages (Debian 12 or newer,
# Ubuntu 24.04). Runs apt-get through sudo when not root.
#   scripts/install-deps.sh [all|build|tools]   (default all)
# build: what configuring and building needs; tools: what only the tests, the fuzzers and
# the lint need (a browser, ffmpeg, clang), which CI installs while it builds (.ci/run).
set -euo pipefail
group=${1:-all}
case "$group" in all | build | tools) ;; *)
  echo "usage: scripts/install-deps.sh [all|build|tools]" >&2; exit 2 ;; esac
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
if [ "$group" != tools ]; then
$SUDO apt-get install -y -qq --no-install-recommends \
  cmake ninja-build g++ pkg-config \
  libtomlplusplus-dev libcli11-dev libfmt-dev libcairo2-dev \
  libgtest-dev libgmock-dev libbenchmark-dev libcgal-dev libgmsh-dev libboost-dev \
  libopenmpi-dev openmpi-bin zlib1g-dev liblzma-dev libdeflate-dev
fi
[ "$group" != build ] || exit 0
# The live view's browser test (tests/browser: headless chromium through selenium) and
# `tridem render --movie` (the ffmpeg program).
$SUDO apt-get install -y -qq --no-install-recommends \
  chromium chromium-driver python3-selenium ffmpeg
# The frames' check with VTK's own readers (tests/paraview).
$SUDO apt-get install -y -qq --no-install-recommends python3-vtk9
# The experiments' curves and pictures (scripts/biaxial_curves.py, shear_flow_mu_i.py,
# drum_angle.py, hopper_gate_plot.py; docs/experiments.md).
$SUDO apt-get install -y -qq --no-install-recommends python3-numpy python3-matplotlib
# The fuzz build (scripts/run-fuzzers.sh): clang with libFuzzer and its sanitizer
# runtimes, and clang's OpenMP.
$SUDO apt-get install -y -qq --no-install-recommends \
  clang-14 libclang-rt-14-dev libomp-14-dev
# The style and static checks of a change (scripts/run-lint.sh, .clang-format, .clang-tidy).
$SUDO apt-get install -y -qq --no-install-recommends \
  clang-format-14 clang-tidy-14
