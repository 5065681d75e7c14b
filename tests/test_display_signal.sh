#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SIGTERM (a service stop) and SIGINT (Ctrl-C) end a walk after the frame in
# progress, through the display's close request (sw_display_close_on_signal):
# seamwalk exits 0, writes its stats for the frames it drew and prints its
# summary, as it must on KMS to give the screen back. Headless here; the
# same on KMS in tests/qemu/kms_in_qemu.sh.
#   test_display_signal.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$(cd "$1" && pwd) src=$2
work=$build/tests/display_signal
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" \
  > /dev/null || fail "build the teaset"
for sig in TERM INT; do
  "$build/firmware/seamwalk" --pack "$work/teaset.swpack" --orbit --headless 64x48 \
    --frames 100000 --stats "$work/$sig.json" > "$work/$sig.out" 2>&1 &
  walker=$!
  # Until the walk is drawing: the stats file does not exist before the end,
  # so wait a fixed while, long enough for start-up on a slow machine.
  sleep 3
  kill -$sig $walker
  wait $walker
  rc=$?
  [ $rc -eq 0 ] || fail "SIG$sig: exit $rc: $(cat "$work/$sig.out")"
  grep -q "^seamwalk: display headless 64x48" "$work/$sig.out" || fail "SIG$sig: no summary"
  python3 - "$work/$sig.json" <<'PY' || fail "SIG$sig: stats"
import json, sys
s = json.load(open(sys.argv[1]))
assert 0 < s["frames"] < 100000, s["frames"]
assert s["mallocs_after_init"] == 0, s["mallocs_after_init"]
PY
done
echo "ok: SIGTERM and SIGINT end the walk cleanly"
