#!/usr/bin/env bash
# Specification of the seamwalk-pack command line: build, info, verify, and
# how it fails (exit 1 with one stderr line, exit 2 for usage, no partial or
# damaged output file).
#   test_pack_cli.sh SEAMWALK_PACK SAMPLES_DIR [SHARED_MODELS_DIR]
set -uo pipefail
tool=$1 samples=$2 shared=${3:-}
work=$(mktemp -d "${TMPDIR:-/tmp}/swpack_cli.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
failures=0 checks=0

check() { # check DESCRIPTION CONDITION...
  local what=$1; shift
  checks=$((checks + 1))
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; failures=$((failures + 1)); fi
}

# run ARGS...: runs the tool, keeping stdout, stderr and the exit code in $work.
run() {
  "$tool" "$@" > "$work/out" 2> "$work/err"
  echo $? > "$work/code"
}
code() { cat "$work/code"; }
lines() { wc -l < "$1"; }
has() { grep -q -- "$2" "$1"; }

# one_line_failure FRAGMENT: exit 1, nothing on stdout, one stderr line with FRAGMENT.
one_line_failure() {
  [ "$(code)" -eq 1 ] && [ "$(lines "$work/err")" -eq 1 ] && [ ! -s "$work/out" ] &&
    has "$work/err" "^seamwalk-pack: .*$1" || { echo "  got exit $(code): $(cat "$work/err")"; false; }
}

# -- usage ------------------------------------------------------------------
run --help
check "--help prints usage and exits 0" eval '[ "$(code)" -eq 0 ] && has "$work/out" "usage: seamwalk-pack build"'
run
check "no command exits 2 with usage" eval '[ "$(code)" -eq 2 ] && has "$work/err" "usage:"'
run frobnicate x
check "unknown command exits 2" eval '[ "$(code)" -eq 2 ] && has "$work/err" "unknown command .frobnicate."'
run build "$samples/teapot.txt"
check "build without -o exits 2" eval '[ "$(code)" -eq 2 ] && has "$work/err" "missing -o"'
run build -o "$work/x.swpack"
check "build without inputs exits 2" eval '[ "$(code)" -eq 2 ] && has "$work/err" "no INPUT"'
run info --yaml x.swpack
check "info with an unknown option exits 2" eval '[ "$(code)" -eq 2 ] && has "$work/err" "--yaml"'
run verify a.swpack b.swpack
check "verify with two packs exits 2" [ "$(code)" -eq 2 ]

# -- the teaset scene -------------------------------------------------------
teaset=$work/teaset.swpack
run build "$samples/teaset.ini" -o "$teaset"
check "build teaset.ini" eval '[ "$(code)" -eq 0 ] && has "$work/out" "3 parts, 70 patches, [0-9]* bytes -> $teaset"'
run build "$samples/teaset.ini" -o "$work/quiet.swpack" --quiet
check "build --quiet prints nothing" eval '[ "$(code)" -eq 0 ] && [ ! -s "$work/out" ] && cmp -s "$teaset" "$work/quiet.swpack"'
run info "$teaset"
check "info lists parts and counts" eval '[ "$(code)" -eq 0 ] && has "$work/out" "teaspoon *16 patches" && has "$work/out" "bezier patches *70" && has "$work/out" "control points *1120" && has "$work/out" "runtime memory"'
run info --json "$teaset"
cp "$work/out" "$work/teaset.json"
check "info --json is valid JSON" eval '[ "$(code)" -eq 0 ] && python3 -m json.tool "$work/teaset.json" > /dev/null'
check "info --json has the counts" python3 - "$work/teaset.json" <<'EOF'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["part_count"] == 3 and [p["name"] for p in j["parts"]] == ["teapot", "teacup", "teaspoon"], j["parts"]
assert j["bezier_patches"] == 70 and j["surfaces"] == 70 and j["control_points"] == 1120
assert j["rational_patches"] == 0 and j["degree_u"] == [3, 3] and j["degree_v"] == [3, 3]
assert [s["name"] for s in j["sections"]][:4] == ["META", "PARTS", "PATCHES", "CONTROL"]
assert abs(j["parts"][0]["color"][2] - 0.62) < 1e-6 and j["runtime_bytes"] > j["total_bytes"]
assert j["box"]["min"][1] > -1e-6 and j["model_size"] > 1
EOF
run verify "$teaset"
check "verify accepts the teaset" eval '[ "$(code)" -eq 0 ] && has "$work/out" "^$teaset: ok (70 patches, [0-9]* bytes)$"'

# -- single files become parts named after them ------------------------------
run build "$samples/saddle.bpt" "$samples/teacup.txt" -o "$work/two.swpack"
check "build .bpt + .txt" eval '[ "$(code)" -eq 0 ] && has "$work/out" "2 parts, 28 patches"'
run info --json "$work/two.swpack"
check "parts are named after the files" python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert [p["name"] for p in j["parts"]] == ["saddle", "teacup"]
assert j["degree_u"] == [2, 3]' "$work/out"

# -- the shared teapot ---------------------------------------------------------
if [ -n "$shared" ] && [ -f "$shared/newell_teapot.txt" ]; then
  run build "$shared/newell_teapot.txt" -o "$work/teapot.swpack"
  check "build the shared teapot" eval '[ "$(code)" -eq 0 ] && has "$work/out" "1 parts, 28 patches"'
  run info --json "$work/teapot.swpack"
  check "shared teapot info --json" eval 'python3 -m json.tool "$work/out" > /dev/null && has "$work/out" "\"bezier_patches\": 28"'
  run verify "$work/teapot.swpack"
  check "verify the shared teapot" [ "$(code)" -eq 0 ]
else
  echo "skip shared teapot: ${shared:-(no folder given)}/newell_teapot.txt absent"
fi

# -- damaged packs -------------------------------------------------------------
size=$(stat -c %s "$teaset")
head -c $((size / 2)) "$teaset" > "$work/short.swpack"
run verify "$work/short.swpack"
check "verify rejects a truncated pack in one line" one_line_failure "short.swpack"
head -c 40 "$teaset" > "$work/tiny.swpack"
run info "$work/tiny.swpack"
check "info rejects a 40-byte pack in one line" one_line_failure "tiny.swpack"
for offset in 20 100 $((size / 2)) $((size - 7)); do
  cp "$teaset" "$work/flip.swpack"
  byte=$(od -An -tu1 -j "$offset" -N1 "$work/flip.swpack" | tr -d ' ')
  printf "\\$(printf %03o $((byte ^ 0x5a)))" |
    dd of="$work/flip.swpack" bs=1 seek="$offset" conv=notrunc status=none
  run verify "$work/flip.swpack"
  check "verify rejects a byte flipped at $offset" one_line_failure "flip.swpack"
done
run verify "$work/missing.swpack"
check "verify of a missing file" one_line_failure "missing.swpack"

# -- failed builds leave no file and keep an existing one ------------------------
printf '1\n1 1\n0 0 0\n1 0 0\n0 one 0\n1 1 1\n' > "$work/bad.bpt"
run build "$work/bad.bpt" -o "$work/new.swpack"
check "a bad input fails the build naming file:line" one_line_failure "bad.bpt:5:3: expected control point y"
check "a failed build leaves no output file, not even a temporary" eval '[ -z "$(ls "$work" | grep new.swpack)" ]'
cp "$teaset" "$work/keep.swpack"
run build "$samples/teaset.ini" "$work/bad.bpt" -o "$work/keep.swpack"
check "a failed build keeps the existing output" eval '[ "$(code)" -eq 1 ] && cmp -s "$teaset" "$work/keep.swpack"'
run build "$work/nope.txt" -o "$work/new.swpack"
check "a missing input fails in one line" one_line_failure "nope.txt: cannot open"
run build "$samples/teapot.igs" -o "$work/new.swpack"
check "an unsupported input fails in one line" one_line_failure "unsupported file type"
run build "$samples/teaset.ini" -o "$work/no/such/dir/x.swpack"
check "an unwritable output fails in one line" one_line_failure "x.swpack"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
