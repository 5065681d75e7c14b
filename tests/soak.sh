#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The soak: seamwalk walks a looping path for a while and
# its resident memory must stay flat and its code allocate nothing.
#   soak.sh BUILD_DIR [--duration S] [--pack PACK] [--path FILE]
#           [--size WxH] [--frames N] [--max-growth-kb K] [--stats FILE]
#           [--test-grow-kb K]
# Default: the teaset (built into a temporary folder) orbited at 640x360 in
# loops of 120 frames for 20 s. The 10-minute soak on the 40,000-patch
# showroom (docs/testing.md, "The soak"):
#   bash tests/soak.sh build --duration 600 --pack showroom.swpack --size 1280x720
# Fails (exit 1) when the walk fails, when mallocs_after_init is not 0, when
# it walked fewer than two loops, or when resident memory at the end exceeds
# what it was after the first quarter of the loops (at least the first loop)
# by more than --max-growth-kb (default 2048). The arena and the GL buffers
# are touched at start; the driver's heap may still take one more step of a
# few MB in the next loops (glibc's heaps grow by whole megabytes), which is
# warm-up; a leak keeps growing through the rest of the run, and that is what
# the check is for. Never fails on timing; prints the figures either way.
# --test-grow-kb K makes seamwalk grow K kB resident at each loop's end (no
# allocation): the check must then fail (CTest soak_catches_growth).
set -euo pipefail
build=$1; shift
src=$(cd "$(dirname "$0")/.." && pwd)
duration=20 pack= path= size=640x360 frames=120 growth=2048 stats= grow=0
while [ $# -gt 0 ]; do
  case $1 in
    --duration) duration=$2; shift ;;
    --pack) pack=$2; shift ;;
    --path) path=$2; shift ;;
    --size) size=$2; shift ;;
    --frames) frames=$2; shift ;;
    --max-growth-kb) growth=$2; shift ;;
    --stats) stats=$2; shift ;;
    --test-grow-kb) grow=$2; shift ;;
    *) echo "soak: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
work=$(mktemp -d "${TMPDIR:-/tmp}/swsoak.XXXXXX")
trap 'rm -rf "$work"' EXIT
if [ -z "$pack" ]; then
  pack=$work/teaset.swpack
  "$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$pack" --quiet
fi
[ -n "$stats" ] || stats=$work/soak.json
route=(--orbit)
[ -n "$path" ] && route=(--path "$path")
"$build/firmware/seamwalk" --pack "$pack" "${route[@]}" --headless "$size" --frames "$frames" \
  --duration "$duration" --memory-mb 8192 --measure-every 1000000 --stats "$stats" \
  --test-grow-kb "$grow" \
  || { echo "soak: the walk failed" >&2; exit 1; }
python3 - "$stats" "$growth" <<'PY'
import json, sys
s, growth = json.load(open(sys.argv[1])), int(sys.argv[2])
rss = s["rss_kb"]
fails = []
if s["mallocs_after_init"] != 0:
    fails.append("mallocs_after_init is %s, not 0" % s["mallocs_after_init"])
if s["soak"]["loops"] < 2:
    fails.append("only %d loop(s) walked: too short to tell" % s["soak"]["loops"])
if min(rss.values()) <= 0:
    fails.append("resident memory not read: %s" % rss)
else:
    per_loop = s["soak"]["rss_kb_per_loop"]
    warm = max(0, len(per_loop) // 4 - 1)
    base = per_loop[warm] if per_loop else rss["after_first_loop"]
    if rss["end"] - base > growth:
        fails.append("resident memory grew by %d kB after loop %d of %d (allowed %d)"
                     % (rss["end"] - base, warm + 1, s["soak"]["loops"], growth))
print("soak: %.0f s, %d frames in %d loops of %d; frame p50 %.1f ms, p99 %.1f ms (last loop), "
      "worst %.1f ms (frame %d); resident kB: start %d, after the first loop %d, end %d "
      "(growth %+d), peak %d; mallocs_after_init %d"
      % (s["soak"]["duration_s"], s["frames_total"], s["soak"]["loops"],
         s["soak"]["frames_per_loop"], s["frame_ms"]["p50"], s["frame_ms"]["p99"],
         s["worst_frame"]["ms"], s["worst_frame"]["frame"], rss["start"],
         rss["after_first_loop"], rss["end"], rss["end"] - rss["after_first_loop"],
         rss["peak"], s["mallocs_after_init"]))
print("soak: resident kB at the end of each loop: %s" % s["soak"]["rss_kb_per_loop"])
for f in fails:
    print("soak: FAIL: " + f)
sys.exit(1 if fails else 0)
PY
