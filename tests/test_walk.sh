#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# End-to-end tests of the two programs, one mode per CTest test:
#   test_walk.sh MODE BUILD_DIR SOURCE_DIR
# MODE: teaset | teapot | golden | errors | seams. Exit 77 means skipped.
set -uo pipefail
mode=$1 build=$2 src=$3
pack_tool=$build/assets/seamwalk-pack
walker=$build/firmware/seamwalk
compare=$build/tests/image_compare
work=$build/tests/walk_$mode
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# walk_model INPUT FRAMES: pack, info, orbit walk with pictures and stats, checks.
walk_model() {
  local input=$1 frames=$2
  "$pack_tool" build "$input" -o "$work/model.swpack" || fail "build $input"
  "$pack_tool" info --json "$work/model.swpack" > "$work/info.json" || fail "info"
  python3 -m json.tool "$work/info.json" > /dev/null || fail "info --json is not JSON"
  "$pack_tool" verify "$work/model.swpack" || fail "verify"
  # The surfaces' walk, whose error and cache the stats' contract checks: at
  # 320x240 the orbit is far enough for part levels to draw a model whole
  # (they are checked on the host and in pictures: tests/test_pieces.sh).
  "$walker" --pack "$work/model.swpack" --headless 320x240 --orbit --frames "$frames" \
    --part-levels 0 --png-dir "$work/png" --png-every 8 --stats "$work/stats.json" || fail "walk"
  python3 "$src/tests/check_stats.py" "$work/stats.json" "$frames" || fail "stats"
  local pngs
  pngs=$(ls "$work/png"/frame_*.png | wc -l)
  [ "$pngs" -eq $(( (frames + 7) / 8 )) ] || fail "expected $(( (frames + 7) / 8 )) PNGs, found $pngs"
  for f in "$work/png"/frame_*.png; do
    "$compare" --coverage "$f" 0.02 || fail "the model is not in $f"
  done
}

# expect_failure CODE FRAGMENT COMMAND...: exits with CODE, one stderr line containing FRAGMENT.
expect_failure() {
  local code=$1 fragment=$2; shift 2
  "$@" 2> "$work/stderr" > /dev/null
  local got=$?
  [ "$got" -eq "$code" ] || fail "'$*' exited $got, expected $code"
  grep -q -- "$fragment" "$work/stderr" || fail "'$*' said '$(cat "$work/stderr")', expected '$fragment'"
  echo "ok   $(head -n 1 "$work/stderr")"
}

case $mode in
teaset)
  walk_model "$src/assets/samples/teaset.ini" 24 ;;
seams)
  # Through the Seam Graph: the same pictures and contract, no crack, a still
  # camera re-tessellates nothing, and a pack without a graph is refused in
  # one line.
  "$pack_tool" build "$src/assets/samples/teaset.ini" -o "$work/model.swpack" > /dev/null || fail "build"
  "$walker" --pack "$work/model.swpack" --headless 320x240 --orbit --frames 8 \
    --png-dir "$work/png" --png-every 4 --stats "$work/stats.json" || fail "walk"
  python3 "$src/tests/check_stats.py" "$work/stats.json" 8 || fail "stats"
  for f in "$work/png"/frame_*.png; do
    "$compare" --coverage "$f" 0.02 || fail "the model is not in $f"
  done
  # A still camera re-tessellates nothing after the first frame (the cache
  # holds every surface at a valid bound), and uploads nothing.
  printf '0 0.4 1.2 3.2 0.25 0.35 0.4 0 1 0\n1 0.4 1.2 3.2 0.25 0.35 0.4 0 1 0\n' > "$work/still.path"
  "$walker" --pack "$work/model.swpack" --headless 320x240 --path "$work/still.path" --frames 8 \
    --stats "$work/still.json" > /dev/null || fail "walk, still camera"
  python3 - "$work/still.json" <<'EOF' || fail "still camera"
import json, sys
c = json.load(open(sys.argv[1]))["cache"]
print("still camera: %d surfaces tessellated in 8 frames, %d frames without, %d bytes uploaded"
      % (c["retessellated"]["total"], c["frames_without_retess"], c["upload_bytes"]["total"]))
assert c["retessellated"]["total"] == c["retessellated"]["max"] > 0, "tessellated after frame 0"
assert c["frames_without_retess"] == 7 and c["upload_bytes"]["total"] == c["upload_bytes"]["max"]
EOF
  expect_failure 1 "has no Seam Graph" "$walker" --pack "$src/tests/fuzz/corpus/pack/seed-sample" \
    --headless 64x64 --orbit --frames 1
  # Far away whole patches vanish: 300 model sizes off (two or three pixels),
  # fewer triangles than patches, some surfaces not drawn at all, no crack.
  "$pack_tool" info --json "$work/model.swpack" > "$work/info.json" || fail "info"
  python3 - "$work/info.json" > "$work/far.path" <<'EOF' || fail "far path"
import json, sys
j = json.load(open(sys.argv[1]))
lo, hi = j["box"]["min"], j["box"]["max"]
c = [(a + b) / 2 for a, b in zip(lo, hi)]
d = 300 * max(b - a for a, b in zip(lo, hi))
print("0 %r %r %r %r %r %r 0 1 0" % (c[0] + d, c[1] + 0.3 * d, c[2] + 0.7 * d, c[0], c[1], c[2]))
EOF
  # The Seam Graph's own vanishing, so without part levels (which would
  # draw the whole model from one mesh this far away).
  "$walker" --pack "$work/model.swpack" --headless 640x480 --path "$work/far.path" --frames 1 \
    --part-levels 0 --stats "$work/far.json" > /dev/null || fail "walk, far"
  python3 - "$work/far.json" <<'EOF' || fail "far away"
import json, sys
j = json.load(open(sys.argv[1]))
tris, patches, seam = j["tris_per_frame"]["max"], j["patches"]["total"], j["seam"]
print("far: %d triangles for %d patches, %d surfaces vanished, %d active seam vertices"
      % (tris, patches, seam["surfaces_vanished_max"], seam["active_vertices_max"]))
assert 0 < tris < patches and seam["surfaces_vanished_max"] > 0 and j["cracks_max"] == 0
EOF
  # The demo's first picture (tests/run-demo.sh: its orbit at 1280x720, the
  # default workers, not waiting for them: CTest's SEAMWALK_TEST_SYNC_WORK
  # would) within the bound: drawn at once from the static levels,
  # it matches the first picture of the walk that makes every mesh in its
  # frame (--workers 0) but for 0.5% of its pixels. Without the levels the
  # first frame is made coarser (SW_SEAM_FIRST_COARSER) and must differ
  # more, or the comparison could not see it.
  first() {
    "$walker" --pack "$work/model.swpack" --headless 1280x720 --orbit --frames 1 \
      --measure-every 0 --png-dir "$work/first_$1" --png-every 1 --stats "$work/first_$1.json" \
      "${@:2}" > "$work/first_$1.log" 2>&1 || fail "first picture, $1: $(tail -2 "$work/first_$1.log")"
  }
  first reference --workers 0
  first levels --sync-work 0
  first coarse --sync-work 0 --static-levels 0
  "$compare" "$work/first_levels/frame_00000.png" "$work/first_reference/frame_00000.png" \
    --level 8 --max-fraction 0.005 || fail "the first picture is not within the bound"
  if "$compare" "$work/first_coarse/frame_00000.png" "$work/first_reference/frame_00000.png" \
    --level 8 --max-fraction 0.005; then
    fail "a first picture made coarser passes the comparison"
  fi
  python3 - "$work/first_levels.json" <<'EOF' || fail "first picture's stats"
import json, sys
t = json.load(open(sys.argv[1]))["threads"]
assert t["workers"] > 0 and t["standins_made"] > 0 and t["waiting_surfaces_max"] == 0, t
EOF
  ;;
teapot)
  model=$src/../shared/models/newell_teapot.txt
  [ -f "$model" ] || { echo "skipped: $model is absent"; exit 77; }
  walk_model "$model" 16 ;;
golden)
  # The references are pictures of the surfaces' own tessellation, so the
  # walks here draw no part levels; those are judged against such walks in
  # pictures (tests/test_walk_pictures.sh).
  "$pack_tool" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" || fail "build"
  "$walker" --pack "$work/teaset.swpack" --headless 320x240 --path "$src/tests/golden/views.path" \
    --frames 3 --part-levels 0 --png-dir "$work/png" --stats "$work/stats.json" || fail "walk"
  for i in 0 1 2; do
    "$compare" "$work/png/frame_0000$i.png" "$src/tests/golden/teaset_view$i.png" \
      || fail "view $i differs from its reference"
  done
  # The comparison must be able to fail: two different views do not match.
  if "$compare" "$src/tests/golden/teaset_view0.png" "$src/tests/golden/teaset_view1.png"; then
    fail "the comparison cannot tell two views apart"
  fi
  # Nor may a broken scene pass: each mutation of the teaset must differ
  # from the references in at least one of the three views.
  mutate() { # mutate NAME SED_SCRIPT_FOR_THE_SCENE [PATCHES_KEPT]
    local dir=$work/mutant_$1
    mkdir -p "$dir"
    cp "$src/assets/samples/"*.txt "$dir/"
    sed "$2" "$src/assets/samples/teaset.ini" > "$dir/teaset.ini"
    if [ -n "${3:-}" ]; then   # the teapot with only its first $3 of 28 patches
      { sed -n 1p "$dir/teapot.txt"; printf '269\t1\t%d\t%d\n' "$3" "$3";
        sed -n "3,$((271 + $3))p" "$dir/teapot.txt"; } > "$dir/teapot.cut"
      mv "$dir/teapot.cut" "$dir/teapot.txt"
    fi
    "$pack_tool" build "$dir/teaset.ini" -o "$dir/teaset.swpack" > /dev/null || fail "build $1"
    "$walker" --pack "$dir/teaset.swpack" --headless 320x240 --path "$src/tests/golden/views.path" \
      --frames 3 --part-levels 0 --png-dir "$dir/png" > /dev/null || fail "walk $1"
    for i in 0 1 2; do
      "$compare" "$dir/png/frame_0000$i.png" "$src/tests/golden/teaset_view$i.png" > /dev/null ||
        { echo "ok   mutant $1 differs in view $i"; return 0; }
    done
    fail "mutant $1 passes the golden comparison"
  }
  mutate no_spoon '/^\[part teaspoon\]/,$d'
  mutate cup_turned '/^\[part teacup\]/,/^\[/s/^rotate = 0 1 0 -30$/rotate = 0 1 0 -60/'
  mutate recoloured 's/^color = 0.16 0.30 0.62$/color = 0.30 0.16 0.62/'
  mutate patches_missing '' 10 ;;
errors)
  "$pack_tool" build "$src/assets/samples/teaset.ini" -o "$work/good.swpack" || fail "build"
  size=$(stat -c %s "$work/good.swpack")
  # Refused before anything is taken, saying by how much and which of the
  # pack's pools take most (the teaset's: the mesh cache); a pack larger
  # than the limit itself is not read to say so.
  expect_failure 1 "needs .* MiB of memory, more than --memory-mb 20.0 by .*largest first: mesh cache" \
    "$walker" --pack "$work/good.swpack" --headless 320x240 --orbit --memory-mb 20
  expect_failure 1 "more than --memory-mb 1.0 by .*: the pack itself [0-9.]* MiB (the rest not read" \
    "$walker" --pack "$work/good.swpack" --headless 320x240 --orbit --memory-mb 1
  head -c $((size / 2)) "$work/good.swpack" > "$work/short.swpack"
  expect_failure 1 "short.swpack" "$walker" --pack "$work/short.swpack" --headless 320x240 --orbit
  cp "$work/good.swpack" "$work/flipped.swpack"
  printf '\xff' | dd of="$work/flipped.swpack" bs=1 seek=$((size - 7)) conv=notrunc status=none
  expect_failure 1 "checksum" "$walker" --pack "$work/flipped.swpack" --headless 320x240 --orbit
  expect_failure 1 "missing.swpack" "$walker" --pack "$work/missing.swpack" --headless 320x240 --orbit
  printf '0 0 0 5 0 0 0 0 1 0\n1 0 0 5\n' > "$work/bad.path"
  expect_failure 1 "bad.path:2" "$walker" --pack "$work/good.swpack" --headless 320x240 --path "$work/bad.path"
  expect_failure 1 "no viewpoint named 'lobby'" "$walker" --pack "$work/good.swpack" --headless 320x240 --view lobby
  expect_failure 2 "exactly one of --path" "$walker" --pack "$work/good.swpack" --headless 320x240
  expect_failure 2 "--headless" "$walker" --pack "$work/good.swpack" --headless 12x9999 --orbit
  expect_failure 2 "unknown option" "$walker" --pack "$work/good.swpack" --orbit --bogus 1
  ;;
*) fail "unknown mode $mode" ;;
esac
echo "test_walk $mode: passed"
