#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Runs a test's command and passes only when it exits as expected and its
output says what it must. CTest's PASS_REGULAR_EXPRESSION alone ignores the
exit code: a crash, an abort or a sanitizer's report after the expected line
would pass. The command's output is passed through as it comes.

  expect_output.py --pass REGEX [--fail REGEX] [--exit N] [--skip N] -- COMMAND...

--pass: must match the command's stdout and stderr together; --fail: must
not; both read as CTest reads them ('.' matches a newline too). --exit: the
status the command must end with (default 0); killed by a signal never
passes. --skip: a status handed on as it is (the test's SKIP_RETURN_CODE).
Exit 0 passed, 1 failed, 2 usage."""
import re
import signal
import subprocess
import sys


def parse(argv):
    if "--" not in argv:
        return None
    split = argv.index("--")
    opts, command = argv[:split], argv[split + 1:]
    known = {"--pass": None, "--fail": None, "--exit": "0", "--skip": None}
    if len(opts) % 2 or not command:
        return None
    for name, value in zip(opts[::2], opts[1::2]):
        if name not in known:
            return None
        known[name] = value
    if known["--pass"] is None:
        return None
    return known, command


def run(command):
    """The command's exit status and its output, echoed as it comes."""
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    chunks = []
    for line in proc.stdout:
        sys.stdout.buffer.write(line)
        sys.stdout.flush()
        chunks.append(line)
    return proc.wait(), b"".join(chunks).decode("utf-8", "replace")


def verdict(opts, code, text):
    """None when the run passes, else why not."""
    if code < 0:
        return "killed by %s" % signal.Signals(-code).name
    if code != int(opts["--exit"]):
        return "exit status %d, expected %s" % (code, opts["--exit"])
    if opts["--fail"] is not None and re.search(opts["--fail"], text, re.DOTALL):
        return "the output matches the failure expression %r" % opts["--fail"]
    if not re.search(opts["--pass"], text, re.DOTALL):
        return "the output does not match %r" % opts["--pass"]
    return None


def main():
    parsed = parse(sys.argv[1:])
    if parsed is None:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    opts, command = parsed
    code, text = run(command)
    if opts["--skip"] is not None and code == int(opts["--skip"]):
        print("expect_output: skipped (exit %d)" % code)
        return code
    why = verdict(opts, code, text)
    print("expect_output: " + ("passed" if why is None else "FAIL: " + why))
    return 0 if why is None else 1


if __name__ == "__main__":
    sys.exit(main())
