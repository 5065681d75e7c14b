#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# seamwalk's own heap calls after start-up (mallocs_after_init, counted
# through --wrap) beside the whole process's (process_mallocs_after_init,
# counted by the preloaded tests/process_alloc_shim.so): the first must be 0
# the second is measured and printed per frame.
#   test_process_allocs.sh SEAMWALK_PACK SEAMWALK SHIM.so SAMPLES_DIR
set -uo pipefail
pack=$1 walker=$2 shim=$3 samples=$4
work=$(mktemp -d "${TMPDIR:-/tmp}/swallocs.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
"$pack" build "$samples/teaset.ini" -o "$work/teaset.swpack" --quiet || { echo "FAIL build"; exit 1; }
failed=0
for walk in ""; do
  LD_PRELOAD="$shim" "$walker" --pack "$work/teaset.swpack" --headless 320x240 --orbit --frames 16 \
    $walk --stats "$work/stats.json" > /dev/null || { echo "FAIL walk $walk"; exit 1; }
  python3 - "$work/stats.json" "${walk:-seams}" <<'PY' || failed=1
import json, sys
s, walk = json.load(open(sys.argv[1])), sys.argv[2]
own, process, frames = s["mallocs_after_init"], s["process_mallocs_after_init"], s["frames"]
print("%s: seamwalk's own heap calls after start-up %d; the whole process's %d (%.1f a frame: "
      "Mesa's llvmpipe and libc)" % (walk, own, process, process / frames))
assert own == 0, "seamwalk's own code allocated after start-up"
assert process >= 0, "the shim was not seen: process_mallocs_after_init is %d" % process
PY
done
[ $failed -eq 0 ] && echo "ok   heap calls counted both ways"
exit $failed
