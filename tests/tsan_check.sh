#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The TSan step checks what it claims (tests/run-tsan.sh): a planted race
# (tsan_race) is reported and fails with TSan's exit code 66; the runtime
# and a test program of the threaded walk carry TSan's instrumentation; the
# host tool and the installer, which start no thread, are built without it
# (sw_without_tsan), and so are the programs of the tests the step leaves out.
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
for program in assets/seamwalk-pack firmware/seamwalk-flash; do
  instrumented "$build/$program" && fail "$program is built with TSan"
done
echo "ok   seamwalk-pack and seamwalk-flash are built without TSan (they start no thread)"
# The step leaves out the tests labelled host_only (sw_host_only_test,
# tests/CMakeLists.txt); their test programs must be uninstrumented too.
for program in tests/test_pack_write tests/test_import_occt tests/test_flash_power; do
  [ -x "$build/$program" ] || fail "$program is not built"
  instrumented "$build/$program" && fail "$program is built with TSan but labelled host_only"
done
host_only=$(ctest --test-dir "$build" -N -L host_only)
grep -q " test_pack_cli$" <<< "$host_only" || fail "test_pack_cli is not labelled host_only"
grep -q " walk_threads$" <<< "$host_only" &&
  fail "walk_threads, which runs the threaded walk, is labelled host_only"
echo "ok   the host_only tests run uninstrumented programs, the threaded walk is not one of them"
