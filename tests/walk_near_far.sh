#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A pack walked through the Seam Graph from close to far (issue 4):
#   walk_near_far.sh WALKER PACK INFO.json WORK_DIR SOURCE_DIR [WALKER ARGS...]
# Views from 0.8 to 40 model sizes away, turning as they go, then the far
# end, where the whole model spans half a pixel (tests/near_far_path.py).
# Every view, every frame measured: no crack, no surface the tessellator
# refused, the error within the bound beyond the sewing offset
# (check_stats.py). These walks draw every surface through the Seam Graph
# (--part-levels 0): what they measure is its tessellation, and a large
# part cut into pieces may be drawn whole from its pieces' levels even at
# 0.8 model sizes at 320x240, leaving nothing measured (part levels are
# measured on the host, tests/test_part_levels_build.c, and in pictures).
# The far end alone, with part levels as a unit draws it: fewer triangles
# than patches (or at most 32).
# Prints what it checked; exit 1 on a failure.
set -uo pipefail
walker=$1 pack=$2 info=$3 work=$4 src=$5
shift 5
fail() { echo "FAIL: $*"; exit 1; }
python3 "$src/tests/near_far_path.py" "$info" "$work" || fail "close-to-far path"
"$walker" --pack "$pack" --headless 320x240 --path "$work/near_far.path" --frames 6 \
  --measure-every 1 --part-levels 0 --stats "$work/near_far.json" "$@" > "$work/near_far.log" \
  || fail "walk: $(tail -n 3 "$work/near_far.log")"
python3 "$src/tests/check_stats.py" "$work/near_far.json" 6 | sed 's/^/  seams: /'
[ "${PIPESTATUS[0]}" -eq 0 ] || fail "stats through the Seam Graph"
"$walker" --pack "$pack" --headless 320x240 --path "$work/far.path" --frames 1 \
  --stats "$work/far.json" "$@" > /dev/null || fail "walk, far"
python3 - "$work/near_far.json" "$work/far.json" <<'PY' || fail "far end"
import json, sys
near, far = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
tris, patches, seam = far["tris_per_frame"]["max"], far["patches"]["total"], far["seam"]
print("  seams, close to far: %d..%d triangles, %d..%d active seam vertices, up to %d surfaces "
      "vanished, %d drawn without holes, frame p50 %.1f ms"
      % (near["tris_per_frame"]["median"], near["tris_per_frame"]["max"],
         near["seam"]["active_vertices_min"], near["seam"]["active_vertices_max"],
         near["seam"]["surfaces_vanished_max"], near["seam"]["surfaces_holes_filled_max"],
         near["frame_ms"]["p50"]))
print("  seams, at the far end: %d triangles for %d patches, %d surfaces vanished, cracks %d"
      % (tris, patches, seam["surfaces_vanished_max"], far["cracks_max"]))
# A small model's coarsest level may not get under its patch count (a box's
# six faces are twelve triangles): 32 triangles at half a pixel pass too.
assert (tris < patches or tris <= 32) and far["cracks_max"] == 0
PY
# --measure-every 0 (a kiosk's setting): the same walk, no frame measured.
"$walker" --pack "$pack" --headless 320x240 --path "$work/near_far.path" --frames 6 \
  --measure-every 0 --part-levels 0 --stats "$work/unmeasured.json" "$@" \
  > "$work/unmeasured.log" \
  || fail "walk, --measure-every 0: $(tail -n 3 "$work/unmeasured.log")"
grep -q "error not measured (--measure-every 0)" "$work/unmeasured.log" \
  || fail "--measure-every 0: the summary does not say the error was not measured"
python3 - "$work/unmeasured.json" <<'PY' || fail "--measure-every 0 measured"
import json, sys
s = json.load(open(sys.argv[1]))
e = s["error_px"]
print("  --measure-every 0: %d frames, %d measured, %d error samples"
      % (s["frames_total"], e["measured_frames"], e["samples"]))
assert s["frames_total"] == 6 and e["measured_frames"] == 0 and e["samples"] == 0
assert e["measure_every"] == 0
PY
