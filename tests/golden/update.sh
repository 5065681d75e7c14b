#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the golden pictures from the current build after an intended
# change of the picture (look at them before committing!):
#   bash tests/golden/update.sh [BUILD_DIR]
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$top/build}
work=$(mktemp -d)
"$build/assets/seamwalk-pack" build "$top/assets/samples/teaset.ini" -o "$work/teaset.swpack"
"$build/firmware/seamwalk" --pack "$work/teaset.swpack" --headless 320x240 \
  --path "$top/tests/golden/views.path" --frames 3 --png-dir "$work/png"
for i in 0 1 2; do cp "$work/png/frame_0000$i.png" "$top/tests/golden/teaset_view$i.png"; done
rm -rf "$work"
echo "golden pictures updated in tests/golden/"
