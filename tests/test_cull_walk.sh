#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Culling end to end (issue 10, item 4):
#   test_cull_walk.sh BUILD_DIR SOURCE_DIR [MODEL...]
# For the teaset sample, a generated showroom of 3,000 patches and each
# MODEL (the shared models; a STEP file this build cannot read is skipped):
# - test_cull_tree on its pack: the tree's nearest and farthest depths equal
#   every patch box's, surface by surface, from 96 views around and inside;
# - an orbit and a close-to-far path (tests/near_far_path.py; the shared
#   models walk the close-to-far path alone) walked with
#   --cull tree and --cull brute: the same pictures byte for byte and the
#   same triangles a frame, and on the showroom at most half the box tests
#   a frame (median; a model of a few dozen one-patch surfaces seen from
#   close can take a few more through the tree than one a surface);
# - the same walks with --back-faces hidden, cone culling on and off: 0
#   pixels differ (cone culling leaves out only surfaces whose every
#   triangle the renderer would not draw), and over all models it left out
#   some surfaces (the test is not vacuous);
# - with back faces drawn (lit, the default) the stats say cone culling is
#   off: a surface seen from behind stays drawn (the teaset and the
#   showroom; the shared models compare tree and brute with back faces
#   hidden and cone culling off).
set -uo pipefail
build=$1 src=$2; shift 2
tool=$build/assets/seamwalk-pack walker=$build/firmware/seamwalk
compare=$build/tests/image_compare tree_test=$build/tests/test_cull_tree
work=$build/tests/cull_walk
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# walk NAME PACK ARGS...: a 320x240 walk with a picture a frame into $work/NAME.
walk() {
  local name=$1 pack=$2; shift 2
  "$walker" --pack "$pack" --headless 320x240 --frames 6 --measure-every 100000 \
    --memory-mb 2048 --png-dir "$work/$name" --stats "$work/$name.json" "$@" \
    > "$work/$name.log" 2>&1 || fail "walk $name: $(tail -n 2 "$work/$name.log")"
}

# same_pictures A B LEVEL: every frame of walk A against walk B.
same_pictures() {
  for f in "$work/$1"/frame_*.png; do
    "$compare" "$f" "$work/$2/$(basename "$f")" --level 0 --max-fraction 0 > "$work/cmp.txt" ||
      fail "$1 and $2 differ: $(cat "$work/cmp.txt")"
  done
}

json() { python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print($2)" "$1"; }

packs=()
"$tool" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" --quiet || fail "teaset"
packs+=("$work/teaset.swpack")
if [ -d "$src/../shared/models" ]; then
  shared=$src/../shared/models
  "$tool" gen showroom --patches 3000 -o "$work/showroom.ini" --part "$shared/occt_hammer.iges" \
    --part "$shared/newell_teapot.txt" > /dev/null || fail "gen showroom"
  "$tool" build "$work/showroom.ini" -o "$work/showroom.swpack" --quiet || fail "showroom"
  packs+=("$work/showroom.swpack")
fi
for model in "$@"; do
  name=$(basename "$model")
  if ! "$tool" build "$model" -o "$work/$name.swpack" --quiet 2> "$work/build.err"; then
    grep -q "built without STEP support" "$work/build.err" && { echo "skipped $name (no STEP)"; continue; }
    fail "build $name: $(cat "$work/build.err")"
  fi
  packs+=("$work/$name.swpack")
done

"$tree_test" "${packs[@]}" || fail "test_cull_tree"

culled_total=0
for pack in "${packs[@]}"; do
  name=$(basename "$pack" .swpack)
  "$tool" info --json "$pack" > "$work/$name.info.json" || fail "info $name"
  mkdir -p "$work/$name.paths"
  python3 "$src/tests/near_far_path.py" "$work/$name.info.json" "$work/$name.paths" || fail "path"
  # Every view on the teaset and the showroom; the shared models (dozens
  # of surfaces each) on the close-to-far path alone, which passes through
  # the orbit's distances too: both views on all of them made this the
  # suite's longest test (about 8 minutes of CI's 2 cores, 112 walks).
  views="orbit near"
  case $name in teaset|showroom) ;; *) views=near ;; esac
  # The shared models compare tree and every box with back faces hidden
  # and cone culling off, the walk cone culling is then set against (three
  # walks a model, not four); lit, only the teaset and the showroom.
  hidden=()
  case $name in teaset|showroom) ;; *) hidden=(--back-faces hidden --cone-cull 0) ;; esac
  for view in $views; do
    how=(--orbit)
    [ $view = near ] && how=(--path "$work/$name.paths/near_far.path")
    walk "$name.$view.tree" "$pack" "${how[@]}" "${hidden[@]}"
    walk "$name.$view.brute" "$pack" "${how[@]}" --cull brute "${hidden[@]}"
    same_pictures "$name.$view.tree" "$name.$view.brute"
    [ "$(json "$work/$name.$view.tree.json" 'j["tris_per_frame"]')" = \
      "$(json "$work/$name.$view.brute.json" 'j["tris_per_frame"]')" ] || fail "$name $view: triangles differ"
    tests_tree=$(json "$work/$name.$view.tree.json" 'j["cull"]["box_tests"]["p50"]')
    tests_brute=$(json "$work/$name.$view.brute.json" 'j["cull"]["box_tests"]["p50"]')
    if [ "$name" = showroom ]; then
      python3 -c "import sys; sys.exit(not float(sys.argv[1]) <= float(sys.argv[2]) / 2)" \
        "$tests_tree" "$tests_brute" || fail "$name $view: $tests_tree box tests, brute $tests_brute"
    fi
    [ "$(json "$work/$name.$view.tree.json" 'j["cull"]["cone_cull"]')" = False ] ||
      fail "$name $view: cone culling on with back faces drawn or --cone-cull 0"
    off=$name.$view.tree   # back faces hidden, cone culling off: what cones must match
    if [ ${#hidden[@]} -eq 0 ]; then
      off=$name.$view.hidden
      walk "$off" "$pack" "${how[@]}" --back-faces hidden --cone-cull 0
    fi
    walk "$name.$view.cones" "$pack" "${how[@]}" --back-faces hidden
    same_pictures "$off" "$name.$view.cones"
    culled=$(json "$work/$name.$view.cones.json" 'int(j["cull"]["cone_culled"]["max"])')
    culled_total=$((culled_total + culled))
    echo "ok   $name $view: box tests (median a frame) tree $tests_tree, every patch $tests_brute;" \
         "cone culling left out up to $culled surfaces a frame, same pixels"
  done
done
[ "$culled_total" -gt 0 ] || fail "cone culling never left a surface out"
echo "ok   every walk: the tree draws what every box draws, cone culling changes no pixel"
