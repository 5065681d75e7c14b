#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The threaded walk (issue 10: workers, budgets) against the walk without
# workers, side by side in one run:
#   walk_threads_bench.sh BUILD_DIR [--quick] [--repeats N] [--showroom PATCHES]
#                         [--frames N] [--json FILE]
# - the teaset orbit at 1280x720 (120 frames), seamwalk --workers 0 and
#   --workers 1 (the default on this 2-core machine), run alternately so both
#   see the same load;
# - with --showroom N: a generated showroom of N patches from ../shared/models
#   parts (the issue's figure is 40000), its orbit the same way.
# For each: frame p50 / p99, first frame (program start to the end of the
# first frame, less its measurement), measured error max, cracks, gaps in the
# seams as drawn, and with workers how far the work was behind (frames,
# bound ratio) and what of the budget it used; then the ratios workers /
# no workers of each alternate pair. Medians over the repeats with their
# spread (min..max). Never fails on timing, only when a walk fails.
# --quick: 320x240, 16 frames, 1 repeat.
set -euo pipefail
build=$1; shift
src=$(cd "$(dirname "$0")/../.." && pwd)
quick=0 repeats=3 showroom=0 json= frames=120
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=1; repeats=1 ;;
    --repeats) repeats=$2; shift ;;
    --showroom) showroom=$2; shift ;;
    --frames) frames=$2; shift ;;
    --json) json=$2; shift ;;
    *) echo "walk_threads_bench: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
size=1280x720
[ $quick -eq 1 ] && size=320x240 frames=16
work=$(mktemp -d "${TMPDIR:-/tmp}/swthreads.XXXXXX")
trap 'rm -rf "$work"' EXIT
pack_tool=$build/assets/seamwalk-pack walker=$build/firmware/seamwalk

# run SCENE PACK: each repeat walks --workers 0 then --workers 1 into
# $work/SCENE_wK.R.json (async: --sync-work 0 whatever the environment says).
run() {
  local scene=$1 pack=$2
  for r in $(seq 1 "$repeats"); do
    for k in 0 1; do
      "$walker" --pack "$pack" --headless $size --frames $frames --orbit --measure-every 4 \
        --memory-mb 4096 --workers $k --sync-work 0 --stats "$work/${scene}_w$k.$r.json" \
        > /dev/null || { echo "walk_threads_bench: $scene --workers $k failed" >&2; exit 1; }
    done
  done
}

"$pack_tool" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" --quiet
run teaset "$work/teaset.swpack"
scenes=teaset
if [ "$showroom" -gt 0 ]; then
  shared=$src/../shared/models
  "$pack_tool" gen showroom --patches "$showroom" -o "$work/showroom.ini" \
    --part "$shared/occt_hammer.iges" --part "$shared/occt_screw.step" \
    --part "$shared/newell_teapot.txt" > /dev/null
  "$pack_tool" build "$work/showroom.ini" -o "$work/showroom.swpack" --quiet
  run showroom "$work/showroom.swpack"
  scenes="$scenes showroom"
fi
python3 - "$work" "$repeats" "$size" "$json" $scenes <<'PY'
import json, statistics, sys
work, repeats, size, out, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5:]
def load(scene, k, r):
    return json.load(open("%s/%s_w%d.%d.json" % (work, scene, k, r)))
def spread(values):
    return [statistics.median(values), min(values), max(values)]
keys = (("frame_p50", lambda j: j["frame_ms"]["p50"]), ("frame_p99", lambda j: j["frame_ms"]["p99"]),
        ("first_frame_ms", lambda j: j["first_frame_ms"]), ("pack_open_ms", lambda j: j["pack_open_ms"]),
        ("error_max_px", lambda j: j["error_px"]["max"]), ("cracks", lambda j: j["cracks_max"]),
        ("gaps", lambda j: j["seam_drawn"]["gaps_max"]), ("tris", lambda j: j["tris_per_frame"]["median"]),
        ("frames_behind_max", lambda j: j["threads"]["frames_behind_max"]),
        ("behind_ratio_max", lambda j: j["threads"]["behind_ratio_max"]),
        ("waiting_max", lambda j: j["threads"]["waiting_surfaces_max"]),
        ("budget_used_mean", lambda j: j["threads"]["budget_used_mean"]),
        ("mallocs_after_init", lambda j: j["mallocs_after_init"]))
rows, ratios = {}, {}
for scene in scenes:
    for k in (0, 1):
        runs = [load(scene, k, r) for r in range(1, repeats + 1)]
        row = {name: spread([f(j) for j in runs]) for name, f in keys}
        rows["%s_workers%d" % (scene, k)] = row
        f = lambda n: "%.1f (%.1f..%.1f)" % tuple(row[n])
        print("%-10s --workers %d  frame p50 %s ms  p99 %s ms  first frame %s ms  error max %s px  "
              "cracks %d  gaps %d  triangles %d%s" % (
                  scene, k, f("frame_p50"), f("frame_p99"), f("first_frame_ms"),
                  "%.3f" % row["error_max_px"][2], row["cracks"][2], row["gaps"][2], row["tris"][0],
                  "" if k == 0 else "  frames behind %d  bound ratio %.2f  budget used %.2f" % (
                      row["frames_behind_max"][2], row["behind_ratio_max"][2],
                      row["budget_used_mean"][0])))
    pair = lambda name: spread([load(scene, 1, r)[name[0]][name[1]] / load(scene, 0, r)[name[0]][name[1]]
                                for r in range(1, repeats + 1)])
    ratios[scene] = {"frame_p50": pair(("frame_ms", "p50")), "frame_p99": pair(("frame_ms", "p99")),
                     "first_frame": spread([load(scene, 1, r)["first_frame_ms"] / load(scene, 0, r)["first_frame_ms"]
                                            for r in range(1, repeats + 1)])}
    q = ratios[scene]
    print("%-10s --workers 1 over 0 (pairs): frame p50 %.2fx (%.2f..%.2f), p99 %.2fx (%.2f..%.2f), "
          "first frame %.2fx (%.2f..%.2f)" % ((scene,) + tuple(q["frame_p50"]) + tuple(q["frame_p99"])
                                              + tuple(q["first_frame"])))
if out:
    json.dump({"bench": "walk_threads", "viewport": size, "repeats": repeats, "runs": rows,
               "ratios": ratios}, open(out, "w"), indent=1)
PY
