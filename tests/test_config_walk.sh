#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# seamwalk --config end to end: a unit's config file names the pack, the
# size, the error bound and an orbit, and the command line overrides it.
#   test_config_walk.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$1 src=$2
work=$build/tests/config_walk
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
walker=$build/firmware/seamwalk

"$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$work/teaset.swpack" \
  > /dev/null || fail "build the teaset"
cat > "$work/unit.ini" <<INI
[display]
display = headless
size = 160x120
[pack]
pack = $work/teaset.swpack
[render]
max_error_px = 2
[navigation]
mode = orbit
INI

"$walker" --config "$work/unit.ini" --frames 3 --stats "$work/stats.json" > /dev/null \
  || fail "walk from the config"
python3 - "$work/stats.json" 160 120 2 <<'PY' || fail "stats of the config walk"
import json, sys
s = json.load(open(sys.argv[1]))
w, h, bound = int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
assert s["frames"] == 3, s["frames"]
assert s["viewport"] == [w, h], s["viewport"]
assert s["error_px"]["bound"] == bound, s["error_px"]["bound"]
print("ok   config walk: %r, bound %g" % (s["viewport"], bound))
PY

"$walker" --config "$work/unit.ini" --headless 96x64 --max-error-px 1 --frames 2 \
  --stats "$work/stats2.json" > /dev/null || fail "walk with overrides"
python3 - "$work/stats2.json" 96 64 1 <<'PY' || fail "the command line does not win"
import json, sys
s = json.load(open(sys.argv[1]))
w, h, bound = int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])
assert s["viewport"] == [w, h], s["viewport"]
assert s["error_px"]["bound"] == bound, s["error_px"]["bound"]
print("ok   command line over config: %r, bound %g" % (s["viewport"], bound))
PY

printf '[render]\nmemory_mb = 256\nmax_error = 1\n' > "$work/bad.ini"
"$walker" --config "$work/bad.ini" 2> "$work/stderr" > /dev/null
code=$?
[ "$code" -eq 2 ] || fail "a bad config exited $code, expected 2"
grep -q "bad.ini:3: \[render\] unknown key 'max_error'" "$work/stderr" \
  || fail "a bad config said '$(head -n 1 "$work/stderr")'"
echo "ok   $(head -n 1 "$work/stderr")"
