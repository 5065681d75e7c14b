#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The command-line conventions of seamwalk, seamwalk-pack and seamwalk-flash:
# --help prints the usage on stdout, nothing on stderr, exit 0; a usage error
# (unknown option or command, bad value, missing argument) prints nothing on
# stdout and two lines on stderr, what was wrong and a hint naming --help,
# with exit 2. seamwalk's test-only options are in --help-test, not --help.
#   test_cli.sh SEAMWALK SEAMWALK_PACK SEAMWALK_FLASH
set -uo pipefail
walker=$1 pack=$2 flash=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/swcli.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
failures=0

check() { # check DESCRIPTION CONDITION...
  local what=$1; shift
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; failures=$((failures + 1)); fi
}

# run PROGRAM ARGS...: keeps stdout, stderr and the exit status in $work.
run() {
  "$@" > "$work/out" 2> "$work/err" < /dev/null
  echo $? > "$work/code"
}
code() { cat "$work/code"; }

helps() { # helps NAME PROGRAM: --help on stdout, exit 0
  local name=$1 program=$2
  run "$program" --help
  check "$name --help: usage on stdout, nothing on stderr, exit 0" \
    eval '[ "$(code)" -eq 0 ] && grep -q "^usage: " "$work/out" && [ ! -s "$work/err" ]'
}

refuses() { # refuses NAME FRAGMENT PROGRAM ARGS...: a usage error naming FRAGMENT
  local name=$1 fragment=$2 program=$3; shift 3
  run "$program" "$@"
  check "$name $*: exit 2, '$fragment' and a hint on stderr" eval '
    [ "$(code)" -eq 2 ] && [ ! -s "$work/out" ] && [ "$(wc -l < "$work/err")" -eq 2 ] &&
    head -n 1 "$work/err" | grep -q -- "^$name: .*$fragment" &&
    [ "$(tail -n 1 "$work/err")" = "try '"'"'$name --help'"'"'" ]' ||
    echo "  got exit $(code): $(head -c 400 "$work/err")"
}

helps seamwalk "$walker"
check "seamwalk --help: no --test- option" eval '! grep -q -- "--test-" "$work/out"'
run "$walker" --help-test
check "seamwalk --help-test: the test options on stdout, exit 0" eval '
  [ "$(code)" -eq 0 ] && [ ! -s "$work/err" ] &&
  [ "$(grep -c -- "^  --test-" "$work/out")" -ge 6 ]'
refuses seamwalk "unknown option '--bogus'" "$walker" --pack x.swpack --orbit --bogus 1
refuses seamwalk "--frames expects" "$walker" --pack x.swpack --orbit --frames many
refuses seamwalk "--headless" "$walker" --pack x.swpack --orbit --headless 12x9999
refuses seamwalk "exactly one of --pack" "$walker" --orbit

helps seamwalk-pack "$pack"
refuses seamwalk-pack "missing command" "$pack"
refuses seamwalk-pack "unknown command 'frobnicate'" "$pack" frobnicate
refuses seamwalk-pack "build: unknown option '--fast'" "$pack" build a.txt -o b.swpack --fast
refuses seamwalk-pack "--up takes" "$pack" build a.txt -o b.swpack --up w
refuses seamwalk-pack "sign: --version takes" "$pack" sign a.swpack --key k.key --version v --name n
refuses seamwalk-pack "gen: --patches" "$pack" gen showroom --patches 0 -o "$work/s.ini"

helps seamwalk-flash "$flash"
refuses seamwalk-flash "missing command" "$flash"
refuses seamwalk-flash "unknown command 'frobnicate'" "$flash" frobnicate --store "$work/unit"
refuses seamwalk-flash "--chunk-kb takes" "$flash" install --store "$work/unit" --chunk-kb 0 p.swpack
refuses seamwalk-flash "unexpected '--bogus'" "$flash" status --store "$work/unit" --bogus
# boot-check's --attempts takes the range of seamwalk's --boot-attempts
# (firmware/program/sw_option_table.c).
refuses seamwalk-flash "--attempts takes 1..1000" "$flash" boot-check --store "$work/unit" --attempts 1001

[ "$failures" -eq 0 ] || { echo "test_cli: $failures failed"; exit 1; }
echo "test_cli: passed"
