#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Seam Graph kept down to the closest view a pack is built for
# (seamwalk-pack build --closest-mm, assets/seam/sw_seam_reroot.h), and a
# view closer than that clamped and counted:
#   test_closest.sh BUILD_DIR SOURCE_DIR
# The teaset built as usual (a hundredth of its size: closer than the golden
# views) and for a closest view of 50 mm (its golden views, about 3 mm from
# the teapot, are far closer). Checks:
#   - the 50 mm pack holds fewer seam vertices than the usual one;
#   - walked at the golden views (320x240, every mesh made in its frame,
#     every frame measured), the usual pack clamps no surface, meets the
#     bound and passes the golden pictures; the 50 mm pack counts its
#     clamped surfaces on the summary line and in the stats, and the error
#     measured on the pictures' own samples exceeds the bound there (the
#     count agrees with a measure that does not share its bookkeeping),
#     with no crack and no gap in the drawn borders;
#   - the same views from ten times as far: the 50 mm pack clamps nothing
#     and its pictures match the usual pack's;
#   - --closest-mm without a length > 0 is a usage error.
set -uo pipefail
build=$1 src=$2
tool=$build/assets/seamwalk-pack walker=$build/firmware/seamwalk
compare=$build/tests/image_compare
work=$build/tests/closest
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

"$tool" build "$src/assets/samples/teaset.ini" -o "$work/usual.swpack" --quiet ||
  fail "build, usual"
"$tool" build "$src/assets/samples/teaset.ini" -o "$work/close.swpack" --quiet --closest-mm 50 ||
  fail "build, --closest-mm 50"
originals() { "$tool" info --json "$1" | python3 -c \
  'import json, sys; print(json.load(sys.stdin)["seam"]["original_vertices"])'; }
usual=$(originals "$work/usual.swpack") close=$(originals "$work/close.swpack")
echo "original seam vertices: $usual usual, $close for a closest view of 50 mm"
[ -n "$usual" ] && [ -n "$close" ] && [ "$close" -lt "$usual" ] ||
  fail "the 50 mm pack holds no fewer seam vertices"

# The golden views, and the same from ten times as far.
python3 - "$src/tests/golden/views.path" "$work/far.path" <<'PY'
import sys
out = []
for line in open(sys.argv[1]):
    f = line.split()
    if not f or f[0].startswith('#'):
        continue
    t, eye, target, up = f[0], list(map(float, f[1:4])), list(map(float, f[4:7])), f[7:10]
    far = [c + 10 * (e - c) for e, c in zip(eye, target)]
    out.append(' '.join([t] + ['%g' % x for x in far + target] + up))
open(sys.argv[2], 'w').write('\n'.join(out) + '\n')
PY

walk() {  # walk PACK PATH NAME: 3 frames, each its own view, all measured
  SEAMWALK_TEST_SYNC_WORK=1 "$walker" --pack "$1" --headless 320x240 --path "$2" --frames 3 \
    --part-levels 0 --measure-every 1 --png-dir "$work/$3" --stats "$work/$3.json" \
    > "$work/$3.log" 2>&1 || fail "walk $3: $(tail -n 3 "$work/$3.log")"
}
figures() {  # figures NAME: clamped, error max, bound, cracks, drawn gaps
  python3 - "$work/$1.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print(j["seam"]["surfaces_clamped_max"], j["error_px"]["max"], j["error_px"]["bound"],
      j["cracks_max"], j["seam_drawn"]["gaps_max"])
PY
}
walk "$work/usual.swpack" "$src/tests/golden/views.path" usual_near
walk "$work/close.swpack" "$src/tests/golden/views.path" close_near
walk "$work/usual.swpack" "$work/far.path" usual_far
walk "$work/close.swpack" "$work/far.path" close_far

read -r clamped err bound cracks gaps < <(figures usual_near)
echo "usual pack, golden views: clamped $clamped, error max $err px (bound $bound), cracks $cracks, gaps $gaps"
[ "$clamped" -eq 0 ] || fail "the usual pack clamped $clamped surfaces at the golden views"
python3 -c "import sys; sys.exit(not $err <= $bound)" || fail "the usual pack's error $err px"
for i in 0 1 2; do
  "$compare" "$work/usual_near/frame_0000$i.png" "$src/tests/golden/teaset_view$i.png" ||
    fail "the usual pack's view $i differs from its golden picture"
done

read -r clamped err bound cracks gaps < <(figures close_near)
echo "50 mm pack, golden views: clamped $clamped, error max $err px (bound $bound), cracks $cracks, gaps $gaps"
[ "$clamped" -gt 0 ] || fail "the 50 mm pack clamped nothing at views closer than 50 mm"
grep -q "clamped max $clamped " "$work/close_near.log" ||
  fail "the summary line does not say clamped max $clamped: $(head -n 1 "$work/close_near.log")"
python3 -c "import sys; sys.exit(not $err > $bound)" ||
  fail "clamped surfaces, yet the pictures' error $err px is within the bound"
[ "$cracks" -eq 0 ] && [ "$gaps" -eq 0 ] || fail "cracks $cracks, gaps $gaps in the clamped walk"

read -r clamped err bound cracks gaps < <(figures close_far)
echo "50 mm pack, ten times as far: clamped $clamped, error max $err px (bound $bound)"
[ "$clamped" -eq 0 ] || fail "the 50 mm pack clamped $clamped surfaces ten times as far"
python3 -c "import sys; sys.exit(not $err <= $bound)" || fail "error $err px ten times as far"
for i in 0 1 2; do
  "$compare" "$work/close_far/frame_0000$i.png" "$work/usual_far/frame_0000$i.png" ||
    fail "view $i from ten times as far: the 50 mm pack's picture differs from the usual one's"
done

for bad in 0 -3 abc; do
  "$tool" build "$src/assets/samples/teaset.ini" -o "$work/bad.swpack" --closest-mm "$bad" \
    > /dev/null 2> "$work/bad.err"
  code=$?
  [ "$code" -eq 2 ] && grep -q -- "--closest-mm" "$work/bad.err" && [ ! -e "$work/bad.swpack" ] ||
    fail "--closest-mm $bad: exit $code, $(cat "$work/bad.err")"
done
echo "ok: closest view kept, clamped and counted"
