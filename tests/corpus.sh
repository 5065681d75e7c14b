#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Does seamwalk take these CAD files? For every IGES, STEP, Newell listing
# and .bpt file under the folders given:
#   tests/corpus.sh [--build DIR] [--require-sewing] [--allow-free FILE:MM]...
#                   [--timeout S] [--max-mb MB] [--json FILE] DIR...
# builds its pack (wall time and peak memory of seamwalk-pack), verifies it,
# walks it through the Seam Graph from close to far (tests/walk_near_far.sh:
# cracks, refused surfaces and the error bound checked every frame), and,
# for IGES and STEP, sews the same faces with OpenCASCADE at the pack's
# tolerance (occt_measure --sew) to set seamwalk's free border beside it.
# One table row per file; --json also writes one JSON object per line; the
# last line counts the files, those ok, those failed by the step that
# failed (build, info, verify, walk, faces, sewing) and the faces skipped.
# A file fails when any step fails (a step past --timeout seconds, 600 by
# default, is killed; --max-mb caps each step's memory), a surface is
# refused or a crack shows, or its pack has fewer surfaces than
# OpenCASCADE transfers faces beyond those the build named as skipped;
# with --require-sewing also when its free border is over 1.05 times
# OpenCASCADE's (plus 1e-6 of the border, for rounding), except that a file
# named by --allow-free may have up to MM of free border (a known shortfall,
# held from getting worse). Exit 1 when any file failed, 2 for usage.
set -uo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$src/build require_sewing=0 json="" allow="" timeout=600 max_mb=0
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --require-sewing) require_sewing=1; shift ;;
    --allow-free) allow="$allow $2"; shift 2 ;;
    --json) json=$2; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    --max-mb) max_mb=$2; shift 2 ;;
    -h|--help) sed -n '2,23p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "corpus.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -gt 0 ] || { echo "usage: corpus.sh [--build DIR] [--require-sewing] [--allow-free FILE:MM]... [--timeout S] [--max-mb MB] [--json FILE] DIR..." >&2; exit 2; }
case $timeout$max_mb in *[!0-9]*) echo "corpus.sh: --timeout and --max-mb take whole numbers" >&2; exit 2 ;; esac
tool=$build/assets/seamwalk-pack walker=$build/firmware/seamwalk measure=$build/tests/occt_measure
for t in "$tool" "$walker"; do
  [ -x "$t" ] || { echo "corpus.sh: $t is not built (cmake --build $build)" >&2; exit 2; }
done
export LSAN_OPTIONS="suppressions=$src/tests/occt-lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
# The walk's checks measure what is drawn: each frame waits for the work it
# asks for, as under CTest (tests/CMakeLists.txt). Without it a loaded
# machine drew six frames of stand-ins and measured no error at all.
export SEAMWALK_TEST_SYNC_WORK=1
work=$(mktemp -d "${TMPDIR:-/tmp}/swcorpus.XXXXXX") || exit 2
trap 'rm -rf "$work"' EXIT
[ -n "$json" ] && : > "$json"

# limited CMD...: CMD with its memory capped by --max-mb; bounded CMD...: and
# killed past --timeout seconds.
limited() { ( [ "$max_mb" -gt 0 ] && ulimit -v $((max_mb * 1024)); exec "$@" ); }
bounded() { limited timeout -s KILL "$timeout" "$@"; }

# A .txt is taken only when it reads as a Newell listing (line 2: four counts).
is_newell() { sed -n 2p "$1" | tr -d '\r' | grep -Eq '^[[:space:]]*([0-9]+[[:space:]]+){3}[0-9]+[[:space:]]*$'; }

files=()
while IFS= read -r -d '' f; do
  case ${f,,} in
    *.igs|*.iges|*.stp|*.step|*.p21|*.bpt) files+=("$f") ;;
    *.txt) is_newell "$f" && files+=("$f") ;;
  esac
done < <(find -L "$@" -type f -print0 | sort -z)
[ ${#files[@]} -gt 0 ] || { echo "corpus.sh: no CAD files under $*" >&2; exit 2; }

printf '%-28s %-6s %7s %7s %8s %10s %10s %8s %6s %6s  %s\n' file result build_s peak_MB \
  surfaces free_frac occt_frac error_px cracks failed note
failed=0
for f in "${files[@]}"; do
  name=$(basename "$f") w=$work/$name
  mkdir -p "$w"
  note="" result=ok reason=""
  start=$(date +%s%N)
  if ! limited /usr/bin/time -f '%M' -o "$w/peak" timeout -s KILL "$timeout" \
      "$tool" build "$f" -o "$w/pack.swpack" --quiet 2> "$w/build.err"; then
    why=$(grep -v '^[0-9]*$' "$w/build.err" | grep -v '^warning' | grep -v '^Command ' | tail -n 1)
    result=fail reason=build note="build: ${why:-killed (past ${timeout} s or ${max_mb} MB)}"
  fi
  secs=$(( ($(date +%s%N) - start) / 1000000 ))
  peak=$(tail -n 1 "$w/peak" 2>/dev/null)
  if [ $result = ok ]; then
    "$tool" info --json "$w/pack.swpack" > "$w/info.json" || { result=fail reason=info note="info"; }
  fi
  if [ $result = ok ] && ! bounded "$tool" verify "$w/pack.swpack" > "$w/verify.out" 2>&1; then
    result=fail reason=verify note="verify: $(tail -n 1 "$w/verify.out")"
  fi
  if [ $result = ok ] && ! bounded bash "$src/tests/walk_near_far.sh" "$walker" "$w/pack.swpack" \
      "$w/info.json" "$w" "$src" > "$w/walk.out" 2>&1; then
    result=fail reason=walk note="walk: $(grep -m1 FAIL "$w/walk.out")"
  fi
  occt=""
  case ${name,,} in
    *.igs|*.iges|*.stp|*.step|*.p21)
      if [ -s "$w/info.json" ]; then
        tol=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seam"]["tolerance"])' "$w/info.json")
        if bounded "$measure" --sew "$tol" "$f" > "$w/occt.json" 2> "$w/occt.err"; then occt=$w/occt.json
        else note="${note:+$note; }OCCT sewing: $(tail -n 1 "$w/occt.err" "$w/occt.json" | tail -n 1)"; fi
      fi ;;
  esac
  row=$(python3 "$src/tests/corpus_row.py" row "$name" "$result" "$reason" "$secs" "${peak:-0}" \
        "$w/info.json" "$w/near_far.json" "${occt:-}" "$require_sewing" "$note" "$allow")
  [ -n "$json" ] && echo "$row" | sed -n 1p >> "$json"
  echo "$row" | sed -n 1p >> "$work/rows.jsonl"
  echo "$row" | sed -n 2p
  echo "$row" | sed -n 1p | grep -q '"result": "ok"' || failed=$((failed + 1))
done
python3 "$src/tests/corpus_row.py" summary "$work/rows.jsonl"
[ $failed -eq 0 ]
