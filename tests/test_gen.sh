#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Specification of the showroom generator (sw_gen_showroom.h): the scene it
# writes builds with seamwalk-pack into a pack of N Bezier patches (within 5%;
# the plan is exact), with its viewpoints; the seed decides the scene; bad
# arguments and part files fail cleanly and write nothing.
#   test_gen.sh SEAMWALK_PACK procedural [SEAMWALK SOURCE_DIR]
#                                              generated objects only; with
#                                              the walker, the 40000-patch
#                                              showroom (10000 under the
#                                              sanitizers) is walked close to
#                                              far through its Seam Graph
#   test_gen.sh SEAMWALK_PACK parts MODELS_DIR with copies of real parts
# The parts mode exits 77 (skipped) when MODELS_DIR is absent.
set -uo pipefail
pack=$1 mode=$2 models=${3:-} walker=${3:-} src=${4:-}
# Under ASan: OpenCASCADE's own allocations are not ours to chase (the
# STEP part's build would otherwise fail on them, as test_pack_cli says).
export LSAN_OPTIONS="suppressions=$(cd "$(dirname "$0")" && pwd)/occt-lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
work=$(mktemp -d "${TMPDIR:-/tmp}/sw_test_gen.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
failures=0 checks=0

check() { # check DESCRIPTION COMMAND...
  local what=$1; shift
  checks=$((checks + 1))
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; failures=$((failures + 1)); fi
}

# patches_of PACK: the Bezier patch count seamwalk-pack info reports.
patches_of() {
  "$pack" info --json "$1" | sed -n 's/^ *"bezier_patches": \([0-9]*\),*$/\1/p'
}

# within_5_percent GOT WANT
within_5_percent() {
  [ -n "$1" ] && [ $(( ($1 - $2) * ($1 - $2) * 400 )) -le $(( $2 * $2 )) ] ||
    { echo "  $1 patches for $2 asked"; false; }
}

# gen_and_build N NAME [GEN ARGS...]: generates NAME.ini, builds NAME.swpack.
gen_and_build() {
  local n=$1 name=$2; shift 2
  "$pack" gen showroom --patches "$n" -o "$work/$name.ini" "$@" > "$work/$name.gen" 2>&1 &&
    "$pack" build "$work/$name.ini" -o "$work/$name.swpack" > "$work/$name.build" 2>&1 ||
    { cat "$work/$name.gen" "$work/$name.build" 2>/dev/null; false; }
}

builds_to() { # builds_to N NAME [GEN ARGS...]
  local n=$1 name=$2
  gen_and_build "$@" && within_5_percent "$(patches_of "$work/$name.swpack")" "$n"
}

has_views() { # the three viewpoints, in the scene and in the pack
  for v in entrance overview closeup; do grep -q "^\[view $v\]$" "$work/$1.ini" || return 1; done
  "$pack" info --json "$work/$1.swpack" > "$work/$1.info" &&
    grep -q '"name": "VIEWPOINTS", .*"size": [1-9]' "$work/$1.info"
}

fails_with() { # fails_with CODE FRAGMENT GEN ARGS...: exit CODE, FRAGMENT on stderr, no output
  local want=$1 fragment=$2; shift 2
  rm -f "$work/bad.ini"
  "$pack" gen "$@" > "$work/out" 2> "$work/err"
  local got=$?
  [ "$got" -eq "$want" ] && grep -q -- "$fragment" "$work/err" && [ ! -e "$work/bad.ini" ] ||
    { echo "  exit $got: $(head -c 300 "$work/err")"; false; }
}

procedural() {
  check "2000 patches asked, 2000 built" builds_to 2000 small
  check "the scene has entrance, overview and closeup views" has_views small
  check "the same seed writes the same scene" \
    bash -c "'$pack' gen showroom --patches 2000 -o '$work/again.ini' > /dev/null &&
             cmp -s '$work/small.ini' '$work/again.ini'"
  check "another seed writes another scene" \
    bash -c "'$pack' gen showroom --patches 2000 --seed 2 -o '$work/other.ini' > /dev/null &&
             ! cmp -s '$work/small.ini' '$work/other.ini'"
  check "a catalog of 3 designs: 2000 patches built, at most 3 designs a kind" \
    bash -c "'$pack' gen showroom --patches 2000 --catalog 3 -o '$work/catalog.ini' > /dev/null &&
             python3 - '$work/catalog.ini' <<'PY'
import configparser, sys
c = configparser.ConfigParser(inline_comment_prefixes=(';',))
c.read(sys.argv[1])
kinds = {}
for s in c.sections():
    p = c[s]
    if 'generate' in p:   # the plates that fill the count up differ in segments only
        kinds.setdefault(p['generate'], set()).add((p.get('size'), p.get('height'),
                                                    p.get('holes'), p.get('seed')))
assert kinds and all(len(v) <= 3 for v in kinds.values()), {k: len(v) for k, v in kinds.items()}
PY"
  check "a catalog's pack stores each design once, as many prototypes as designs" \
    bash -c "'$pack' build '$work/catalog.ini' -o '$work/catalog.swpack' > /dev/null &&
             '$pack' info --json '$work/catalog.swpack' > '$work/catalog.json' &&
             python3 - '$work/catalog.ini' '$work/catalog.json' <<'PY'
import configparser, json, sys
c = configparser.ConfigParser(inline_comment_prefixes=(';',))
c.read(sys.argv[1])
designs = {tuple(c[s].get(k) for k in ('generate', 'size', 'height', 'holes', 'segments', 'seed'))
           for s in c.sections() if 'generate' in c[s]}
j = json.load(open(sys.argv[2]))
placed = sum(1 for s in c.sections() if s.startswith('part '))
assert j['prototype_count'] == len(designs) and j['instance_count'] == placed, \
    (j['prototype_count'], len(designs), j['instance_count'], placed)
assert j['placed']['patches'] == 2000, j['placed']
PY"
  check "--catalog past 1000 is a usage error" fails_with 2 "--catalog" showroom --patches 5 \
    --catalog 1001 -o "$work/bad.ini"
  check "a tiny showroom (7 patches) builds exactly" builds_to 7 tiny
  # SW_GEN_DIVISOR (the sanitizer builds: 4) divides the large showroom:
  # the same generator, build and walk, a quarter of the patches.
  local large=$((40000 / ${SW_GEN_DIVISOR:-1}))
  check "$large patches asked, within 5% built" builds_to "$large" large --seed 40
  if [ -n "$walker" ]; then
    "$pack" info --json "$work/large.swpack" > "$work/large.json"
    check "the $large-patch showroom close to far through its Seam Graph" \
      bash "$src/tests/walk_near_far.sh" "$walker" "$work/large.swpack" "$work/large.json" "$work" \
        "$src" --memory-mb 1024
  fi
  check "missing --patches is a usage error" fails_with 2 "missing --patches" showroom -o "$work/bad.ini"
  check "--patches 0 is a usage error" fails_with 2 "--patches" showroom --patches 0 -o "$work/bad.ini"
  check "--patches 12x is a usage error" fails_with 2 "12x" showroom --patches 12x -o "$work/bad.ini"
  check "only showrooms are generated" fails_with 2 "expected 'showroom'" garden --patches 5 -o "$work/bad.ini"
  check "an unknown option is a usage error" fails_with 2 "'--fast'" showroom --fast --patches 5 -o "$work/bad.ini"
  check "a missing part file fails naming it" \
    fails_with 1 "no_such_part.bpt" showroom --patches 50 --part "$work/no_such_part.bpt" -o "$work/bad.ini"
  printf '1\n1 1\n0 0 0\n1 0 0\n0 one 0\n1 1 1\n' > "$work/broken.bpt"
  check "a broken part file fails naming file and line" \
    fails_with 1 "broken.bpt:5:" showroom --patches 50 --part "$work/broken.bpt" -o "$work/bad.ini"
}

parts() {
  [ -d "$models" ] || { echo "skip: no models folder '$models'"; exit 77; }
  # SW_GEN_DIVISOR (the sanitizer builds: 4) divides the showrooms' sizes:
  # the same copies and checks, a quarter of the patches to build.
  local d=${SW_GEN_DIVISOR:-1}
  local teapot=$models/newell_teapot.txt
  # The folder is there: a model missing from it is a failure, not a skip.
  check "the models folder has the teapot, the bearing and the screw" \
    test -f "$teapot" -a -f "$models/occt_bearing.iges" -a -f "$models/occt_screw.step"
  [ -f "$teapot" ] || { echo "$checks checks, $failures failed"; exit 1; }
  check "copies of the Newell teapot and objects: $((2000 / d)) patches" \
    builds_to $((2000 / d)) teapots --part "$teapot" --seed 3
  check "the teapot is copied" grep -q "^file = .*newell_teapot.txt$" "$work/teapots.ini"
  local iges=$models/occt_bearing.iges
  check "copies of an IGES part (trimmed) and the teapot: $((3000 / d)) patches" \
    builds_to $((3000 / d)) bearings --part "$teapot" --part "$iges" --seed 5
  local step=$models/occt_screw.step
  "$pack" build "$step" -o "$work/screw.swpack" > "$work/screw.out" 2>&1
  if grep -q "built without STEP support" "$work/screw.out"; then
    echo "skip STEP parts: this seamwalk-pack is built without STEP support"
  else
    check "copies of a STEP part, an IGES part and the teapot: $((4000 / d)) patches" \
      builds_to $((4000 / d)) mixed --part "$teapot" --part "$iges" --part "$step" --seed 4
    check "a STEP part is named scene part/product, and no part is empty" \
      python3 - "$work/mixed.swpack" "$pack" <<'PY'
import json, subprocess, sys
j = json.loads(subprocess.run([sys.argv[2], "info", "--json", sys.argv[1]], capture_output=True,
                              text=True, check=True).stdout)
names = [p["name"] for p in j["parts"]]
empty = [p["name"] for p in j["parts"] if p["patches"] == 0]
screws = [n for n in names if n.startswith("occt_screw")]
assert not empty, "empty parts: %s" % empty[:5]
assert screws and all("/" in n for n in screws), screws[:5]
PY
    # The screw is z-up (42 mm along z, 30 x 35 across): stood up, each copy
    # is taller (about 1465 mm) than its 1.2 m footprint; lying, it would be
    # about 980 mm high.
    check "STEP copies stand upright on the floor" \
      python3 - "$work/mixed.swpack" "$pack" <<'PY'
import json, subprocess, sys
j = json.loads(subprocess.run([sys.argv[2], "info", "--json", sys.argv[1]], capture_output=True,
                              text=True, check=True).stdout)
for p in j["parts"]:
    if p["name"].startswith("occt_screw"):
        lo, hi = p["box"]["min"], p["box"]["max"]
        high, wide = hi[1] - lo[1], max(hi[0] - lo[0], hi[2] - lo[2])
        assert abs(lo[1]) < 1e-3 and high > 1.1 * wide, (p["name"], lo, hi)
PY
  fi
}

case $mode in
  procedural) procedural ;;
  parts) parts ;;
  *) echo "usage: test_gen.sh SEAMWALK_PACK procedural|parts [MODELS_DIR]"; exit 2 ;;
esac
echo "$checks checks, $failures failed"
[ "$checks" -gt 0 ] && [ "$failures" -eq 0 ]
