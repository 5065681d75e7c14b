#!/usr/bin/env bash
# The TSan step checks what it claims (tests/run-tsan.sh): a planted race
# (tsan_race) is reported and fails with TSan's exit code 66; the runtime
# and a test program of the threaded walk carry TSan's instrumentation; the
# host tool, which starts no thread, is built without it (sw_without_tsan).
#   tsan_check.sh BUILD_DIR
set -uo pipefail
build=$1
fail() { echo "FAIL: $*"; exit 1; }
out=$(mktemp) && trap 'rm -f "$out"' EXIT
"$build/tests/tsan_race" > /dev/null 2> "$out"
rc=$?
[ $rc -eq 66 ] || fail "the planted race exited $rc, expected 66: $(head -c 300 "$out")"
grep -q "WARNING: ThreadSanitizer: data race" "$out" || fail "no race report for the planted race"
echo "ok   the planted race is reported and fails (exit 66)"
# grep -c reads all of nm's output: -q would stop early, and nm's SIGPIPE
# fail the pipe under pipefail.
instrumented() { nm "$1" 2>/dev/null | grep -c " __tsan_func_entry$" > /dev/null; }
for program in firmware/seamwalk tests/test_handoff tests/test_steal_queue; do
  instrumented "$build/$program" || fail "$program is not built with TSan"
done
echo "ok   seamwalk, test_handoff and test_steal_queue are instrumented"
instrumented "$build/assets/seamwalk-pack" && fail "seamwalk-pack is built with TSan"
echo "ok   seamwalk-pack is built without TSan (it starts no thread)"
