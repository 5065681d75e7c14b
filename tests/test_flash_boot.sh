#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# seamwalk --store, the boot side of the pack store: a pending slot runs on
# trial and is marked good after healthy frames; one that fails to load, or
# never runs healthy, gets K boots and then the unit falls back to the good
# slot and says so; boots of the good slot are never counted, so repeated
# power cuts cannot use it up; a unit with no valid slot shows the message
# screen (its PNG read back here) instead of a black display. The unit
# shows its frames on a display, here an X11 window on Xvfb: a headless
# walk shows nobody anything, so it never marks a pending slot good.
#   test_flash_boot.sh SEAMWALK SEAMWALK_FLASH FAULT_SHIM FIXTURE WORK
set -uo pipefail
if [ "$(id -u)" != 0 ]; then  # the unit's trusted keys must be root's (firmware/store/STORE.md)
  echo "skipped: needs root, for trusted keys owned by root"
  exit 77
fi
command -v Xvfb >/dev/null || { echo "skipped: Xvfb is not installed (Debian: xvfb)"; exit 77; }
walker=$1 flash=$2 shim=$3 fixture=$4 work=$5
rm -rf "$work" && mkdir -p "$work"
Xvfb -displayfd 5 -screen 0 640x480x24 -nolisten tcp 5>"$work/display" 2>"$work/xvfb.log" &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null' EXIT
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || { echo "FAIL: Xvfb did not start: $(cat "$work/xvfb.log")"; exit 1; }
export DISPLAY=:$(tr -d '\n' <"$work/display")
unset WAYLAND_DISPLAY
unit=$work/unit
keys=$fixture/keys cfg=$fixture/unit.ini
failures=0 checks=0
check() { checks=$((checks + 1)); if ! "${@:2}"; then echo "FAIL: $1"; failures=$((failures + 1)); fi; }
display=(--display x11 --size 160x120)
boot() {  # boot ARGS...: one boot of the unit; its exit code in $work/rc, its log in $work/log
  "$walker" --store "$unit" --keys "$keys" "${display[@]}" --orbit --frames 3 \
    --stats "$work/stats.json" "$@" >"$work/log" 2>&1
  echo $? >"$work/rc"
}
rc() { [ "$(cat "$work/rc")" = "$1" ]; }
not_rc() { [ "$(cat "$work/rc")" != "$1" ]; }
logged() { grep -q -- "$1" "$work/log"; }
not_logged() { ! grep -q -- "$1" "$work/log"; }
stat_is() { python3 -c "import json,sys; s=json.load(open('$work/stats.json'))['store']; \
sys.exit(0 if str(s[sys.argv[1]]) == sys.argv[2] else 1)" "$1" "$2"; }
state() { "$flash" status --store "$unit" --config "$cfg" >"$work/status" 2>&1; grep -q -- "$1" "$work/status"; }

# ---- no valid slot: the message screen ----------------------------------------
mkdir -p "$unit"
boot --png-dir "$work/png"
check "no pack: exit 3" rc 3
check "no pack: the log says so" logged "no valid pack in $unit: showing the message screen"
check "no pack: the stats say so" stat_is message_screen "NO VALID PACK"
check "no pack: no slot ran" stat_is slot "-"
# The frame, read back from the PNG: mostly the message background, some
# white text, nothing else, and certainly not black.
check "no pack: the frame shows the message" python3 - "$work/png/frame_00000.png" <<'EOF'
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n'
pos, idat, w = 8, b'', 0
while pos < len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b'IHDR':
        w, h, depth, colour = struct.unpack('>IIBB', body[:10])
        assert depth == 8 and colour == 2, (depth, colour)
    elif kind == b'IDAT':
        idat += body
    pos += 12 + n
raw, stride, rows, prev = zlib.decompress(idat), w * 3, [], bytearray(w * 3)
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for x in range(stride):
        a = line[x - 3] if x >= 3 else 0
        b, c = prev[x], prev[x - 3] if x >= 3 else 0
        p = a + b - c
        pred = [0, a, b, (a + b) // 2,
                a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c][f]
        line[x] = (line[x] + pred) & 255
    rows.append(line)
    prev = line
pixels = [bytes(r[i:i + 3]) for r in rows for i in range(0, stride, 3)]
bg, text = sum(p == b'\x80\x10\x10' for p in pixels), sum(p == b'\xff\xff\xff' for p in pixels)
print(f"message frame {w}x{h}: {bg} background, {text} text, {len(pixels) - bg - text} other pixels")
sys.exit(0 if bg > len(pixels) // 2 and text > len(pixels) // 50 and bg + text == len(pixels) else 1)
EOF

# ---- headless: frames nobody sees never mark a pending slot good ----------------------
"$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/old.swpack" >/dev/null
display=(--headless 160x120)
boot --good-after-s 0
display=(--display x11 --size 160x120)
check "headless: runs" rc 0
check "headless: on trial" logged "starting slot A ('spoon-1' version 1), pending: boot attempt 1"
check "headless: says why it stays pending" logged "slot A stays pending: the display is headless"
check "headless: not marked good" not_logged "ran healthy for .* s: marked good"
check "headless: the stats say not marked" stat_is marked_good 0
check "headless: the state still says pending" state "pending: A (1 boots so far)"

# ---- a display that does not come up: no boot attempt spent -------------------------
# (a DRM device that comes up late at boot: the run fails and the service
# starts it again; those runs must not use up the pending slot's boots)
[ -e /tmp/.X11-unix/X9999 ] && { echo "FAIL: an X server on :9999, the test's missing display"; exit 1; }
for k in 1 2 3; do
  DISPLAY=:9999 boot --good-after-s 0
  check "no display $k: fails" not_rc 0
  check "no display $k: says why" logged "cannot open the X display ':9999'"
  check "no display $k: no slot started" not_logged "starting slot"
done
check "no display: no boot attempt spent" state "pending: A (1 boots so far)"

# ---- a pending slot is marked good after healthy frames ----------------------------
boot --good-after-s 0
check "first pack: runs" rc 0
check "first pack: on trial" logged "starting slot A ('spoon-1' version 1), pending: boot attempt 2"
check "first pack: marked good" logged "slot A ran healthy for .* s: marked good"
check "first pack: stats" stat_is marked_good 1
check "no heap calls after start, mark-good included" python3 -c \
  "import json; assert json.load(open('$work/stats.json'))['mallocs_after_init'] == 0"
check "first pack: the state says good" state "active: A"
boot --good-after-s 1e9
check "a good slot: runs, not on trial" logged "starting slot A ('spoon-1' version 1), good"

# ---- K boots that never run healthy (power cuts), then the fallback ----------------
"$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/new.swpack" >/dev/null
for k in 1 2; do
  boot --good-after-s 1e9 --boot-attempts 2
  check "trial $k: the new pack starts" logged "starting slot B ('cup-2' version 2), pending: boot attempt $k"
done
for k in 1 2 3 4 5; do
  boot --good-after-s 1e9 --boot-attempts 2
  check "boot $k after the tries: the good slot" logged "starting slot A ('spoon-1' version 1), good"
  if [ "$k" = 1 ]; then
    check "the fallback is said" logged "slot B ('cup-2' version 2) did not run healthy in 2 boots: falling back to slot A"
  else
    check "and said only once" not_logged "did not run healthy"
  fi
done
check "slot B is bad" state "slot B: bad"
check "slot A still active" state "active: A"

# ---- a pending slot that fails to load K times rolls back --------------------------
"$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/new.swpack" >/dev/null
printf 'X' | dd of="$unit/slot-b.swpack" bs=1 seek=5000 conv=notrunc status=none
for k in 1 2 3; do
  boot --good-after-s 0
  check "broken trial $k: said" logged "slot B does not start"
  check "broken trial $k: the good slot runs instead" logged "starting slot A ('spoon-1' version 1), good"
done
boot --good-after-s 0
check "after 3 failed loads: the fallback is said" logged "slot B ('cup-2' version 2) did not run healthy in 3 boots: falling back to slot A"
check "after 3 failed loads: A runs" logged "starting slot A ('spoon-1' version 1), good"
check "after 3 failed loads: B is bad" state "slot B: bad"

# ---- power cuts while a boot is being recorded ---------------------------------------
"$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/new.swpack" >/dev/null
cuts=0 killed=0
for k in 1 2 3 4 5 6 7 8 9 10; do
  (env LD_PRELOAD="$shim" ASAN_OPTIONS=verify_asan_link_order=0 SW_FAULT_KILL_AT=$k \
    "$walker" --store "$unit" --keys "$keys" --headless 160x120 --orbit --frames 2 --good-after-s 1e9 \
    --boot-attempts 20 \
    >/dev/null 2>&1) 2>/dev/null
  [ $? = 137 ] && killed=$((killed + 1))
  "$flash" boot-check --store "$unit" --config "$cfg" >"$work/boot" 2>&1 &&
    grep -q "verified" "$work/boot" &&
    cuts=$((cuts + 1))
done
# Two copies of the state, each written, fsynced, renamed, its directory fsynced.
check "the boot record's 8 calls (4 for each copy of the state) were each cut" [ "$killed" -eq 8 ]
check "after each cut while recording a boot, a slot still verifies" [ "$cuts" -eq 10 ]

# ---- mark-good by the runtime, then rollback -----------------------------------------
"$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/new.swpack" >/dev/null
exec 9>"$unit/lock"
flock 9          # an install is running: the boot must neither wait nor start a trial
boot --good-after-s 0
exec 9>&-
check "busy store: said" logged "the store is busy (an install is running)"
check "busy store: the good slot runs" logged "starting slot A ('spoon-1' version 1), good"
check "busy store: no attempt used" state "pending: B (0 boots so far)"
boot --good-after-s 0
check "new pack marked good by the runtime" state "active: B"
"$flash" rollback --store "$unit" --config "$cfg" >/dev/null
boot --good-after-s 0
check "after rollback the old pack runs" logged "starting slot A ('spoon-1' version 1), good"

# ---- untrusted keys: nothing starts, and it says why -----------------------------------
boot --keys "$fixture/stranger.pub"  # the later --keys wins
check "wrong keys: the message screen" rc 3
check "wrong keys: why" logged "not among the 1 trusted keys"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
