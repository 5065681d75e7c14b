# SPDX-License-Identifier: MIT
# The checks the shell tests share, sourced: check DESCRIPTION COMMAND...
# runs COMMAND and counts it as passed or failed ("ok" or "FAIL" and the
# description on a line); checks_done prints the counts and returns 1 when
# any failed. run ARGS... runs $tool with ARGS, keeping its stdout, stderr
# and exit status in $work (out, err, code); code, has FILE PATTERN and said
# PATTERN (on stderr, printing it when not) read them.
failures=0 checks=0
check() {
  local what=$1; shift
  checks=$((checks + 1))
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; failures=$((failures + 1)); fi
}
checks_done() { echo "$checks checks, $failures failed"; [ "$failures" -eq 0 ]; }
run() { "$tool" "$@" > "$work/out" 2> "$work/err"; echo $? > "$work/code"; }
code() { cat "$work/code"; }
has() { grep -q -- "$2" "$1"; }
said() { has "$work/err" "$1" || { echo "  stderr: $(cat "$work/err")"; false; }; }
