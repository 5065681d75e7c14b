#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The picture comparison of tests/walk_pictures.py can fail, and does not
# fail without cause:
#   test_walk_pictures.sh BUILD_DIR SOURCE_DIR
# A showroom of 2,000 patches (seamwalk-pack gen showroom with walk_bench's
# four parts from ../shared/models) walked round its middle
# (tests/bench/walk_path.py, as walk_bench makes its paths), 120 frames at
# 640x360, every 10th frame's picture against the reference walk
# (--workers 0):
# - the same walk with --workers 0: no interior background pixel and no
#   pixel differing (the same program draws the same pictures), exit 0;
# - the mutant --test-drop-surface N, N the flat plate nearest the path
#   (so in view: lying on the floor beside the walk, nothing behind it but
#   the background), --workers 0: the plate's pixels must show as interior
#   background (exit 1, more than 0 px).
# - the whole showroom in view (--orbit) as the kiosk service walks it,
#   far parts drawn from their part levels: within the targets (no interior
#   background, at most 0.5% differing) and at least one part drawn so; the
#   mutant --test-part-levels-coarsest 1 must miss them (exit 1).
# Exit 77: ../shared/models is absent; with it present a missing
# part fails.
set -uo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
tool=$build/assets/seamwalk-pack
work=$build/tests/walk_pictures
shared=$src/../shared/models
fail() { echo "FAIL: $*"; exit 1; }
[ -d "$shared" ] || { echo "skipped: $shared is absent"; exit 77; }
parts=(occt_hammer.iges occt_screw.step newell_teapot.txt nist_mbe_pmi_1.stp)
gen=(gen showroom --patches 2000 -o "$work/showroom.ini")
for p in "${parts[@]}"; do
  [ -f "$shared/$p" ] || fail "$shared/$p is missing (walk_bench's showroom part)"
  gen+=(--part "$shared/$p")
done
rm -rf "$work" && mkdir -p "$work"

"$tool" "${gen[@]}" > "$work/gen.log" 2>&1 || fail "gen showroom: $(tail -n 3 "$work/gen.log")"
"$tool" build "$work/showroom.ini" -o "$work/showroom.swpack" --quiet > "$work/build.log" 2>&1 \
  || fail "build: $(tail -n 3 "$work/build.log")"
"$tool" info --json "$work/showroom.swpack" > "$work/info.json" || fail "info"

# The path as walk_bench makes it, and the plate: parts are packed in the
# scene's order, each part's surfaces after the last part's, so a part's
# first surface is the sum of the surfaces before it. Distance is measured
# on the floor from the plate's centre to the walk's keys joined in order.
python3 - "$work/info.json" "$work/showroom.path" "$src/tests/bench/walk_path.py" \
    > "$work/plate.txt" <<'EOF' || fail "path or plate: $(cat "$work/plate.txt")"
import json, math, subprocess, sys
info = json.load(open(sys.argv[1]))
box = info["box"]["min"] + info["box"]["max"]
up = info["up_axis"].lstrip("+-")
subprocess.run([sys.executable, sys.argv[3], sys.argv[2], "--box"] +
               ["%.6f" % v for v in box] + ["--up", up, "--seconds", "40"], check=True)
u = 1 if up == "y" else 2
h0, h1 = (0, 2) if up == "y" else (0, 1)
keys = [[float(v) for v in line.split()] for line in open(sys.argv[2])
        if line.strip() and not line.startswith("#")]
floor = [(k[1 + h0], k[1 + h1]) for k in keys]

def to_walk(p):
    best = math.inf
    for (a0, a1), (b0, b1) in zip(floor, floor[1:]):
        d0, d1 = b0 - a0, b1 - a1
        t = max(0.0, min(1.0, ((p[0] - a0) * d0 + (p[1] - a1) * d1) / (d0 * d0 + d1 * d1 or 1)))
        best = min(best, math.hypot(p[0] - a0 - t * d0, p[1] - a1 - t * d1))
    return best

first, plates = 0, []
for part in info["parts"]:
    lo, hi = part["box"]["min"], part["box"]["max"]
    if part["name"].startswith("plate_") and part["surfaces"] == 1 and hi[u] - lo[u] < 1e-3:
        centre = ((lo[h0] + hi[h0]) / 2, (lo[h1] + hi[h1]) / 2)
        plates.append((to_walk(centre), first, part["name"]))
    first += part["surfaces"]
if not plates:
    sys.exit("no flat plate in the showroom")
d, surface, name = min(plates)
print(surface, name, "%.0f" % d)
EOF
read -r surface plate distance < "$work/plate.txt"
echo "ok   showroom of 2000 patches; the mutant leaves out surface $surface ($plate, $distance mm from the walk)"

pictures() {   # pictures NAME ARGS...: walk_pictures.py into work/NAME, its exit status
  local name=$1
  shift
  python3 "$src/tests/walk_pictures.py" "$work/showroom.swpack" "$work/showroom.path" "$build" \
    "$work/$name" 640x360 120 --json "$work/$name.json" "$@" > "$work/$name.out" 2>&1
  local rc=$?
  sed "s|$work/||g; s/^/  /" "$work/$name.out" | tail -n 6
  return $rc
}
# figure FILE KEY...: the JSON figure at that path of keys
figure() {
  python3 -c "import json,sys
v = json.load(open(sys.argv[1]))
for k in sys.argv[2:]: v = v[k]
print(v)" "$@"
}

pictures same --workers 0 --part-levels 0 --max-differing 0
rc=$?
[ $rc -eq 0 ] || fail "--workers 0 against itself: exit $rc (0 expected; $work/same.out)"
[ "$(figure "$work/same.json" interior_background_px_max)" -eq 0 ] || fail "same: holes"
echo "ok   --workers 0 against the reference: no interior background, no pixel differs"

pictures drop --workers 0 --part-levels 0 --test-drop-surface "$surface"
rc=$?
[ $rc -eq 1 ] || fail "without surface $surface: exit $rc (1 expected: the missing plate; $work/drop.out)"
holes=$(figure "$work/drop.json" interior_background_px_max)
[ "$holes" -gt 0 ] || fail "without surface $surface: no interior background pixel"
echo "ok   without surface $surface: $holes interior background px (frame $(figure "$work/drop.json" interior_background_frame))"

# The whole showroom in view (--orbit), walked as the kiosk service walks
# it: far parts are drawn whole from their part levels, and the pictures
# must still meet the targets; the mutant drawing every part from its
# coarsest level must not.
orbit() { # orbit NAME FLAGS...: 16 frames, every one compared
  local name=$1
  shift
  python3 "$src/tests/walk_pictures.py" "$work/showroom.swpack" orbit "$build" "$work/$name" \
    640x360 16 --every 1 --max-differing 0.005 --json "$work/$name.json" "$@" \
    > "$work/$name.out" 2>&1
  local rc=$?
  sed "s|$work/||g; s/^/  /" "$work/$name.out" | tail -n 6
  return $rc
}
orbit orbit
rc=$?
[ $rc -eq 0 ] || fail "the orbit with part levels: exit $rc (0 expected; $work/orbit.out)"
parts=$(figure "$work/orbit/test.json" part_levels parts_max)
[ "$parts" -gt 0 ] || fail "the orbit drew no part from a part level"
# Stand-ins far finer than their bound are replaced by the walk's own
# meshes when the workers have budget left: those pictures are the ones
# judged above.
leaner=$(figure "$work/orbit/test.json" threads standins_leaner_jobs)
[ "$leaner" -gt 0 ] || fail "the orbit gave no stand-in a leaner mesh of the walk's own"
echo "ok   the orbit: $parts parts drawn from part levels, $leaner stand-ins given leaner meshes, pictures within the targets"
orbit coarsest --test-part-levels-coarsest 1
rc=$?
[ $rc -eq 1 ] || fail "every part at its coarsest level: exit $rc (1 expected; $work/coarsest.out)"
echo "ok   every part at its coarsest level: $(figure "$work/coarsest.json" differing_fraction_max) of the pixels differ"
