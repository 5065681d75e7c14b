#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Cracks and holes seen in the pictures, not in the walk's own counts:
#   test_image_holes.sh MODEL BUILD_DIR SOURCE_DIR
# MODEL (a scene .ini or a CAD file) is packed and walked headless through
# six still views, close, mid and far (tests/hole_views.py), twice: at the
# default bound of 0.5 px and, as the reference, at 0.05 px. Both are drawn
# over magenta (255,0,255), a colour no part has, with back faces flat cyan
# (0,255,255, --back-faces), another, so the inside of a closed solid
# showing through a crack can be told from its outside. Every view's
# interior pixels (more than 2 px inside the reference's silhouette and
# contours) that show the background where the reference shows the model
# are holes, and there must be none (tests/image_holes.c); those that show
# the inside are counted and printed (a crack into a solid, or a contour
# the coarser tessellation moved by its bound). A mutant that leaves one
# surface out (--test-drop-surface) must be caught in some view (holes and
# inside pixels beyond the test's own), or the test could not see a hole at
# all. Exit 77: the file is absent.
set -uo pipefail
model=$1 build=$2 src=$3
name=$(basename "$model")
tool=$build/assets/seamwalk-pack walker=$build/firmware/seamwalk holes=$build/tests/image_holes
work=$build/tests/holes/$name
rm -rf "$work" && mkdir -p "$work"
export LSAN_OPTIONS="suppressions=$src/tests/occt-lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
fail() { echo "FAIL: $name: $*"; exit 1; }
[ -f "$model" ] || { echo "skipped: $model is absent"; exit 77; }
magenta=255,0,255 cyan=0,255,255 size=640x480 views=6

"$tool" build "$model" -o "$work/model.swpack" --quiet 2> "$work/build.err" \
  || fail "build: $(cat "$work/build.err")"
"$tool" info --json "$work/model.swpack" > "$work/info.json" || fail "info"
python3 "$src/tests/hole_views.py" "$work/info.json" "$work/views.path" || fail "views"

# walk DIR BOUND [ARGS...]: the six views at BOUND px into DIR/frame_*.png.
walk() {
  local dir=$1 bound=$2
  shift 2
  "$walker" --pack "$work/model.swpack" --headless $size --path "$work/views.path" \
    --frames $views --max-error-px "$bound" --background $magenta --back-faces $cyan \
    --png-dir "$work/$dir" --stats "$work/$dir.json" --measure-every 1000000 "$@" \
    > "$work/$dir.log" 2>&1 || fail "walk $dir: $(tail -n 3 "$work/$dir.log")"
}

# holes_in DIR: the holes and inside pixels of every view of DIR against the
# reference, summed into DIR.holes and DIR.inside; exit 2 (a broken
# comparison) fails the test.
holes_in() {
  local dir=$1 holes_sum=0 inside_sum=0 f
  for f in "$work/ref"/frame_*.png; do
    local out last
    out=$("$holes" "$work/$dir/$(basename "$f")" "$f" $magenta --inside $cyan --max 1000000000 \
          --out "$work/$dir-holes-$(basename "$f")")
    [ $? -le 1 ] || fail "image_holes on $dir/$(basename "$f"): $out"
    last=$(echo "$out" | tail -n 1)
    [ "$dir" = test ] && echo "$last" | sed "s|$work/||g; s/^/  /"
    holes_sum=$(( holes_sum + $(echo "$last" | sed -E 's/.*: ([0-9]+) holes, .*/\1/') ))
    inside_sum=$(( inside_sum + $(echo "$last" | sed -E 's/.* holes, ([0-9]+) inside .*/\1/') ))
  done
  echo "$holes_sum" > "$work/$dir.holes"
  echo "$inside_sum" > "$work/$dir.inside"
}

# The reference in the frame, on the GL thread (--workers 0): at 0.05 px
# the close views fill the tessellation cache, and there the workers' meshes
# (made two at a time, placed in the order they finish) can find no room
# where the same walk in the frame caps them: the reference would have
# holes of its own, differently from run to run.
walk ref 0.05 --workers 0
walk test 0.5
for f in "$work/ref"/frame_*.png; do
  inside=$("$holes" "$f" "$f" $magenta --inside $cyan | tail -n 1 \
          | sed -E 's/.* in ([0-9]+) interior.*/\1/')
  [ "$inside" -gt 0 ] || fail "view $(basename "$f") shows no model to compare"
done
holes_in test
[ "$(cat "$work/test.holes")" -eq 0 ] \
  || fail "$(cat "$work/test.holes") holes where the reference shows the model (pictures: $work/test-holes-*)"
test_open=$(( $(cat "$work/test.holes") + $(cat "$work/test.inside") ))
echo "ok   $name: no holes in $views views (0.5 px against 0.05 px); $(cat "$work/test.inside") pixels show the inside"

# The mutant: the first of surfaces 0..7 whose absence shows.
for s in 0 1 2 3 4 5 6 7; do
  walk drop$s 0.5 --test-drop-surface $s
  holes_in drop$s
  caught=$(( $(cat "$work/drop$s.holes") + $(cat "$work/drop$s.inside") - test_open ))
  if [ "$caught" -gt 0 ]; then
    echo "ok   mutant without surface $s caught: $(cat "$work/drop$s.holes") holes, $caught more pixels open than the test's"
    exit 0
  fi
done
fail "no mutant without one of surfaces 0..7 shows a hole: the test cannot see one"
