#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Culling that scales (issue 10, item 4): the culling tree against testing
# every patch box every frame (seamwalk --cull brute), and cone culling on
# and off with back faces hidden, side by side in one run:
#   cull_bench.sh BUILD_DIR [--patches N] [--pack FILE] [--frames F]
#                 [--repeats R] [--size WxH] [--json FILE]
# On a generated showroom of N patches (default 40,000; from the hammer,
# screw and teapot of ../shared/models, as tests/bench/walk_cache_bench.sh
# builds it; --pack reuses a pack built so) at 1280x720 (--size), three camera
# setups: its orbit (F frames, default 60), a walk at eye height from the
# entrance through the hall (F frames) and the entrance viewpoint still.
# Each walk runs R times (default 3), the methods alternating; the figures
# come from the walk's stats JSON ("cull": box tests and milliseconds of
# the frustum culling a frame; cone_culled; frame_ms). Prints medians over
# the repeats with their spread (min..max) and the ratios brute / tree;
# never fails on timing, only when a walk fails.
set -euo pipefail
build=$1; shift
src=$(cd "$(dirname "$0")/../.." && pwd)
patches=40000 pack= frames=60 repeats=3 json= size=1280x720
while [ $# -gt 0 ]; do
  case $1 in
    --patches) patches=$2; shift ;;
    --pack) pack=$2; shift ;;
    --frames) frames=$2; shift ;;
    --repeats) repeats=$2; shift ;;
    --json) json=$2; shift ;;
    --size) size=$2; shift ;;
    *) echo "cull_bench: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
work=$(mktemp -d "${TMPDIR:-/tmp}/swcull.XXXXXX")
trap 'rm -rf "$work"' EXIT
tool=$build/assets/seamwalk-pack walker=$build/firmware/seamwalk
if [ -z "$pack" ]; then
  shared=$src/../shared/models
  "$tool" gen showroom --patches "$patches" -o "$work/showroom.ini" \
    --part "$shared/occt_hammer.iges" --part "$shared/occt_screw.step" \
    --part "$shared/newell_teapot.txt" > /dev/null
  pack=$work/showroom.swpack
  "$tool" build "$work/showroom.ini" -o "$pack" --quiet
fi
# The hall walk: in at the entrance at eye height, down the middle, a turn
# to each side (the showroom's floor is y = 0, its entrance at z = -45,500).
cat > "$work/hall.path" <<'EOF'
0   0 1700 -45500    0 1000 -38500   0 1 0
1   0 1700 -30000    8000 1000 -24000   0 1 0
2   0 1700 -15000   -8000 1000 -9000   0 1 0
3   0 1700      0    0 1000   7000   0 1 0
4   0 1700  15000    9000 1200 21000   0 1 0
EOF

# run NAME K ARGS...: one walk into $work/NAME.K.json
run() {
  local name=$1 k=$2; shift 2
  "$walker" --pack "$pack" --headless "$size" --measure-every 100000 --memory-mb 4096 \
    --stats "$work/$name.$k.json" "$@" > "$work/$name.$k.log" 2>&1 \
    || { echo "cull_bench: walk $name failed: $(tail -n 2 "$work/$name.$k.log")" >&2; exit 1; }
}
names=
for setup in orbit hall still; do
  case $setup in
    orbit) how=(--orbit --frames "$frames") ;;
    hall) how=(--path "$work/hall.path" --frames "$frames") ;;
    still) how=(--view entrance --frames "$frames") ;;
  esac
  for k in $(seq 1 "$repeats"); do
    run "$setup.brute" "$k" "${how[@]}" --cull brute
    run "$setup.tree" "$k" "${how[@]}"
    run "$setup.lit" "$k" "${how[@]}" --back-faces hidden --cone-cull 0
    run "$setup.cones" "$k" "${how[@]}" --back-faces hidden
  done
  names="$names $setup"
done
python3 - "$work" "$repeats" "$pack" "$json" $names <<'PY'
import json, statistics, sys
work, repeats, pack, out, setups = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5:]
def runs(name):
    return [json.load(open("%s/%s.%d.json" % (work, name, k))) for k in range(1, repeats + 1)]
def spread(values):
    return [statistics.median(values), min(values), max(values)]
fields = (("box_tests_p50", lambda j: j["cull"]["box_tests"]["p50"]),
          ("box_tests_max", lambda j: j["cull"]["box_tests"]["max"]),
          ("cull_ms_p50", lambda j: j["cull"]["ms"]["p50"]),
          ("cull_ms_p99", lambda j: j["cull"]["ms"]["p99"]),
          ("cone_culled_p50", lambda j: j["cull"]["cone_culled"]["p50"]),
          ("frame_ms_p50", lambda j: j["frame_ms"]["p50"]),
          ("tris_p50", lambda j: j["tris_per_frame"]["median"]))
result = {"pack": pack, "repeats": repeats, "setups": {}}
fmt = lambda v, p: ("%%.%df (%%.%df..%%.%df)" % (p, p, p)) % tuple(v)
for s in setups:
    rows = {m: {k: spread([f(j) for j in runs("%s.%s" % (s, m))]) for k, f in fields}
            for m in ("brute", "tree", "lit", "cones")}
    result["setups"][s] = rows
    b, t, l, c = rows["brute"], rows["tree"], rows["lit"], rows["cones"]
    print("%s (median of %d, min..max):" % (s, repeats))
    print("  frustum, every patch box: box tests %s a frame (max %s), cull %s ms (p99 %s)"
          % (fmt(b["box_tests_p50"], 0), fmt(b["box_tests_max"], 0), fmt(b["cull_ms_p50"], 3),
             fmt(b["cull_ms_p99"], 3)))
    print("  frustum, culling tree:    box tests %s a frame (max %s), cull %s ms (p99 %s)"
          % (fmt(t["box_tests_p50"], 0), fmt(t["box_tests_max"], 0), fmt(t["cull_ms_p50"], 3),
             fmt(t["cull_ms_p99"], 3)))
    ratio = lambda a, z: a / z if z > 0 else float("inf")
    print("  ratio every box / tree: box tests %.0fx, cull ms %.2fx (medians)"
          % (ratio(b["box_tests_p50"][0], t["box_tests_p50"][0]),
             ratio(b["cull_ms_p50"][0], t["cull_ms_p50"][0])))
    print("  back faces hidden: cone culling off frame %s ms, %s tris; on: frame %s ms, %s tris, "
          "%s surfaces culled a frame" % (fmt(l["frame_ms_p50"], 1), fmt(l["tris_p50"], 0),
                                           fmt(c["frame_ms_p50"], 1), fmt(c["tris_p50"], 0),
                                           fmt(c["cone_culled_p50"], 0)))
if out:
    json.dump(result, open(out, "w"), indent=1)
PY
