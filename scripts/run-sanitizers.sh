#!/usr/bin/env bash
# Builds the whole CPU suite with AddressSanitizer + UndefinedBehaviorSanitizer in
# build-asan/ and runs it (GPU tests excluded): any leak, out-of-bounds access, overflow
# or other undefined behaviour fails the run. -O1 keeps the parity tests quick enough (not
# -O0 for the test sources: it halved their compile time but many tests step solvers in
# loops of their own: 534 s more test time in all, the suite 984 s of wall time, 2026-12-04);
# -g1 (line tables only) still gives each reported frame its file and line, and compiles
# a quarter faster than -g (a test source: 9.4 s against 12.8 s), objects half the size.
# Warnings are not errors here: with -fsanitize, gcc 12 warns falsely inside libstdc++
# (maybe-uninitialized in <regex>); the normal build keeps -Werror. MPI is left out: its
# tests are mpirun end to end (tests/mpi), and Open MPI's runtime keeps memory LSan reports.
# Executables are not position-independent here: ASan's descriptors of every global made
# the test binary carry 2.25 million relative relocations, which the loader applied at
# each of the suite's ~720 starts (0.42 s a start with the leak check; 0.25 s without
# them, 2026-12-04). Two sources long to compile and quick to run (the live view's
# Boost.Beast server, 95 s at -O1 against 48 s at -O0; the command line's main) are
# compiled at -O0 (TRIDEM_UNOPTIMISED_SOURCES).
set -euo pipefail
cd "$(dirname "$0")/.."
flags="-O1 -g1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined -no-pie" \
  -DTRIDEM_UNOPTIMISED_SOURCES="src/live/live_server.cpp;app/main.cpp" \
  -DTRIDEM_BUILD_BENCH=OFF -DTRIDEM_ENABLE_CUDA=OFF -DTRIDEM_WERROR=OFF -DTRIDEM_WITH_MPI=OFF >/dev/null
cmake --build build-asan
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Not the GPU tests, nor the longest validations (label long, tests/discovered_test_properties.cmake).
ctest --test-dir build-asan --output-on-failure -LE "gpu|long"
