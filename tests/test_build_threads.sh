#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# seamwalk-pack build makes the same pack, byte for byte, whatever
# --threads says: a generated showroom of many parts, and a courtyard of
# one part cut into pieces, each built with --threads 1 and --threads 4 and
# compared with cmp; the summary names the threads it used; --threads takes
# a count and nothing else. With TEST_PROGRAM (test_build_threads.c), a
# smaller showroom and the courtyard are built once and the program makes
# their levels in order and on threads and compares them. With --step FILE,
# that file (a STEP or IGES file OpenCASCADE reads: its faces are converted
# on the threads too) is built with 1 and 4 threads and compared; exit 77
# when it is absent.
#   test_build_threads.sh SEAMWALK_PACK SOURCE_DIR [TEST_PROGRAM | --step FILE]
set -uo pipefail
pack=$1 src=$2 program=${3:-}
work=$(mktemp -d "${TMPDIR:-/tmp}/sw_build_threads.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
. "$src/tests/sh_checks.sh"

# built INPUT NAME THREADS [ARGS...]: NAME-THREADS.swpack, its summary
# naming THREADS threads.
built() {
  local input=$1 name=$2 threads=$3; shift 3
  local out=$work/$name-$threads
  "$pack" build "$input" -o "$out.swpack" --threads "$threads" "$@" > "$out.log" 2>&1 &&
    grep -q ", $threads threads\?)$" "$out.log" || { tail -5 "$out.log"; false; }
}

same_bytes() { # same_bytes NAME: NAME-1.swpack and NAME-4.swpack
  cmp "$work/$1-1.swpack" "$work/$1-4.swpack"
}

usage_error() { # usage_error VALUE: --threads VALUE exits 2 naming it
  "$pack" build "$work/court.igs" -o "$work/bad.swpack" --threads "$1" > /dev/null 2> "$work/err"
  local got=$?
  [ "$got" -eq 2 ] && grep -q -- "--threads takes a thread count, not '$1'" "$work/err" &&
    [ ! -e "$work/bad.swpack" ] || { echo "  exit $got: $(head -c 300 "$work/err")"; false; }
}

if [ "$program" = --step ]; then
  model=${4:?--step takes a file}
  [ -f "$model" ] || { echo "skipped: $model is absent"; exit 77; }
  check "$(basename "$model") builds on 1 thread" built "$model" model 1
  check "$(basename "$model") builds on 4 threads" built "$model" model 4
  check "its packs are the same bytes" same_bytes model
  checks_done
  exit
fi
patches=2000
[ -z "$program" ] || patches=600   # made twice in the program, instrumented under TSan
"$pack" gen showroom --patches $patches -o "$work/showroom.ini" > /dev/null &&
  python3 "$src/tests/gen_soup.py" "$work/court.igs" --cells 24 > /dev/null ||
  { echo "FAIL the inputs could not be made"; exit 1; }
if [ -n "$program" ]; then
  check "the showroom builds" built "$work/showroom.ini" showroom 1
  check "the cut courtyard builds" built "$work/court.igs" court 1 --cut-patches 512
  check "the showroom's levels in order and on threads" "$program" "$work/showroom-1.swpack"
  check "the courtyard's levels in order and on threads" \
    "$program" --cut-patches 512 "$work/court-1.swpack"
  checks_done
  exit
fi
check "the showroom builds on 1 thread" built "$work/showroom.ini" showroom 1
check "the showroom builds on 4 threads" built "$work/showroom.ini" showroom 4
check "the showroom's packs are the same bytes" same_bytes showroom
check "the cut courtyard builds on 1 thread" built "$work/court.igs" court 1 --cut-patches 512
check "the cut courtyard builds on 4 threads" built "$work/court.igs" court 4 --cut-patches 512
check "the courtyard's packs are the same bytes" same_bytes court
check "--threads x is a usage error" usage_error x
check "--threads -2 is a usage error" usage_error -2
checks_done
