#!/usr/bin/env bash
# End-to-end checks of the command line: outputs, exit codes and messages.
# usage: cli_test.sh TRIDEM SOURCE_DIR WORK_DIR [HAVE_CUDA]
set -u
tridem=$1 src=$2 work=$3 have_cuda=${4:-0}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_ok() { "$@" >out.txt 2>err.txt || fail "exit $? from: $* :: $(cat err.txt)"; }
# expect_error PATTERN CMD...: exit code 1 (the README's promise for every refusal, usage
# errors included), one "error: " message, and PATTERN in it.
expect_error() {
  local pattern=$1; shift
  "$@" >out.txt 2>err.txt
  local code=$?
  [ "$code" = 1 ] || { fail "exit code $code, expected 1, from: $* :: $(cat err.txt)"; return; }
  head -n 1 err.txt | grep -q "^error: " || fail "the message of: $* does not start with 'error: ' :: $(cat err.txt)"
  grep -q -- "$pattern" err.txt || fail "'$pattern' not in the message of: $* :: $(cat err.txt)"
}

cat >pile.toml <<'TOML'
[simulation]
steps = 200
gravity = [0, -9.81]
[output]
dir = "pile_out"
every = 100
[[material]]
name = "sand"
density = 2650
penalty = 1e6
friction = 0.5
damping = 0.3
[[triangle]]
material = "sand"
vertices = [[1, 0], [-1, 0], [0, -1]]
fixed = true
[[generate]]
kind = "random"
material = "sand"
region = [[-0.5, 0.001], [0.5, 0.3]]
size = 0.05
TOML

# A run writes every output, with the contract headers.
expect_ok "$tridem" run pile.toml --quiet
grep -q "^dt = .* x dt_crit" out.txt || fail "run does not print dt and its ratio"
grep -q "^dt_crit set by particle" out.txt || fail "run does not say what sets dt_crit"
grep -q "triangle-steps/s" out.txt || fail "run does not print the summary"
[ "$(head -1 pile_out/final.csv)" = "id,x,y,theta,vx,vy,omega,x1,y1,x2,y2,x3,y3,body" ] || fail "final.csv header"
[ "$(head -1 pile_out/bodies.csv)" = "id,x,y,theta,vx,vy,omega,mass,inertia,members" ] || fail "bodies.csv header"
[ "$(wc -l <pile_out/bodies.csv)" = "$(wc -l <pile_out/final.csv)" ] || fail "bodies.csv: not one row per triangle without bodies"
[ "$(head -1 pile_out/energy.csv)" = "step,time,kinetic,momentum_x,momentum_y,angular_momentum,potential,elastic,dissipated_damping,dissipated_friction,dissipated_local,wall_work,total,dissipated_fracture" ] || fail "energy.csv header"
[ "$(head -1 pile_out/walls.csv)" = "step,time,id,fx,fy,torque,x,y,vx,vy" ] || fail "walls.csv header"
[ "$(cut -d, -f1 pile_out/energy.csv | tail -n +2 | tr '\n' ' ')" = "0 100 200 " ] || fail "energy.csv steps"
for f in frames/frame_000000000.vtu frames/frame_000000100.vtu frames/frame_000000200.vtu tridem.pvd \
         contacts/contacts_000000200.csv; do
  [ -s "pile_out/$f" ] || fail "missing output $f"
done
n=$(($(wc -l <pile_out/final.csv) - 1))
[ "$n" -gt 10 ] || fail "final.csv has $n rows"

# --out, --steps and --backend override the scene.
expect_ok "$tridem" run pile.toml --quiet --out other --steps 10 --backend cpu
grep -q "cpu (serial)" out.txt || fail "--backend cpu not used"
[ "$(cut -d, -f1 other/energy.csv | tail -1)" = "10" ] || fail "--steps not used"

# --method overrides the scene's; a method's settings are checked against the one run.
expect_ok "$tridem" run pile.toml --quiet --out all_pairs --steps 5 --method all-pairs
grep -q "all-pairs" out.txt || fail "--method all-pairs not used"
expect_ok "$tridem" run pile.toml --quiet --out single --steps 5 --backend cpu --method single-domain \
  --contact-test direct-area --no-bbox-prefilter
grep -q "single-domain (contact test direct-area, bbox pre-filter off)" out.txt ||
  fail "--method single-domain --contact-test direct-area --no-bbox-prefilter not used"
expect_ok "$tridem" run pile.toml --quiet --out decomposition --steps 5 --method decomposition --backend cpu
grep -q "decomposition: .* sub-domains" out.txt || fail "--method decomposition: no sub-domains in the summary"
sed 's/^\[output\]/[simulation.decomposition]\ncapacity = 2\n[output]/' pile.toml >tight.toml
expect_error "more than the capacity 2 of one sub-domain" "$tridem" run tight.toml --quiet --steps 5 --out tight \
  --method decomposition --backend cpu
expect_error "contact_test" "$tridem" run pile.toml --quiet --steps 5 --contact-test direct-area
expect_error "bbox_prefilter" "$tridem" run pile.toml --quiet --steps 5 --no-bbox-prefilter

# [output] vtk_encoding = "ascii" writes text frames, which render reads too.
sed 's/every = 100/every = 100\nvtk_encoding = "ascii"/' pile.toml >ascii.toml
expect_ok "$tridem" run ascii.toml --quiet --out ascii_out --steps 100
grep -q 'format="ascii"' ascii_out/frames/frame_000000100.vtu || fail "vtk_encoding = ascii not used"
grep -q 'format="binary"' pile_out/frames/frame_000000100.vtu || fail "frames are not binary by default"
expect_ok "$tridem" render ascii_out/frames/frame_000000100.vtu -o ascii.png

# [output] frame_arrays: a frame without velocities is not drawn by speed (the message
# says what to draw instead), by material it is; `tridem view` refuses to replay it.
sed 's/every = 100/every = 100\nframe_arrays = ["force"]\ncontact_arrays = ["force"]/' pile.toml >lean.toml
expect_ok "$tridem" run lean.toml --quiet --out lean_out --steps 100
grep -q 'Name="velocity"' lean_out/frames/frame_000000100.vtu && fail "frame_arrays left velocity in"
grep -q 'Name="depth"' lean_out/contacts/contacts_000000100.vtp && fail "contact_arrays left depth in"
expect_error "--color material" "$tridem" render lean_out -o lean.png
expect_ok "$tridem" render lean_out -o lean.png --color material
expect_error "no velocity array" "$tridem" view lean_out --port 0

# Output events every step: the run must reach its end (it stalled at step 63, when the
# chunk length, doubled at every event, overflowed).
sed 's/every = 100/every = 1\ncontacts = false/' pile.toml >every1.toml
expect_ok timeout 60 "$tridem" run every1.toml --quiet --out every1_out
[ "$(cut -d, -f1 every1_out/energy.csv | tail -1)" = "200" ] || fail "run with every = 1 stalled"

# info describes the scene.
expect_ok "$tridem" info pile.toml
grep -q "dt critical" out.txt || fail "info lacks dt critical"
grep -q "dt critical .* set by particle" out.txt || fail "info does not say what sets dt critical"
grep -q "memory" out.txt || fail "info lacks memory"
# A run given by its simulated time: info prints the steps it takes (it printed 0).
sed 's/^steps = .*/time = 1e-3/' pile.toml >timed.toml
expect_ok "$tridem" info timed.toml
grep -qE "^steps        [1-9][0-9]* \(t = 0.001" out.txt || fail "info of a timed run: $(grep ^steps out.txt)"
# info lists the [[measure]] tables (region, file, cadence) and the periodic cell.
cp pile.toml measured.toml
sed -i 's/^gravity = .*/gravity = [0, -9.81]\nperiodic_x = [-1, 1]/' measured.toml
printf '[[measure]]\nname = "core"\nregion = [[-0.5, 0], [0.5, 0.5]]\nevery = 50\n[[measure]]\nname = "all"\n' >>measured.toml
expect_ok "$tridem" info measured.toml
grep -q "^measures     2" out.txt || fail "info does not count the measures: $(cat out.txt)"
grep -qE "^  core +region \[-0.5, 0.5\] x \[0, 0.5\] m -> measure_core.csv, every 50 steps" out.txt ||
  fail "info lacks the region measure: $(grep -A2 ^measures out.txt)"
grep -qE "^  all +the whole domain .* -> measure_all.csv, every 100 steps" out.txt ||
  fail "info lacks the whole-domain measure: $(grep -A2 ^measures out.txt)"
grep -q "^periodic     x in \[-1, 1)" out.txt || fail "info lacks the periodic cell: $(cat out.txt)"
if [ "$have_cuda" = 1 ]; then
  grep -q "gpu memory   about" out.txt || fail "info lacks the GPU memory of the cuda backend"
fi
grep -Eq "^pairs        about [0-9]+ in the first list" out.txt || fail "info lacks the first list's pairs"
grep -Eq "^numbering    ids i and i \+ 1 [0-9.]+ grain sizes apart on average, [0-9.]+ of two scrambled ids' distance \(a scene this small keeps its data in the caches" out.txt ||
  fail "info lacks how the pile's particles are numbered: $(grep ^numbering out.txt)"

# render draws the last frame to PNG.
expect_ok "$tridem" render pile_out -o pile.png
[ "$(head -c 8 pile.png | od -An -c | tr -d ' ')" = "211PNG\r\n032\n" ] || fail "render did not write a PNG"
expect_ok "$tridem" render pile_out -o pile_bodies.png --color body
[ "$(head -c 8 pile_bodies.png | od -An -c | tr -d ' ')" = "211PNG\r\n032\n" ] || fail "render --color body did not write a PNG"

# Many output events (one per step) must not stall the time loop (it once did after 63).
sed 's/every = 100/every = 1/' pile.toml >every_step.toml
expect_ok timeout 120 "$tridem" run every_step.toml --quiet --steps 150 --out every_out
[ "$(ls every_out/frames/*.vtu 2>/dev/null | wc -l)" -eq 151 ] || fail "every = 1 did not write 151 frames"

# Refusals: a message naming the cause, exit code 1.
sed 's/penalty = 1e6/penalty = -5/' pile.toml >bad_penalty.toml
expect_error "bad_penalty.toml" "$tridem" run bad_penalty.toml
expect_error "penalty" "$tridem" run bad_penalty.toml
sed 's/steps = 200/steps = 200\ndt = 1.0/' pile.toml >big_dt.toml
expect_error "dt_crit" "$tridem" run big_dt.toml --quiet
sed 's/steps = 200/steps = 3\ndt = 1e-3/' pile.toml >forced.toml
expect_ok "$tridem" run forced.toml --quiet --force --out forced_out
# The CUDA backend runs where a GPU is, and says why not elsewhere.
if nvidia-smi -L >/dev/null 2>&1; then
  expect_ok "$tridem" run pile.toml --backend cuda --quiet --out cuda_out
  grep -q "solver cuda" out.txt || fail "--backend cuda did not report the cuda solver"
  # The GPU is the caller's choice: the last one listed works, one past it is refused.
  gpus=$(nvidia-smi -L | grep -c '^GPU')
  expect_ok "$tridem" run pile.toml --backend cuda --device $((gpus - 1)) --quiet --out device_out
  expect_error "--device $gpus is not a GPU of this machine" \
    "$tridem" run pile.toml --backend cuda --device "$gpus" --quiet --out device_out
else
  expect_error "not available" "$tridem" run pile.toml --backend cuda
  expect_error "not available" "$tridem" run pile.toml --backend cuda --device 1
fi
expect_error "backend is cpu" "$tridem" run pile.toml --quiet --steps 5 --backend cpu --device 1 --out device_out
expect_error "at least 0, got '-1'" "$tridem" run pile.toml --device -1
expect_error "no scene file 'does_not_exist.toml'" "$tridem" run does_not_exist.toml
expect_error "no-such-option" "$tridem" run pile.toml --no-such-option
expect_error "subcommand" "$tridem" bogus
expect_error "at least 1, got '0'" "$tridem" run pile.toml --steps 0
grep -q "[0-9]\{40\}" err.txt && fail "--steps 0: the message prints a huge number :: $(cat err.txt)"
expect_error "backend is cpu" "$tridem" run pile.toml --quiet --steps 5 --backend cpu --threads 2 --out threads_out
# --particle-order place: the solver keeps the generated grains numbered by place, says so,
# and writes final.csv in the scene's ids and order (the default run of this small scene
# keeps the scene's order; positions within rounding: the sums run in another order).
expect_ok "$tridem" run pile.toml --quiet --particle-order place --out place_out
grep -q "particles numbered by place" out.txt || fail "--particle-order place: the start line does not say so :: $(head -1 out.txt)"
[ "$(cut -d, -f1 place_out/final.csv)" = "$(cut -d, -f1 pile_out/final.csv)" ] || fail "--particle-order place: final.csv ids differ"
paste -d, pile_out/final.csv place_out/final.csv | tail -n +2 |
  awk -F, -v m=14 '{ for (c = 2; c <= 3; ++c) { d = $c - $(c + m); if (d > 1e-9 || d < -1e-9) { print; exit 1 } } }' >place_diff.txt ||
  fail "--particle-order place: final.csv positions differ beyond rounding: $(cat place_diff.txt)"
expect_ok "$tridem" run pile.toml --quiet --particle-order scene --steps 5 --out scene_order_out
grep -q "numbered by place" out.txt && fail "--particle-order scene: the solver renumbered"
expect_error "particle-order" "$tridem" run pile.toml --particle-order nowhere
# Generated polygons (bodies), 1.4x10^5 triangles in their placement order: tridem info
# and tridem run (auto) say the solver numbers them by place, and it does.
sed -e 's/^steps = 200/steps = 2/' -e 's/^every = 100/every = 0/' \
    -e 's/^kind = "random"/kind = "polygons"\nsides = [5, 8]\npacking_fraction = 0.5\nseed = 3/' \
    -e 's/^region = .*/region = [[-1, 0.001], [1, 1.2]]/' -e 's/^size = 0.05/size = [0.006, 0.009]/' \
    -e 's/vertices = \[\[1, 0\], \[-1, 0\], \[0, -1\]\]/vertices = [[1.1, 0], [-1.1, 0], [0, -1]]/' \
    pile.toml >polygons.toml
expect_ok "$tridem" info polygons.toml
grep -q "^numbering .*tridem run numbers them by place inside the solver" out.txt ||
  fail "info does not say that run numbers the polygons by place: $(grep ^numbering out.txt)"
expect_ok "$tridem" run polygons.toml --quiet --out polygons_out
grep -q "particles numbered by place" out.txt || fail "auto did not number the polygons by place :: $(head -1 out.txt)"
grep -q "^note: .*the solver keeps them numbered by place" out.txt || fail "run does not note the numbering"
[ "$(head -1 polygons_out/bodies.csv)" = "id,x,y,theta,vx,vy,omega,mass,inertia,members" ] || fail "polygons: bodies.csv header"
expect_error "folder 'missing/dir' does not exist" "$tridem" render pile_out -o missing/dir/x.png
"$tridem" --version | grep -q "^tridem [0-9]" || fail "--version"
"$tridem" --help | grep -q "run" || fail "--help"

# A blow-up names the step and the particle: a grain thrown at another with a step far too
# large (initially overlapping grains are refused when the scene is read).
cat >blowup.toml <<'TOML'
[simulation]
steps = 100
dt = 1e-2
[[material]]
name = "m"
density = 1000
penalty = 1e9
[[triangle]]
material = "m"
vertices = [[0, 0], [1, 0], [0, 1]]
[[triangle]]
material = "m"
vertices = [[1.05, 0], [2.05, 0], [1.05, 1]]
velocity = [-40, 0]
TOML
expect_error "blow-up at step" "$tridem" run blowup.toml --force --quiet --out blow_out
grep -q "particle" err.txt || fail "blow-up message does not name the particle"

grep -q "last_good.ckpt" err.txt || fail "blow-up message does not name the last good state"
[ -s blow_out/last_good.ckpt ] || fail "blow-up did not keep the last good state"

# Checkpoints: a run cut in two by --restart ends with the same files as a straight one.
sed 's/every = 100/every = 100\ncheckpoint_every = 100/' pile.toml >ckpt.toml
expect_ok "$tridem" run ckpt.toml --quiet --backend cpu --out straight
expect_ok "$tridem" run ckpt.toml --quiet --backend cpu --out halves --steps 100
expect_ok "$tridem" run ckpt.toml --quiet --backend cpu --out halves --restart halves/checkpoint.ckpt
grep -q "continuing from halves/checkpoint.ckpt at step 100" out.txt || fail "restart does not say where it starts"
for f in final.csv energy.csv walls.csv tridem.pvd frames/frame_000000200.vtu; do
  cmp -s "straight/$f" "halves/$f" || fail "restarted run differs from the straight one in $f"
done
# A checkpoint cut short, damaged, or of another scene is refused with a message.
head -c 100 straight/checkpoint.ckpt >cut.ckpt
expect_error "truncated" "$tridem" run ckpt.toml --quiet --out refused --restart cut.ckpt
cp straight/checkpoint.ckpt flipped.ckpt
printf '\x55' | dd of=flipped.ckpt bs=1 seek=200 conv=notrunc 2>/dev/null
expect_error "corrupt" "$tridem" run ckpt.toml --quiet --out refused --restart flipped.ckpt
sed 's/density = 2650/density = 2600/' ckpt.toml >lighter.toml
expect_error "another scene" "$tridem" run lighter.toml --quiet --out refused --restart straight/checkpoint.ckpt

# Ctrl-C (SIGINT) and kill (SIGTERM) stop a long run at a step boundary with a checkpoint,
# exit 128 + signal, and say how to go on; the run then continues from it.
sed 's/steps = 200/steps = 100000000/; s/\[1, 0\], \[-1, 0\], \[0, -1\]/[10, 0], [-10, 0], [0, -10]/' ckpt.toml >long.toml
# The INT run has overrides of the physics: the printed command must carry them all.
overrides_INT="--method single-domain --contact-test exact --no-bbox-prefilter"
overrides_TERM=""
# A background job of a script ignores SIGINT until the program installs its handler,
# which it does before the run prints its first line: a signal sent sooner (a fixed
# sleep, on a loaded machine) is lost and the run goes on for its 10^8 steps.
wait_for_start() {
  for _ in $(seq 600); do
    [ -s out.txt ] && return 0
    kill -0 "$1" 2>/dev/null || fail "the run ended before it was signalled :: $(cat err.txt)"
    sleep 0.1
  done
  kill -KILL "$1"; fail "the run printed nothing in 60 s :: $(cat err.txt)"
}
# The program restarts itself once with huge pages asked of the C library (and passive
# OpenMP waits), unless the user's GLIBC_TUNABLES names that setting (app/startup_environment).
tunables_INT=""
tunables_TERM="glibc.malloc.hugetlb=0"
expected_tunables_INT="glibc.malloc.hugetlb=1"
expected_tunables_TERM="glibc.malloc.hugetlb=0"
for sig in INT TERM; do
  overrides=overrides_$sig
  tunables=tunables_$sig
  expected_tunables=expected_tunables_$sig
  # shellcheck disable=SC2086
  GLIBC_TUNABLES="${!tunables}" "$tridem" run long.toml --quiet --backend cpu --out "long_$sig" ${!overrides} >out.txt 2>err.txt &
  pid=$!
  wait_for_start "$pid"
  if [ -r "/proc/$pid/environ" ]; then
    environment=$(tr '\0' '\n' <"/proc/$pid/environ")
    grep -qx "GLIBC_TUNABLES=${!expected_tunables}" <<<"$environment" ||
      fail "SIG$sig run: GLIBC_TUNABLES is not ${!expected_tunables} :: $(grep GLIBC_TUNABLES <<<"$environment")"
    grep -qx "OMP_WAIT_POLICY=passive" <<<"$environment" || fail "SIG$sig run: OpenMP waits are not passive"
  fi
  kill -"$sig" "$pid"
  wait "$pid"
  code=$?
  expected=130; [ "$sig" = TERM ] && expected=143
  [ "$code" = "$expected" ] || fail "SIG$sig: exit code $code, expected $expected :: $(cat err.txt)"
  grep -q -- "--restart long_$sig/checkpoint.ckpt" err.txt || fail "SIG$sig: no restart advice :: $(cat err.txt)"
  [ -s "long_$sig/checkpoint.ckpt" ] && [ -s "long_$sig/final.csv" ] || fail "SIG$sig: no checkpoint or final.csv"
  for option in ${!overrides}; do
    grep -q -- "continue with: .*$option" err.txt || fail "SIG$sig: restart advice drops $option :: $(cat err.txt)"
  done
  cp err.txt "err_$sig.txt"
done
# The checkpoint holds the physics settings: a restart without the overrides is refused
# naming both values; the printed command continues the run.
expect_error "method = single-domain, this run has grid" "$tridem" run long.toml --quiet --backend cpu --out long_INT --restart long_INT/checkpoint.ckpt
stopped=$(sed -n 's/.* at step \([0-9]*\):.*/\1/p' err_INT.txt)
continue_INT=$(sed -n 's/^continue with: //p' err_INT.txt)
eval "$continue_INT --steps $((stopped + 50))" >out.txt 2>err.txt || fail "the printed restart command failed :: $continue_INT :: $(cat err.txt)"
[ "$(cut -d, -f1 long_INT/energy.csv | tail -1)" = "$((stopped + 50))" ] || fail "the printed restart command did not continue the SIGINT run to its end"
stopped=$(sed -n 's/.* at step \([0-9]*\):.*/\1/p' err_TERM.txt)
expect_ok "$tridem" run long.toml --quiet --backend cpu --out long_TERM --restart long_TERM/checkpoint.ckpt --steps $((stopped + 100))
[ "$(cut -d, -f1 long_TERM/energy.csv | tail -1)" = "$((stopped + 100))" ] || fail "run interrupted by SIGTERM did not continue to its end"

# The same guarantees on the GPU, where there is one.
if nvidia-smi -L >/dev/null 2>&1; then
  expect_ok "$tridem" run ckpt.toml --quiet --backend cuda --out gpu_straight
  expect_ok "$tridem" run ckpt.toml --quiet --backend cuda --out gpu_halves --steps 100
  expect_ok "$tridem" run ckpt.toml --quiet --backend cuda --out gpu_halves --restart gpu_halves/checkpoint.ckpt
  for f in final.csv energy.csv walls.csv tridem.pvd frames/frame_000000200.vtu; do
    cmp -s "gpu_straight/$f" "gpu_halves/$f" || fail "restarted GPU run differs from the straight one in $f"
  done
  "$tridem" run long.toml --quiet --backend cuda --out long_gpu >out.txt 2>err.txt &
  pid=$!
  wait_for_start "$pid"
  kill -INT "$pid"
  wait "$pid"
  code=$?
  [ "$code" = 130 ] || fail "GPU SIGINT: exit code $code, expected 130 :: $(cat err.txt)"
  [ -s long_gpu/checkpoint.ckpt ] && [ -s long_gpu/final.csv ] || fail "GPU SIGINT: no checkpoint or final.csv"
  stopped=$(sed -n 's/.* at step \([0-9]*\):.*/\1/p' err.txt)
  expect_ok "$tridem" run long.toml --quiet --backend cuda --out long_gpu --restart long_gpu/checkpoint.ckpt --steps $((stopped + 100))
  [ "$(cut -d, -f1 long_gpu/energy.csv | tail -1)" = "$((stopped + 100))" ] || fail "GPU run interrupted by SIGINT did not continue to its end"
  expect_error "blow-up at step" "$tridem" run blowup.toml --force --quiet --backend cuda --out gpu_blow_out
  [ -s gpu_blow_out/last_good.ckpt ] || fail "GPU blow-up did not keep the last good state"
fi

if [ "$failures" -gt 0 ]; then echo "$failures failed"; exit 1; fi
echo "all CLI checks passed"
