#!/usr/bin/env bash
# Style and static checks on what a change touched, not on the whole tree (which predates
# .clang-format and is not reformatted): clang-format (.clang-format) on the changed lines
# of C++ and CUDA files, clang-tidy (.clang-tidy) on the changed C++ sources, with the
# headers they include. The change is measured from the merge base with origin/main (or
# main); on main itself, from the previous commit. Uncommitted changes count too.
#   scripts/run-lint.sh [BASE] [BUILD_DIR]      (BUILD_DIR holds compile_commands.json;
#                                                default build/)
set -euo pipefail
cd "$(dirname "$0")/.."
base="${1:-}"
build="${2:-build}"

pick() {  # the first of these programs that exists
  for p in "$@"; do command -v "$p" >/dev/null 2>&1 && { echo "$p"; return; }; done
  echo "lint: none of $* is installed (scripts/install-deps.sh installs them)" >&2
  exit 1
}
clang_format=$(pick clang-format-14 clang-format)
git_clang_format=$(pick git-clang-format-14 git-clang-format)
clang_tidy=$(pick clang-tidy-14 clang-tidy)

head=$(git rev-parse HEAD)
if [ -z "$base" ]; then
  for ref in origin/main main; do
    if git rev-parse -q --verify "$ref^{commit}" >/dev/null; then
      candidate=$(git merge-base HEAD "$ref")
      if [ "$candidate" != "$head" ]; then base=$candidate; break; fi
    fi
  done
fi
[ -n "$base" ] || base=$(git rev-parse -q --verify HEAD~1 || true)
if [ -z "$base" ]; then
  echo "lint: no earlier commit to compare with; nothing to check"
  exit 0
fi
echo "lint: changes since $(git rev-parse --short "$base")"

status=0
# clang-format: only the lines the change touched.
formatting=$("$git_clang_format" --binary "$clang_format" --diff --extensions cpp,hpp,cu,cuh \
  "$base" -- app src include tests bench 2>&1 || true)
case "$formatting" in
  "" | *"no modified files to format"* | *"did not modify any files"*)
    echo "lint: clang-format: the changed lines are formatted" ;;
  *)
    echo "$formatting"
    echo "lint: clang-format: the changed lines above differ from .clang-format's style;" \
         "fix them with: git clang-format $base"
    status=1 ;;
esac

# clang-tidy: the changed C++ sources that the build compiles.
commands="$build/compile_commands.json"
if [ ! -f "$commands" ]; then
  echo "lint: $commands is missing: configure the build first (cmake -S . -B $build)" >&2
  exit 1
fi
# The build is configured for g++: its GCC-only warning flags are not clang-tidy's business,
# nor is gcc's precompiled header, which clang cannot read (it would refuse the source):
# clang-tidy sees each source as written, without the forced include. The test sources
# compile in batches (tests/CMakeLists.txt, unity build): each gets its batch's command.
tidy_db=$(mktemp -d)
trap 'rm -rf "$tidy_db"' EXIT
python3 - "$commands" "$tidy_db/compile_commands.json" <<'PY'
import json, re, sys
entries = []
for e in json.load(open(sys.argv[1])):
    e["command"] = re.sub(r" -Winvalid-pch -include [^ ]*/cmake_pch\.hxx", "", e["command"])
    entries.append(e)
    if "/Unity/unity_" in e["file"]:
        for source in re.findall(r'^#include "([^"]+)"', open(e["file"]).read(), re.M):
            entries.append(dict(e, file=source, command=e["command"].replace(e["file"], source)))
json.dump(entries, open(sys.argv[2], "w"), indent=1)
PY
files=()
while IFS= read -r f; do
  [ -f "$f" ] && grep -qF "\"file\": \"$PWD/$f\"" "$tidy_db/compile_commands.json" && files+=("$f")
done < <(git diff --name-only --diff-filter=ACMR "$base" -- '*.cpp')
if [ ${#files[@]} -eq 0 ]; then
  echo "lint: clang-tidy: no changed C++ source to check"
else
  echo "lint: clang-tidy on ${#files[@]} changed file(s)"
  "$clang_tidy" -p "$tidy_db" --quiet --extra-arg=-Wno-unknown-warning-option "${files[@]}" ||
    status=1
fi
exit $status
