#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Wayland developer window for real: Weston's headless backend with its
# pixman renderer as the compositor, Mesa's EGL on Wayland with llvmpipe
# (wl_shm buffers) as the client. seamwalk --display wayland must give the
# same frames as --headless (image_compare), no mallocs after init, and auto
# must choose Wayland when WAYLAND_DISPLAY is set (before X11).
# Weston's headless backend has no input devices, so the wl_keyboard path is
# not exercised here. Skips (exit 77) only where weston is not installed;
# cmake/install-deps.sh installs it, so CI runs it.
#   test_display_wayland.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$(cd "$1" && pwd) src=$2
command -v weston > /dev/null || { echo "SKIP: weston is not installed (Debian: weston)"; exit 77; }
work=$build/tests/display_wayland
rm -rf "$work" && mkdir -p "$work/xdg" && chmod 700 "$work/xdg"
fail() { echo "FAIL: $*"; [ -f "$work/weston.log" ] && tail -20 "$work/weston.log"; exit 1; }

export XDG_RUNTIME_DIR=$work/xdg
socket=sw-test-$$
weston --no-config --backend=headless-backend.so --use-pixman --socket="$socket" \
  --width=640 --height=480 --idle-time=0 > "$work/weston.log" 2>&1 &
compositor=$!
trap 'kill "$compositor" 2> /dev/null; wait "$compositor" 2> /dev/null' EXIT
for _ in $(seq 100); do [ -S "$XDG_RUNTIME_DIR/$socket" ] && break; sleep 0.1; done
[ -S "$XDG_RUNTIME_DIR/$socket" ] || fail "weston did not start"
export WAYLAND_DISPLAY=$socket
unset DISPLAY

"$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" \
  > /dev/null || fail "build the teaset"
walker=$build/firmware/seamwalk
common=(--pack "$work/teaset.swpack" --orbit --frames 4 --png-every 1)
"$walker" "${common[@]}" --display wayland --size 320x240 --png-dir "$work/wayland" \
  --stats "$work/wayland.json" > "$work/wayland.out" || fail "walk in the Wayland window"
grep -q "^seamwalk: display wayland 320x240 (asked for wayland)" "$work/wayland.out" \
  || fail "the summary names the display: $(cat "$work/wayland.out")"
"$walker" "${common[@]}" --headless 320x240 --png-dir "$work/headless" > /dev/null \
  || fail "walk headless"
for f in "$work"/headless/frame_*.png; do
  "$build/tests/image_compare" "$f" "$work/wayland/$(basename "$f")" || fail "$(basename "$f") differs"
done
python3 - "$work/wayland.json" <<'PY' || fail "stats of the Wayland walk"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["mallocs_after_init"] == 0, s["mallocs_after_init"]
assert s["viewport"] == [320, 240], s["viewport"]
assert s["frames"] == 4, s["frames"]
PY
DISPLAY=:4242 "$walker" "${common[@]}" --size 160x120 --frames 1 > "$work/auto.out" \
  || fail "walk with auto"
grep -q "^seamwalk: display wayland 160x120 (auto: WAYLAND_DISPLAY is set and EGL offers Wayland)" \
  "$work/auto.out" || fail "auto did not choose wayland: $(cat "$work/auto.out")"
echo "ok: Wayland window on $WAYLAND_DISPLAY"
