#!/bin/sh
# SPDX-License-Identifier: MIT
# seamwalk-pack info on a pack with a Seam Graph: the text report has the
# seam lines and --json parses with the seam counts in it.
# Usage: test_pack_seam_info.sh SEAMWALK_PACK PACK
set -e
tool=$1 pack=$2
"$tool" info "$pack" | grep -q '^  seam graph  *14 vertices (10 original, 4 created)'
"$tool" info "$pack" | grep -q '^  seam memory  *916 bytes: 83.3 per boundary edge'
"$tool" info --json "$pack" | python3 -c '
import json, sys
seam = json.load(sys.stdin)["seam"]
sys.exit(0 if seam["edges"] == 11 and seam["bytes"] == 916 else 1)'
