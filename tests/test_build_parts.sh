#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A scene built whole and in parts gives one pack, byte for byte:
#   test_build_parts.sh BUILD_DIR SOURCE_DIR
# The scene: the teaset's files (the teapot twice), a generated plate and
# rail, and a cup at a scale of its own in each axis (a prototype of its
# own). Checks:
#   - `build` with --threads 1 and --threads 4: the same bytes;
#   - `build-part` of every prototype, then `merge`: the same bytes as the
#     whole build, and the parts' import notes carried over;
#   - `ninja` writes a build.ninja that ninja builds (parts, then the
#     placing) into the same bytes, and a second ninja run has nothing to do;
#   - merge refuses too few parts, a part that is not one prototype's pack
#     and a pack of placed parts, each in one line.
set -uo pipefail
build=$1 src=$2
tool=$build/assets/seamwalk-pack
work=$build/tests/build_parts
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
cp "$src"/assets/samples/{teapot.txt,teacup.txt,teaspoon.txt} "$work/"
cat > "$work/room.ini" <<'INI'
[part pot]
file = teapot.txt
[part pot2]
file = teapot.txt
rotate = 0 1 0 90
translate = 3 0 0
[part spoon]
file = teaspoon.txt
scale = 0.6
translate = -2 0 0
[part cup]
file = teacup.txt
scale = 0.4 0.5 0.4
translate = 0 0 3
[part plate]
generate = plate
size = 2
height = 1
holes = 2
segments = 3
seed = 9
translate = 0 0 -3
[part rail]
generate = rail
size = 3
height = 1
holes = 1
segments = 5
seed = 4
translate = 4 0 3
INI
"$tool" build "$work/room.ini" -o "$work/one.swpack" --threads 1 --quiet || fail "build --threads 1"
"$tool" build "$work/room.ini" -o "$work/four.swpack" --threads 4 --quiet || fail "build --threads 4"
cmp -s "$work/one.swpack" "$work/four.swpack" || fail "1 and 4 threads give different packs"
echo "ok: 1 and 4 threads, the same $(stat -c %s "$work/one.swpack") bytes"

n=$("$tool" info --json "$work/one.swpack" | python3 -c 'import json,sys; print(json.load(sys.stdin)["prototype_count"])')
[ "$n" = 5 ] || fail "$n prototypes, expected 5 (teapot, spoon, cup, plate, rail)"
parts=()
for ((k = 0; k < n; k++)); do
  "$tool" build-part "$work/room.ini" --prototype $k -o "$work/p$k.swpack" --quiet \
    || fail "build-part $k"
  parts+=("$work/p$k.swpack")
done
"$tool" build-part "$work/room.ini" --prototype $n -o "$work/none.swpack" > "$work/out" 2>&1
[ $? -eq 1 ] && grep -q "prototype $n, the scene has $n" "$work/out" || fail "build-part past the end: $(cat "$work/out")"
"$tool" merge "$work/room.ini" "${parts[@]}" -o "$work/merged.swpack" --quiet || fail "merge"
cmp -s "$work/one.swpack" "$work/merged.swpack" || fail "merged parts differ from the whole build"
echo "ok: $n parts built apart and merged, the same bytes"

"$tool" merge "$work/room.ini" "${parts[@]:1}" -o "$work/bad.swpack" > "$work/out" 2>&1
[ $? -eq 1 ] && grep -q "names $n prototypes, $((n - 1)) packs given" "$work/out" \
  || fail "merge with a part missing: $(cat "$work/out")"
"$tool" merge "$work/room.ini" "${parts[@]:0:4}" "$work/one.swpack" -o "$work/bad.swpack" \
  > "$work/out" 2>&1
[ $? -eq 1 ] && grep -q "places parts of its own" "$work/out" \
  || fail "merge of a placed pack: $(cat "$work/out")"
echo "not a pack" > "$work/junk.swpack"
"$tool" merge "$work/room.ini" "${parts[@]:0:4}" "$work/junk.swpack" -o "$work/bad.swpack" \
  > "$work/out" 2>&1
[ $? -eq 1 ] && [ "$(wc -l < "$work/out")" -eq 1 ] && grep -q "prototype 5 of 5" "$work/out" \
  || fail "merge of a file that is no pack: $(cat "$work/out")"
[ ! -e "$work/bad.swpack" ] || fail "a failed merge left its output"
echo "ok: merge refuses a missing part, a placed pack and a file that is no pack"

command -v ninja > /dev/null || fail "ninja is not installed (ninja-build)"
mkdir -p "$work/farm"
"$tool" ninja "$work/room.ini" -o "$work/farm/build.ninja" --pack room.swpack > /dev/null \
  || fail "seamwalk-pack ninja"
ninja -C "$work/farm" > "$work/farm.log" 2>&1 || fail "ninja: $(tail -5 "$work/farm.log")"
cmp -s "$work/one.swpack" "$work/farm/room.swpack" || fail "ninja's pack differs from the whole build"
ninja -C "$work/farm" -n | grep -q "no work to do" || fail "ninja would build again"
echo "ok: ninja built $n parts and placed them, the same bytes; nothing left to do after"
