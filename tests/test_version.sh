#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# One version everywhere: each program's --version prints its name and the
# project's version (CMake's project(VERSION), the one source), on stdout
# with exit 0, and a walk's stats carry the same.
#   test_version.sh VERSION SEAMWALK SEAMWALK_PACK SEAMWALK_FLASH SAMPLES WORK
set -uo pipefail
version=$1 walker=$2 pack=$3 flash=$4 samples=$5 work=$6
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
for p in "$walker" "$pack" "$flash"; do
  name=$(basename "$p")
  out=$("$p" --version 2>"$work/err")
  rc=$?
  [ $rc -eq 0 ] || fail "$name --version: exit $rc"
  [ "$out" = "$name $version" ] || fail "$name --version: '$out', expected '$name $version'"
  [ ! -s "$work/err" ] || fail "$name --version wrote to stderr: $(cat "$work/err")"
  echo "ok   $out"
done
"$pack" build "$samples/teaspoon.txt" -o "$work/spoon.swpack" --quiet || fail "build"
"$walker" --pack "$work/spoon.swpack" --headless 64x48 --orbit --frames 1 \
  --stats "$work/stats.json" > /dev/null 2>&1 || fail "walk"
stats=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['version'])" \
  "$work/stats.json") || fail "stats: no version"
[ "$stats" = "$version" ] || fail "stats version '$stats', expected '$version'"
echo "ok   stats version $stats"
