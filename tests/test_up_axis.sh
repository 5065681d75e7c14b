#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The up axis end to end, one mode per CTest test:
#   test_up_axis.sh MODE BUILD_DIR SOURCE_DIR SHARED_MODELS_DIR
# cli:   seamwalk-pack build's defaults per input, --up, a scene's up_axis, the
#        warning for inputs that differ, info (text and --json), and packs
#        from before the ORIENTATION section.
# orbit: seamwalk --orbit shows z-up STEP parts upright: a tall part (the
#        screw) is taller than wide in every frame, a flat one (the NIST
#        plate) wider than tall; with --up y the same screw lies on its side,
#        as every STEP part did before packs had an up axis.
# Exit 77 means skipped.
set -uo pipefail
mode=$1 shared=$4
# Absolute, since the scenes written below name the samples from their folder.
build=$(cd "$2" && pwd) src=$(cd "$3" && pwd)
tool=$build/assets/seamwalk-pack
walker=$build/firmware/seamwalk
compare=$build/tests/image_compare
samples=$src/assets/samples
export LSAN_OPTIONS="suppressions=$src/tests/occt-lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
work=$build/tests/up_axis_$mode
rm -rf "$work" && mkdir -p "$work"
failures=0 checks=0

check() { # check DESCRIPTION CONDITION...
  local what=$1; shift
  checks=$((checks + 1))
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; failures=$((failures + 1)); fi
}
run() { # run ARGS...: the tool's stdout, stderr and exit code kept in $work
  "$tool" "$@" > "$work/out" 2> "$work/err"
  echo $? > "$work/code"
}
code() { cat "$work/code"; }
has() { grep -q -- "$2" "$1"; }

# up_of PACK: the up axis info --json reports, also checked against the text.
up_of() {
  local json text
  json=$("$tool" info --json "$1" | python3 -c 'import json,sys; print(json.load(sys.stdin)["up_axis"])')
  text=$("$tool" info "$1" | sed -n 's/^  up axis  *\([-+][xyz]\).*/\1/p')
  [ "$json" = "$text" ] || { echo "  info says $text, --json $json"; return 1; }
  echo "$json"
}
# built_up AXIS INPUT... [--up A]: builds quietly, succeeds and is AXIS.
built_up() {
  local want=$1; shift
  run build "$@" -o "$work/p.swpack" --quiet
  [ "$(code)" -eq 0 ] || { echo "  build failed: $(cat "$work/err")"; return 1; }
  local got
  got=$(up_of "$work/p.swpack") || return 1
  [ "$got" = "$want" ] || { echo "  up axis $got, expected $want"; return 1; }
}
no_warning() { [ ! -s "$work/err" ] || { echo "  stderr: $(cat "$work/err")"; false; }; }

scene() { # scene FILE [TOP LINE]: a one-part scene of the teapot, the line first
  { [ -n "${2:-}" ] && echo "$2"; printf '[part pot]\nfile = %s/teapot.txt\n' "$samples"; } > "$1"
}

cli() {
  check "a Newell listing is +y" built_up +y "$samples/teapot.txt"
  check "a .bpt file is +y" built_up +y "$samples/saddle.bpt"
  check "a scene without up_axis is +y" built_up +y "$samples/teaset.ini"
  # Into a file first: grep -q stops reading early, and under pipefail a
  # long listing (a pack with static levels) then fails on SIGPIPE.
  check "the pack lists its ORIENTATION section" eval '"$tool" info "$work/p.swpack" > "$work/info" && grep -q "^    ORIENTATION  *offset" "$work/info"'
  scene "$work/z.ini" "up_axis = z"
  check "a scene's up_axis = z is +z" built_up +z "$work/z.ini"
  scene "$work/nx.ini" "up_axis = -x"
  check "a scene's up_axis = -x is -x" built_up -x "$work/nx.ini"
  check "--up z overrides a listing's +y" built_up +z "$samples/teapot.txt" --up z
  check "--up -y overrides a scene's up_axis" built_up -y "$work/z.ini" --up -y
  check "--up +x is accepted" built_up +x "$samples/teapot.txt" --up +x
  check "--up gives no warning" no_warning

  check "inputs that differ take the first's" built_up +z "$work/z.ini" "$samples/teapot.txt"
  check "and a warning names both files" eval 'has "$work/err" "^warning: the inputs.* up axes differ: $work/z.ini (+z), $samples/teapot.txt (+y); the pack takes the first input.s, +z (--up sets it)$"'
  check "--up silences it" built_up +y "$work/z.ini" "$samples/teapot.txt" --up y
  check "(no warning)" no_warning
  check "inputs that agree give no warning" built_up +y "$samples/teapot.txt" "$samples/saddle.bpt"
  check "(none)" no_warning

  for bad in w X 2 "+" "x y" ""; do
    rm -f "$work/bad.swpack"
    run build "$samples/teapot.txt" --up "$bad" -o "$work/bad.swpack"
    check "--up '$bad' is a usage error naming the value" eval '[ "$(code)" -eq 2 ] && has "$work/err" "^seamwalk-pack: build: --up takes x, y, z, -x, -y or -z, not .$bad.$" && [ ! -e "$work/bad.swpack" ]'
  done
  run build "$samples/teapot.txt" -o "$work/bad.swpack" --up
  check "--up without a value is a usage error" eval '[ "$(code)" -eq 2 ] && has "$work/err" "--up takes"'
  scene "$work/bad.ini" "up_axis = sideways"
  run build "$work/bad.ini" -o "$work/bad.swpack"
  check "a bad scene up_axis fails naming file:line" eval '[ "$(code)" -eq 1 ] && has "$work/err" "bad.ini:1: up_axis: .sideways., expected x, y, z, -x, -y or -z"'

  # Signing lays the sections out again: the up axis must survive it.
  "$tool" build "$samples/teapot.txt" --up z -o "$work/signed.swpack" --quiet &&
    "$tool" keygen -o "$work/owner" > /dev/null &&
    "$tool" sign "$work/signed.swpack" --key "$work/owner.key" --version 1 --name pot > /dev/null
  check "a signed pack keeps its up axis" eval '[ "$(up_of "$work/signed.swpack")" = "+z" ] && "$tool" verify "$work/signed.swpack" --key "$work/owner.pub" > /dev/null'

  # Packs from before ORIENTATION: the fuzz corpus's seed was written then.
  local old=$src/tests/fuzz/corpus/pack/seed-sample
  check "an old pack reads as +y" eval '[ "$(up_of "$old")" = "+y" ]'
  check "and info says it is the default" eval '"$tool" info "$old" | grep -q "^  up axis  *+y (no ORIENTATION section: the default)$"'

  if [ -f "$shared/gpucast_teapot.igs" ]; then
    check "an IGES file is +z" built_up +z "$shared/gpucast_teapot.igs"
    check "IGES then a listing: +z, warned" built_up +z "$shared/gpucast_teapot.igs" "$samples/teapot.txt"
    check "(the warning names the IGES file)" has "$work/err" "gpucast_teapot.igs (+z), .*teapot.txt (+y)"
  else
    echo "skipped: the IGES checks ($shared/gpucast_teapot.igs is absent)"
  fi
  if [ -f "$shared/occt_screw.step" ]; then
    run build "$shared/occt_screw.step" -o "$work/p.swpack" --quiet
    if has "$work/err" "built without STEP support"; then
      echo "skipped: the STEP check (built without STEP support)"
    else
      check "a STEP file is +z" built_up +z "$shared/occt_screw.step"
    fi
  else
    echo "skipped: the STEP check ($shared/occt_screw.step is absent)"
  fi
}

# walk_aspect PACK MIN MAX: every frame of a 4-frame orbit (front, side,
# back, side) has a silhouette between MIN and MAX times as tall as wide.
walk_aspect() {
  local pack=$1 min=$2 max=$3 dir
  dir=$work/png_$(basename "$pack" .swpack)
  "$walker" --pack "$pack" --headless 320x240 --orbit --frames 4 --png-dir "$dir" \
    --stats "$dir.json" > /dev/null || { echo "  walk failed"; return 1; }
  local ok=0
  # What is drawn is what is culled and measured: the camera turns, not the
  # model, so the error bound and the allocation count hold as for y-up.
  python3 "$src/tests/check_stats.py" "$dir.json" 4 > "$dir.check" || { cat "$dir.check"; ok=1; }
  for f in "$dir"/frame_*.png; do
    "$compare" --aspect "$f" "$min" "$max" | sed 's/^/  /'
    [ "${PIPESTATUS[0]}" -eq 0 ] || ok=1
  done
  return $ok
}
# not_all_within PACK MIN MAX: some frame is outside (lying down).
not_all_within() { ! walk_aspect "$@"; }

orbit() {
  local screw=$shared/occt_screw.step plate=$shared/nist_mbe_pmi_11.stp
  [ -f "$screw" ] && [ -f "$plate" ] || { echo "skipped: $screw or $plate is absent"; exit 77; }
  "$tool" build "$screw" -o "$work/screw.swpack" --quiet 2> "$work/err"
  if has "$work/err" "built without STEP support"; then
    echo "skipped: built without STEP support"; exit 77
  fi
  "$tool" build "$plate" -o "$work/plate.swpack" --quiet || { echo "FAIL build $plate"; exit 1; }
  "$tool" build "$screw" --up y -o "$work/screw_y.swpack" --quiet || { echo "FAIL build --up y"; exit 1; }
  # The screw's box is 30 x 35 mm across and 42 mm along z, with a slim
  # shank: standing, about 1.9 times as tall as wide from every side.
  check "the z-up screw stands upright all round the orbit" walk_aspect "$work/screw.swpack" 1.5 3
  # The plate is 63 mm across and 3 mm thick: lying flat, seen from 25
  # degrees above, about 0.36; standing up (y-up) 0.8 face on, 16 edge on.
  check "the z-up plate lies flat all round the orbit" walk_aspect "$work/plate.swpack" 0.2 0.6
  check "with --up y the screw lies on its side (the old view)" not_all_within "$work/screw_y.swpack" 1.5 3
}

case $mode in
cli) cli ;;
orbit) orbit ;;
*) echo "unknown mode $mode"; exit 2 ;;
esac
echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
