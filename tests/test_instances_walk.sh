#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A scene of repeated parts packed as placed parts (each file stored once)
# and with --copies (each part a copy of its own), walked the same way:
#   test_instances_walk.sh BUILD_DIR SOURCE_DIR
# The scene: the Newell teapot placed five times (turned, scaled, moved),
# the cup twice and a generated vase twice. Checks:
#   - the placed pack stores 3 prototypes for 9 placements and is smaller
#     than the copies' (9 prototypes), and both place the same 9 parts with
#     the same boxes (info); the placed one's walk keeps a seam front per
#     instance over the prototypes' graphs (fewer bytes than one over the
#     placed graph), the copies' one front;
#   - the walk of each, every mesh made in its frame (--workers 0, so each
#     frame is a function of the pack alone), over an orbit of 48 frames
#     at 320x240, every 6th frame pictured, as built and with every
#     surface tessellated (--part-levels 0): every picture pixel for pixel
#     the same (shared prototypes draw as copies do), and none empty;
#   - the walk's own figures: no crack, no surface in view undrawn, the
#     drawn borders show no gap, and the tessellated walk's error within
#     the bound.
set -uo pipefail
build=$1 src=$2
tool=$build/assets/seamwalk-pack walker=$build/firmware/seamwalk
compare=$build/tests/image_compare
work=$build/tests/instances_walk
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
cp "$src/assets/samples/teapot.txt" "$src/assets/samples/teacup.txt" "$work/"
{
  for i in 0 1 2 3 4; do
    printf '[part pot%d]\nfile = teapot.txt\nrotate = 0 1 0 %d\nscale = %s\ntranslate = %d 0 %d\n\n' \
      "$i" $((i * 47)) "1.$i" $((i * 3 - 6)) $((i % 2 * 2))
  done
  printf '[part cup0]\nfile = teacup.txt\ntranslate = 0 0 -2.5\n\n'
  printf '[part cup1]\nfile = teacup.txt\nrotate = 0 1 0 120\nscale = 0.5\ntranslate = 2 0 -2.5\n\n'
  for i in 0 1; do
    printf '[part vase%d]\ngenerate = vase\nsize = 1.5\nheight = 2.5\nsegments = 4\nseed = 5\n' "$i"
    printf 'rotate = 0 1 0 %d\ntranslate = %d 0 3.5\n\n' $((i * 30)) $((i * 3 - 2))
  done
} > "$work/room.ini"

for kind in placed copies; do
  flag=""
  [ $kind = copies ] && flag=--copies
  "$tool" build "$work/room.ini" -o "$work/$kind.swpack" $flag --quiet 2> "$work/$kind.err" \
    || fail "build $kind: $(cat "$work/$kind.err")"
  "$tool" info --json "$work/$kind.swpack" > "$work/$kind.json" || fail "info $kind"
done
python3 - "$work/placed.json" "$work/copies.json" <<'EOF' || fail "the two packs"
import json, sys
p, c = (json.load(open(f)) for f in sys.argv[1:3])
assert p["version"] == 2 and c["version"] == 2, (p["version"], c["version"])
assert p["prototype_count"] == 3 and p["instance_count"] == 9, p["prototype_count"]
assert c["prototype_count"] == 9 and c["instance_count"] == 9, c["prototype_count"]
assert p["total_bytes"] * 2 < c["total_bytes"], (p["total_bytes"], c["total_bytes"])
assert p["placed"] == c["placed"], (p["placed"], c["placed"])
for a, b in zip(p["parts"], c["parts"]):
    assert a["name"] == b["name"] and a["box"] == b["box"], (a, b)
# The walk's seam fronts: per instance where the parts repeat (fewer bytes
# than one over the placed graph), one where nothing repeats.
f, g = p["seam_fronts"], c["seam_fronts"]
assert f["per_instance_bytes"] < f["one_bytes"], f
assert g["per_instance_bytes"] > g["one_bytes"] and g["one_bytes"] == f["one_bytes"], (f, g)
print("placed: %d bytes, 3 prototypes; copies: %d bytes, 9; seam fronts %d bytes, copies' %d"
      % (p["total_bytes"], c["total_bytes"], f["per_instance_bytes"], g["one_bytes"]))
EOF
# walk NAME PACK ARGS...: the orbit into NAME/, NAME.stats.json
walk() {
  local name=$1 pack=$2
  shift 2
  "$walker" --pack "$work/$pack.swpack" --orbit --headless 320x240 --frames 48 --workers 0 \
    --memory-mb 2048 --png-dir "$work/$name" --png-every 6 --measure-every 6 \
    --stats "$work/$name.stats.json" "$@" > "$work/$name.walk.log" 2>&1 \
    || fail "walk $name: $(tail -3 "$work/$name.walk.log")"
}
# As built (far parts from their part levels), and with every surface
# tessellated by the walk (--part-levels 0).
walk placed placed
walk copies copies
walk placed_surfaces placed --part-levels 0
walk copies_surfaces copies --part-levels 0
frames=0
for pair in placed:copies placed_surfaces:copies_surfaces; do
  a=${pair%%:*} b=${pair##*:}
  for f in "$work/$a"/frame_*.png; do
    g="$work/$b/$(basename "$f")"
    [ -f "$g" ] || fail "no picture $g"
    "$compare" "$f" "$g" --level 0 --max-fraction 0 > "$work/compare.log" 2>&1 \
      || fail "$a/$(basename "$f") differs from $b's: $(cat "$work/compare.log")"
    "$compare" --coverage "$f" 0.02 > /dev/null 2>&1 || fail "$a/$(basename "$f") is empty"
    frames=$((frames + 1))
  done
done
[ "$frames" -ge 16 ] || fail "only $frames pictures"
python3 - "$work"/*.stats.json <<'EOF' || fail "walk figures"
import json, sys
for f in sys.argv[1:]:
    s = json.load(open(f))
    assert s["cracks_max"] == 0, (f, s["cracks_max"])
    assert s["threads"]["waiting_surfaces_max"] == 0, (f, s["threads"])
    assert s["seam_drawn"]["gaps_max"] == 0 and s["seam_drawn"]["unchecked_frames"] == 0, \
        (f, s["seam_drawn"])
    if "surfaces" in f:
        assert s["error_px"]["samples"] > 0 and s["seam_drawn"]["points_max"] > 0, (f, s["error_px"])
        assert s["error_px"]["max"] <= 0.5 + s["seam"]["sewing_offset_px_max"] + 1e-3, s["error_px"]
EOF
echo "ok: $frames pictures the same pixel for pixel, placed and copies; no crack, no gap"
