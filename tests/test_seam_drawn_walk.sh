#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The seams as drawn, end to end (firmware/walk/gl/sw_seam_drawn.h, sw_seam_fill.h):
#   test_seam_drawn_walk.sh BUILD_DIR SOURCE_DIR
# The teaset walked around an orbit, every frame measured: drawn as the
# tessellator makes them (--fill-crossings 0) its seam crossings are
# T-vertices the check must see; with the fill fans (the default) none is
# left, the fans are counted apart from the triangles, and no gap opens.
set -uo pipefail
build=$1 src=$2
work=$build/tests/seam_drawn_walk
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" \
  > /dev/null || fail "build"
for fill in 0 1; do
  "$build/firmware/seamwalk" --pack "$work/teaset.swpack" --headless 640x480 --orbit --frames 8 \
    --measure-every 1 --fill-crossings $fill --stats "$work/fill$fill.json" > /dev/null \
    || fail "walk --fill-crossings $fill"
done
python3 - "$work/fill0.json" "$work/fill1.json" <<'PY' || fail "seams as drawn"
import json, sys
raw, filled = (json.load(open(p))["seam_drawn"] for p in sys.argv[1:3])
crossings = json.load(open(sys.argv[1]))["seam"]["crossings_max"]
print("  as made: %d T-vertices of %d border points (%d crossings); filled: %d T-vertices, "
      "%d fan triangles, %d gaps" % (raw["t_vertices_max"], raw["points_max"], crossings,
                                     filled["t_vertices_max"], filled["fill_triangles_max"],
                                     filled["gaps_max"]))
assert raw["unchecked_frames"] == 0 and filled["unchecked_frames"] == 0
assert raw["t_vertices_max"] > 0 and raw["fill_triangles_max"] == 0
assert filled["t_vertices_max"] == 0 and filled["fill_triangles_max"] > 0
assert filled["gaps_max"] == 0 and raw["gaps_max"] == 0
PY
echo "ok   the check sees the crossings' T-vertices, the fans close them"
