#!/usr/bin/env bash
# A lever to measure, built beside the benchmark without touching the tree: PATCH (a unified
# diff against HEAD, as `git diff` writes it) applied to a copy of src/ and include/, the
# CUDA sources SOURCES (default the solver's, which instantiates the step kernels) compiled
# from that copy with the build's own compile commands, and tridem_bench linked against the
# build's library with those objects swapped in: BUILD/bench/tridem_bench_NAME, which
# scripts/device_bundle.sh carries and bench/compare_builds.sh measures against the others
# in one call (PATCH none: the build as it is, the A/B's baseline). A lever is kept in the
# tree only once measured (docs/performance.md).
# With TESTS=1 also BUILD/tests/tridem_tests_NAME, the test program with the lever.
# A patch that changes a header must name every CUDA source that includes it: the objects
# left unbuilt keep the old header, and a struct of two layouts in one program (an ODR
# violation) gives wrong numbers, not a build error. So a patch that touches a header is
# refused with the default SOURCES; name them (src/backends/cuda/*.cu for the device
# views, the particle fields or the buffers).
#   scripts/build_variant.sh NAME PATCH [SOURCE.cu ...]   env: BUILD (default build), TESTS
set -euo pipefail
name="${1:?give the variant a name}"
patch="${2:?give the lever as a patch, or none for the tree as it is}"
shift 2
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath "${BUILD:-$root/build}")"
sources=("$@")
if [ ${#sources[@]} -eq 0 ] && [ "$patch" != none ] &&
  grep -qE '^\+\+\+ b/.*\.(hpp|cuh|h)$' "$patch"; then
  echo "build_variant.sh: $patch changes a header; name every CUDA source that includes it" \
    "(e.g. src/backends/cuda/*.cu), or the objects not rebuilt keep the old one" >&2
  exit 2
fi
[ ${#sources[@]} -gt 0 ] || sources=(src/backends/cuda/cuda_solver.cu)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
git -C "$root" archive HEAD src include | tar -x -C "$work"
cp "$build/src/libtridem_core.a" "$work/libtridem_core.a"
if [ "$patch" = none ]; then sources=(); else patch -p1 -d "$work" --quiet <"$patch"; fi
for source in "${sources[@]}"; do
  object="$work/$(basename "$source").o"
  command="$(python3 - "$build/compile_commands.json" "$root/$source" "$root" "$work" "$object" <<'EOF'
import json, shlex, sys
commands, source, root, work, obj = sys.argv[1:]
for entry in json.load(open(commands)):
    if entry["file"] == source:
        words = shlex.split(entry["command"])
        out = []
        for k, w in enumerate(words):
            if k > 0 and words[k - 1] == "-o":
                w = obj
            w = w.replace(root + "/src", work + "/src").replace(root + "/include", work + "/include")
            out.append(w)
        print(entry["directory"] + "\n" + shlex.join(out))
        break
else:
    sys.exit(f"{source} is not in {commands}")
EOF
)"
  directory="$(head -1 <<<"$command")"
  (cd "$directory" && eval "$(tail -n +2 <<<"$command")")
  # The archive names its members by the object's file name: this replaces the build's one.
  (cd "$work" && ar r libtridem_core.a "$(basename "$object")")
done
relink() {  # TARGET (bench/tridem_bench, tests/tridem_tests): TARGET_NAME
  local link
  link="$(ninja -C "$build" -t commands "$1" | tail -1)"
  link="${link//src\/libtridem_core.a/$work/libtridem_core.a}"
  link="${link//-o $1 /-o $1_$name }"
  (cd "$build" && eval "$link")
  echo "built $build/$1_$name"
}
relink bench/tridem_bench
# The test program too (the state hashes and GPU tests of the lever), with TESTS=1.
if [ "${TESTS:-0}" = 1 ]; then relink tests/tridem_tests; fi
