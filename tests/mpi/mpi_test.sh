#!/usr/bin/env bash
# MPI ranks against one rank (src/mpi/, docs/scaling.md), end to end through mpirun.
# usage: mpi_test.sh TRIDEM WORK_DIR MODE ARGS...
#   parity NP SCENE [tridem run options]: the output directory of NP ranks equals that of
#                  one rank byte for byte (final.csv, energy.csv, walls.csv, frames,
#                  contacts, checkpoint), the checkpoint written by the NP ranks
#   restart FROM TO SCENE STEPS: FROM ranks run to STEPS, TO ranks continue from its
#                  checkpoint to the scene's end; equal to one uninterrupted rank
#   blowup NP SCENE: the run fails on every rank, exit 1 with one message (the one-rank
#                  message), and last_good.ckpt, final.csv as one rank leaves them
#   refused NP PATTERN SCENE [tridem run options]: exit 1, one "error:" line, with PATTERN
#   checkpoint-fails NP SCENE: the checkpoint cannot be written: exit 1, one "error:" line
#                  naming the file
#   refused-without-gpu NP PATTERN SCENE [options]: refused, on a machine without a GPU
#                  (exit 77, skipped, where nvidia-smi lists one)
#   parity-without-gpu NP SCENE [options]: parity, on a machine without a GPU (skipped
#                  where nvidia-smi lists one)
# mpirun runs as root in CI (OMPI_ALLOW_RUN_AS_ROOT, set by CTest) and oversubscribes 2 cores.
set -u
tridem=$1 work=$2 mode=$3
shift 3
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
ranks() { local np=$1; shift; timeout 60 mpirun --oversubscribe -np "$np" "$tridem" "$@"; }

case "$mode" in
  parity)
    np=$1 scene=$2
    shift 2
    "$tridem" run "$scene" --out "$work/one" --quiet "$@" >"$work/one.log" 2>&1 ||
      fail "one rank: $(cat "$work/one.log")"
    ranks "$np" run "$scene" --out "$work/many" --quiet "$@" >"$work/many.log" 2>&1 ||
      fail "$np ranks: exit $? :: $(cat "$work/many.log")"
    if [ "$np" -gt 1 ]; then
      grep -q "solver $np ranks of" "$work/many.log" || fail "no '$np ranks' in the start line: $(head -3 "$work/many.log")"
      [ "$(grep -c '^tridem ' "$work/many.log")" = 1 ] || fail "the start line is not printed once"
      grep -q "first exchange .* GB/s" "$work/many.log" || fail "no measured bandwidth in the start line"
      # EXPECT_START: what the start line must say (how the ranks cut the scene, on what).
      [ -z "${EXPECT_START:-}" ] || grep -qF "$EXPECT_START" "$work/many.log" ||
        fail "the start line does not say '$EXPECT_START': $(head -3 "$work/many.log")"
      # Checkpoints are written by every rank, each its slice (mpi/parallel_checkpoint.cpp).
      if [ -f "$work/one/checkpoint.ckpt" ]; then
        grep -qE "checkpoints? written by the $np ranks side by side" "$work/many.log" ||
          fail "the checkpoint was not written by the $np ranks: $(grep plans "$work/many.log")"
      fi
    fi
    diff -r "$work/one" "$work/many" || fail "$np ranks differ from one rank"
    grep "plans" "$work/many.log"
    # EXPECT_OVERLAP=P: rank 0 computed its own pairs with the ghost exchange in flight on
    # more than 0 and at least P % of the steps; EXPECT_GHOST_CONTACTS=P: pairs on its
    # ghosts touched on at least P % of them (docs/scaling.md, "Overlap").
    if [ -n "${EXPECT_OVERLAP:-}${EXPECT_GHOST_CONTACTS:-}" ]; then
      counts=$(sed -nE 's/.*overlapped the ghost exchange with its own pairs on ([0-9]+) of ([0-9]+) steps.*touching on ([0-9]+)\).*/\1 \2 \3/p' "$work/many.log")
      [ -n "$counts" ] || fail "no overlap in the summary: $(grep plans "$work/many.log")"
      read -r overlapped steps touching <<<"$counts"
      [ "$overlapped" -gt 0 ] && [ $((100 * overlapped)) -ge $((${EXPECT_OVERLAP:-0} * steps)) ] ||
        fail "overlapped on $overlapped of $steps steps, expected ${EXPECT_OVERLAP:-0} % or more"
      [ $((100 * touching)) -ge $((${EXPECT_GHOST_CONTACTS:-0} * steps)) ] ||
        fail "pairs on ghosts touched on $touching of $steps steps, expected ${EXPECT_GHOST_CONTACTS:-0} % or more"
    fi
    echo "$np ranks: the output directory equals one rank's ($(find "$work/one" -type f | wc -l) files)"
    ;;
  restart)
    from=$1 to=$2 scene=$3 steps=$4
    "$tridem" run "$scene" --out "$work/one" --quiet >"$work/one.log" 2>&1 || fail "one rank: $(cat "$work/one.log")"
    ranks "$from" run "$scene" --out "$work/many" --quiet --steps "$steps" >"$work/a.log" 2>&1 ||
      fail "$from ranks: $(cat "$work/a.log")"
    ranks "$to" run "$scene" --out "$work/many" --quiet --restart "$work/many/checkpoint.ckpt" >"$work/b.log" 2>&1 ||
      fail "$to ranks from the checkpoint: $(cat "$work/b.log")"
    grep -q "continuing from .* at step $steps" "$work/b.log" || fail "no 'continuing from' line: $(cat "$work/b.log")"
    for f in final.csv energy.csv walls.csv checkpoint.ckpt; do
      cmp "$work/one/$f" "$work/many/$f" || fail "$f after $from ranks then $to differs from one rank"
    done
    diff -r "$work/one/frames" "$work/many/frames" || fail "frames differ"
    echo "$from ranks to step $steps, then $to ranks to the end: one rank's outputs"
    ;;
  blowup)
    np=$1 scene=$2
    shift 2
    "$tridem" run "$scene" --out "$work/one" --quiet "$@" >"$work/one.log" 2>"$work/one.err"
    [ $? = 1 ] || fail "one rank did not fail"
    ranks "$np" run "$scene" --out "$work/many" --quiet "$@" >"$work/many.log" 2>"$work/many.err"
    code=$?
    [ "$code" = 1 ] || fail "exit code $code, expected 1 (124: a rank hung) :: $(cat "$work/many.err")"
    [ "$(grep -c '^error: ' "$work/many.err")" = 1 ] || fail "not one message: $(cat "$work/many.err")"
    diff <(grep '^error: ' "$work/one.err") <(grep '^error: ' "$work/many.err") ||
      fail "the message differs from one rank's"
    for f in final.csv last_good.ckpt energy.csv; do
      cmp "$work/one/$f" "$work/many/$f" || fail "$f differs from one rank's"
    done
    echo "$np ranks stop with one rank's message: $(grep '^error: ' "$work/many.err" | cut -c1-120)"
    ;;
  checkpoint-fails)
    # The checkpoint's temporary file cannot be made (a directory is in its place, which
    # stops root too): every rank stops with one message naming it, none hangs.
    np=$1 scene=$2
    mkdir -p "$work/many/checkpoint.ckpt.tmp"
    ranks "$np" run "$scene" --out "$work/many" --quiet >"$work/many.log" 2>"$work/many.err"
    code=$?
    [ "$code" = 1 ] || fail "exit code $code, expected 1 (124: a rank hung) :: $(cat "$work/many.err")"
    [ "$(grep -c '^error: ' "$work/many.err")" = 1 ] || fail "not one message: $(cat "$work/many.err")"
    grep -q "checkpoint.ckpt.tmp" "$work/many.err" || fail "the message does not name the file: $(cat "$work/many.err")"
    [ ! -e "$work/many/checkpoint.ckpt" ] || fail "a checkpoint was left"
    echo "$np ranks stop with one message: $(grep '^error: ' "$work/many.err" | cut -c1-160)"
    ;;
  refused-without-gpu | parity-without-gpu)
    if nvidia-smi -L >/dev/null 2>&1; then echo "SKIP: this machine has a GPU"; exit 77; fi
    exec bash "$0" "$tridem" "$work" "${mode%-without-gpu}" "$@"
    ;;
  refused)
    np=$1 pattern=$2 scene=$3
    shift 3
    ranks "$np" run "$scene" --out "$work/many" --quiet "$@" >"$work/many.log" 2>"$work/many.err"
    code=$?
    [ "$code" = 1 ] || fail "exit code $code, expected 1 (124: a rank hung) :: $(cat "$work/many.err")"
    [ "$(grep -c '^error: ' "$work/many.err")" = 1 ] || fail "not one message: $(cat "$work/many.err")"
    grep -q -- "$pattern" "$work/many.err" || fail "'$pattern' not in: $(cat "$work/many.err")"
    echo "refused once: $(grep '^error: ' "$work/many.err" | cut -c1-160)"
    ;;
  *) fail "unknown mode $mode" ;;
esac
