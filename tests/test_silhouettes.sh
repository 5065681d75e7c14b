#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Stand-ins' silhouettes against the reference walk's:
#   test_silhouettes.sh BUILD_DIR SOURCE_DIR
# A courtyard of 40 x 40 cells (tests/gen_soup.py: a paved patch soup with
# rows of columns, 3,800 patches) walked along walk_path.py's path, 120
# frames at 640x360, as the kiosk service walks it (tests/walk_pictures.py):
# columns seen one behind another, their silhouettes meeting, most of them
# drawn from static levels. Against the reference walk (--workers 0):
# - as built: no interior background pixel in any 10th frame (exit 0);
# - the stand-ins kept till the walk's meshes come for their bound
#   (--leaner-standins 0): none either;
# - that, with the mutant --test-standin-silhouettes 0 (a stand-in's level chosen by its
#   error alone where a silhouette crosses it, not by the bound it was made
#   for): slits of background between columns (exit 1, interior background
#   above 0).
# Needs nothing from ../shared/models.
set -uo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
tool=$build/assets/seamwalk-pack
work=$build/tests/silhouettes
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
python3 "$src/tests/gen_soup.py" "$work/court.igs" --cells 40 > "$work/gen.log" 2>&1 \
  || fail "gen_soup: $(tail -n 3 "$work/gen.log")"
"$tool" build "$work/court.igs" -o "$work/court.swpack" --quiet > "$work/build.log" 2>&1 \
  || fail "build: $(tail -n 3 "$work/build.log")"
"$tool" info --json "$work/court.swpack" > "$work/info.json" || fail "info"
python3 - "$work/info.json" "$work/court.path" "$src/tests/bench/walk_path.py" <<'PY' \
  || fail "walk_path"
import json, subprocess, sys
info = json.load(open(sys.argv[1]))
subprocess.run([sys.executable, sys.argv[3], sys.argv[2], "--box"] +
               ["%.6f" % v for v in info["box"]["min"] + info["box"]["max"]] +
               ["--up", info["up_axis"].lstrip("+-"), "--seconds", "40"], check=True)
PY
pictures() {
  python3 "$src/tests/walk_pictures.py" "$work/court.swpack" "$work/court.path" "$build" \
    "$work/$1" 640x360 120 --json "$work/$1.json" "${@:2}" > "$work/$1.log" 2>&1
}
pictures built
rc=$?
grep -E "interior background px max|differing max|undrawn" "$work/built.log"
[ $rc -eq 0 ] || fail "as built: exit $rc ($work/built.log)"
# The stand-ins themselves, kept until the walk's own meshes come for
# their bound (as built, ones far finer than their bound are soon replaced
# by leaner meshes, and the mutant's slits would not last to be seen).
pictures kept --leaner-standins 0
rc=$?
grep -E "interior background px max" "$work/kept.log" | sed 's/^/kept:/'
[ $rc -eq 0 ] || fail "stand-ins kept: exit $rc ($work/kept.log)"
pictures mutant --leaner-standins 0 --test-standin-silhouettes 0
rc=$?
grep -E "interior background px max" "$work/mutant.log" | sed 's/^/mutant:/'
[ $rc -eq 1 ] || fail "the mutant --test-standin-silhouettes 0: exit $rc, expected 1 (slits seen)"
echo "silhouettes: ok"
