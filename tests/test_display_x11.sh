#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The X11 developer window for real: Xvfb (a virtual X server) with Mesa's
# llvmpipe. Runs tests/test_display_x11 (draw, read back, keys, close), then
# seamwalk --display x11 against --headless: the same frames (image_compare),
# no mallocs after init, and auto choosing x11 when DISPLAY is set.
# Skips (exit 77) only where Xvfb is not installed; cmake/install-deps.sh
# installs it, so CI runs it.
#   test_display_x11.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$1 src=$2
command -v Xvfb > /dev/null || { echo "SKIP: Xvfb is not installed (Debian: xvfb)"; exit 77; }
work=$build/tests/display_x11
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# -displayfd: Xvfb picks a free display number and writes it when ready.
Xvfb -displayfd 5 -screen 0 1024x768x24 -nolisten tcp 5> "$work/display" 2> "$work/xvfb.log" &
xvfb=$!
trap 'kill "$xvfb" 2> /dev/null; wait "$xvfb" 2> /dev/null' EXIT
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || fail "Xvfb did not start: $(cat "$work/xvfb.log")"
export DISPLAY=:$(tr -d '\n' < "$work/display")
unset WAYLAND_DISPLAY

"$build/tests/test_display_x11" || fail "test_display_x11"

"$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" \
  > /dev/null || fail "build the teaset"
walker=$build/firmware/seamwalk
common=(--pack "$work/teaset.swpack" --orbit --frames 4 --png-every 1)
"$walker" "${common[@]}" --display x11 --size 320x240 --png-dir "$work/x11" \
  --stats "$work/x11.json" > "$work/x11.out" || fail "walk in the X11 window"
grep -q "^seamwalk: display x11 320x240 (asked for x11)" "$work/x11.out" \
  || fail "the summary names the display: $(cat "$work/x11.out")"
"$walker" "${common[@]}" --headless 320x240 --png-dir "$work/headless" > /dev/null \
  || fail "walk headless"
for f in "$work"/headless/frame_*.png; do
  "$build/tests/image_compare" "$f" "$work/x11/$(basename "$f")" || fail "$(basename "$f") differs"
done
python3 - "$work/x11.json" <<'PY' || fail "stats of the X11 walk"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["mallocs_after_init"] == 0, s["mallocs_after_init"]
assert s["viewport"] == [320, 240], s["viewport"]
assert s["frames"] == 4, s["frames"]
PY
"$walker" "${common[@]}" --size 160x120 --frames 1 > "$work/auto.out" || fail "walk with auto"
grep -q "^seamwalk: display x11 160x120 (auto: DISPLAY is set and EGL offers X11)" \
  "$work/auto.out" || fail "auto did not choose x11: $(cat "$work/auto.out")"
# --navigate in the window: another client holds Up for 1.5 s, as a
# developer at the keyboard would; the window's keys drive the input step
# (platform/input/sw_window_keys.c), so the eye walks forward. SIGTERM ends the
# walk after the key, through the normal exit. The key waits for the first
# frame's pose: the window opens while the pack still loads, and a press
# and release both queued before the first frame walk nowhere (seen under
# TSan on a loaded machine: 3 frames, 0 mm).
"$walker" --pack "$work/teaset.swpack" --navigate --display x11 --size 160x120 --frames 100000 \
  --pose-log "$work/nav.poses" --stats "$work/nav.json" > "$work/nav.out" 2>&1 &
nav=$!
for _ in $(seq 600); do
  grep -q '^[0-9]' "$work/nav.poses" 2>/dev/null && break
  kill -0 "$nav" 2>/dev/null || break
  sleep 0.1
done
"$build/tests/x11_send_key" seamwalk Up 1.5 20 || { kill "$nav"; fail "no seamwalk window to press a key in"; }
sleep 0.5
kill -TERM "$nav"
wait "$nav" || fail "walk --navigate in the X11 window: $(cat "$work/nav.out")"
python3 - "$work/nav.poses" "$work/nav.json" <<'PY' || fail "the Up key did not walk: $(cat "$work/nav.out")"
import json, math, sys
rows = [l.split() for l in open(sys.argv[1]) if not l.startswith("#")]
first, last = [float(v) for v in rows[0][2:5]], [float(v) for v in rows[-1][2:5]]
moved = math.dist(first, last)
assert moved > 1.0, moved      # mm: the default walk speed for about 1.5 s
assert json.load(open(sys.argv[2]))["mallocs_after_init"] == 0
print("the Up key walked the eye %.1f mm over %d frames" % (moved, len(rows)))
PY
echo "ok: X11 window on $DISPLAY"
