#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The tests that check a program's output pass only when it also exits as
expected (tests/expect_output.py): the expected line followed by a crash,
an abort or a non-zero exit fails, and no CTest test of the build checks
output with PASS_REGULAR_EXPRESSION alone, which ignores the exit code.
  test_expect_output.py BUILD_DIR"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
WRAPPER = os.path.join(HERE, "expect_output.py")
LINE = "soak: 20 s, 2 loops; mallocs_after_init 0"
PASS = "soak: 20 s, .*mallocs_after_init 0\n"
failures = 0


def check(what, ok):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += not ok


def wrapped(script, *opts):
    """The wrapper's exit status on a shell command."""
    command = [sys.executable, WRAPPER, "--pass", PASS, *opts, "--", "sh", "-c", script]
    return subprocess.run(command, stdout=subprocess.DEVNULL).returncode


def check_verdicts():
    say = "echo '%s'; " % LINE
    check("the expected line and exit 0 pass", wrapped(say + "exit 0") == 0)
    check("the expected line, then SIGSEGV, fails", wrapped(say + "kill -SEGV $$") == 1)
    check("the expected line, then abort, fails", wrapped(say + "kill -ABRT $$") == 1)
    check("the expected line, then a crashed child's status, fails",
          wrapped(say + "sh -c 'kill -SEGV $$'") == 1)
    check("the expected line, then a leak report's exit 23, fails", wrapped(say + "exit 23") == 1)
    check("exit 0 without the line fails", wrapped("echo nothing") == 1)
    check("a failure line fails", wrapped(say + "echo 'soak: FAIL: x'", "--fail", "soak: FAIL") == 1)
    check("an expected exit 1 passes", wrapped(say + "exit 1", "--exit", "1") == 0)
    check("exit 0 where 1 is expected fails", wrapped(say + "exit 0", "--exit", "1") == 1)
    check("a skip status is handed on", wrapped("exit 77", "--skip", "77") == 77)


def ctest_tests(build):
    out = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1"],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)["tests"]


def check_suite(build):
    tests = ctest_tests(build)
    bare = [t["name"] for t in tests
            if any(p["name"] == "PASS_REGULAR_EXPRESSION" for p in t.get("properties", []))]
    check("no test relies on PASS_REGULAR_EXPRESSION alone (%s)" % (", ".join(bare) or "none"),
          not bare)
    through = [t["name"] for t in tests if WRAPPER in t.get("command", [])]
    check("the output checks run through expect_output.py (%d: %s)"
          % (len(through), ", ".join(through)), "soak_short" in through)


def main():
    if len(sys.argv) != 2:
        print(__doc__.split("\n")[-1], file=sys.stderr)
        return 2
    check_verdicts()
    check_suite(sys.argv[1])
    print("test_expect_output: %s" % ("FAIL" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
