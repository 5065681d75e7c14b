#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A part cut into pieces, drawn far away from its pieces' levels:
#   test_pieces.sh BUILD_DIR SOURCE_DIR
# A courtyard of 40 x 40 cells (tests/gen_soup.py: one part of 3,800
# patches, cut past 1,024 with --cut-patches; the default is 4,096):
# - its pack's part levels against what they stand for, and its pieces'
#   borders against each other at every front, and its levels of itself
#   whole (test_part_levels_build --cut: fails on a pack with no part cut);
# - the whole courtyard in view (--orbit, 16 frames at 1280x720) as the
#   kiosk service walks it, against the reference walk (--workers 0
#   --part-levels 0), every 5th frame: no interior background pixel, at
#   most 0.5% of pixels differing, and more than one piece drawn from its
#   levels in a frame;
# - the mutant --test-part-levels-coarsest 1 (every piece from its
#   coarsest level, whatever the bound) must fail the pictures (exit 1).
# Needs nothing from ../shared/models.
set -uo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
tool=$build/assets/seamwalk-pack
work=$build/tests/pieces
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
python3 "$src/tests/gen_soup.py" "$work/court.igs" --cells 40 > "$work/gen.log" 2>&1 \
  || fail "gen_soup: $(tail -n 3 "$work/gen.log")"
"$tool" build "$work/court.igs" -o "$work/court.swpack" --cut-patches 1024 > "$work/build.log" 2>&1 \
  || fail "build: $(tail -n 3 "$work/build.log")"
grep "part levels" "$work/build.log"
"$build/tests/test_part_levels_build_prog" --cut "$work/court.swpack" > "$work/levels.log" 2>&1 \
  || fail "test_part_levels_build --cut: $(tail -n 5 "$work/levels.log")"
tail -n 1 "$work/levels.log"
pictures() {
  python3 "$src/tests/walk_pictures.py" "$work/court.swpack" orbit "$build" "$work/$1" 1280x720 \
    16 --every 5 --json "$work/$1.json" "${@:2}" > "$work/$1.log" 2>&1
}
pictures orbit
rc=$?
grep -E "interior background px max|differing max|undrawn" "$work/orbit.log"
[ $rc -eq 0 ] || fail "orbit: exit $rc ($work/orbit.log)"
pieces=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["part_levels"]["parts_max"])' \
  "$work/orbit/test.json") || fail "no stats in $work/orbit/test.json"
echo "pieces drawn from their levels in a frame, most: $pieces"
[ "$pieces" -gt 1 ] || fail "the orbit drew $pieces pieces from their levels, expected more than one"
pictures mutant --test-part-levels-coarsest 1
rc=$?
grep -E "interior background px max|differing max" "$work/mutant.log" | sed 's/^/mutant: /'
[ $rc -eq 1 ] || fail "the mutant --test-part-levels-coarsest 1: exit $rc, expected 1"
echo "pieces: ok"
