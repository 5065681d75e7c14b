#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# seamwalk --input-timeline end to end (issue 11, "Done when"): a scripted
# timeline drives a headless walk through the fake devices: a recorded
# F310 descriptor plugged at start, its left stick pushed and released, a
# bouncing GPIO button press (next viewpoint), the pad unplugged while its
# stick is pushed and plugged back, a missing GPIO chip. Checks the poses
# against what the navigation rules give, that the run goes on through the
# unplug, that no frame allocates, that a second run is identical, and
# that the poses match the committed golden log.
#   test_input_walk.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$1 src=$2
work=$build/tests/input_walk
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
walker=$build/firmware/seamwalk

# The teaset showroom with two named viewpoints (y up, floor y = 0).
cp "$src"/assets/samples/{teaset.ini,teapot.txt,teacup.txt,teaspoon.txt} "$work"/
cat >> "$work/teaset.ini" <<'INI'

[view front]
eye = 0 0.8 4
target = 0 0.5 0
up = 0 1 0

[view side]
eye = 4 0.8 0
target = 0 0.5 0
up = 0 1 0
INI
"$build/assets/seamwalk-pack" build "$work/teaset.ini" -o "$work/teaset.swpack" > /dev/null \
  || fail "build the teaset"

cat > "$work/unit.ini" <<INI
[display]
size = 64x48
[pack]
pack = $work/teaset.swpack
[render]
max_error_px = 4
[navigation]
walk_speed_mm_s = 1
eye_height_mm = 0.2
transition_s = 1
attract_timeout_s = 0
[gpio next]
chip = gpiochip0
line = 17
active_low = yes
action = next_view
[gpio gone]
chip = missing
line = 3
action = home
INI

desc=$src/tests/hid/logitech_f310_dinput.hex
cat > "$work/walk.timeline" <<TL
# F310 in D mode: X Y Z Rz, hat (8 = centred), buttons. 0x00 on Y: stick up.
0    pad 0 plug 0003 046d c216 0110 $desc F310
0.1  pad 0 report 80 00 80 80 08 00 00 00
1.0  pad 0 report 80 80 80 80 08 00 00 00
# the GPIO button (active low) bounces on press and on release
1.500 gpio next 0
1.501 gpio next 1
1.502 gpio next 0
1.503 gpio next 1
1.504 gpio next 0
1.700 gpio next 1
1.701 gpio next 0
1.702 gpio next 1
# walking again, then the pad is pulled out while its stick is pushed
2.6  pad 0 report 80 00 80 80 08 00 00 00
2.8  pad 0 unplug
# plugged back: found by the enumeration at 4 s
3.5  pad 0 plug 0003 046d c216 0110 $desc F310
4.1  pad 0 report 80 00 80 80 08 00 00 00
TL

run() {
  "$walker" --config "$work/unit.ini" --input-timeline "$work/walk.timeline" --frames 150 \
    --pose-log "$work/$1.poses" --stats "$work/$1.json" > /dev/null 2> "$work/$1.stderr"
}
run a || { cat "$work/a.stderr"; fail "the timeline walk exited $?"; }
grep -q "gamepad /dev/hidraw-fake0 unplugged" "$work/a.stderr" || fail "no unplug log line"
grep -q "\[gpio gone\] not used: missing: no such GPIO chip" "$work/a.stderr" \
  || fail "no log line for the missing chip"
[ "$(grep -c 'gamepad /dev/hidraw-fake0 (046d:c216' "$work/a.stderr")" -eq 2 ] \
  || fail "the pad was not found twice (plug, replug)"

python3 - "$work/a.poses" "$work/a.json" <<'PY' || fail "poses of the timeline walk"
import json, math, sys
rows = [l.split() for l in open(sys.argv[1]) if not l.startswith('#')]
eye = [tuple(map(float, r[2:5])) for r in rows]
mode = [r[11] for r in rows]
def dist(a, b): return math.dist(a, b)
assert len(rows) == 150, len(rows)
assert dist(eye[0], (0, 0.8, 4)) < 1e-6, eye[0]          # home: viewpoint "front"
# 27 frames of full stick from 0.1 s, then the glide: 21.5/30 + 5.5/30 units
moved = dist(eye[45], eye[0])
assert abs(moved - 0.9) < 0.005, moved
assert abs(eye[45][1] - 0.8) < 1e-9, eye[45]               # walking stays level
assert mode[40] == 'walk' and mode[47] == 'transition', (mode[40], mode[47])
# one next_view for the bouncing press: lands on "side" and stays there
land = mode.index('walk', 47)
assert dist(eye[land], (4, 0.8, 0)) < 1e-5, eye[land]
assert 'transition' not in mode[land:], 'a second transition: the bounce counted twice'
# unplugged at 2.8 s while pushed: glides to a stop, then stands still
assert dist(eye[84], eye[land]) > 0.05, 'did not walk from 2.6 s'
assert dist(eye[100], eye[119]) == 0, (eye[100], eye[119])
# replugged, found at 4 s, pushed from 4.1 s: walks again
assert dist(eye[149], eye[119]) > 0.3, dist(eye[149], eye[119])
s = json.load(open(sys.argv[2]))
assert s["frames"] == 150 and s["mallocs_after_init"] == 0, (s["frames"], s["mallocs_after_init"])
print("ok   timeline walk: %d frames, walked %.3f, landed on 'side' at frame %d, stood still "
      "after the unplug, walked after the replug; mallocs after init 0" % (len(rows), moved, land))
PY

run b || fail "the second run exited $?"
cmp -s "$work/a.poses" "$work/b.poses" || fail "the same timeline gave other poses"
echo "ok   the second run's poses are identical"

python3 - "$work/a.poses" "$src/tests/golden/input_walk.poses" <<'PY' || fail "golden poses"
import sys
a = [l.split() for l in open(sys.argv[1]) if not l.startswith('#')]
g = [l.split() for l in open(sys.argv[2]) if not l.startswith('#')]
assert len(a) == len(g), (len(a), len(g))
for ra, rg in zip(a, g):
    assert ra[11] == rg[11], (ra[0], ra[11], rg[11])
    worst = max(abs(float(x) - float(y)) for x, y in zip(ra[2:11], rg[2:11]))
    assert worst < 1e-5, (ra[0], worst)
print("ok   poses match tests/golden/input_walk.poses")
PY

# The real devices on a machine without them (this one: no GPIO chip, no
# controller): --navigate runs, each absence a log line, not a failure.
sed -e 's/^chip = missing/chip = gpiochip-absent/' "$work/unit.ini" > "$work/live.ini"
"$walker" --config "$work/live.ini" --navigate --frames 5 --stats "$work/live.json" \
  > /dev/null 2> "$work/live.stderr" || { cat "$work/live.stderr"; fail "--navigate without devices exited $?"; }
grep -q "\[gpio next\] not used: gpiochip0 line 17: no such GPIO chip" "$work/live.stderr" ||
  [ -e /dev/gpiochip0 ] || fail "no log line for the absent GPIO chip: $(cat "$work/live.stderr")"
echo "ok   --navigate without devices: $(wc -l < "$work/live.stderr") log lines, exit 0"
