#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The unit and the udev rule as shipped (firmware/dist/seamwalk.service,
# firmware/dist/70-seamwalk.rules, issue 25): the unit verifies (systemd-analyze
# verify, on a copy whose ExecStart is this build's seamwalk), rates at most
# 3.0 in `systemd-analyze security` (offline: no running systemd needed),
# is Type=notify with a watchdog, and leaves llvmpipe's JIT its writable
# and executable memory. The udev rule gives the seamwalk group only game
# controllers' hidraw nodes: its own PROGRAM and RESULT are run here on
# recorded report descriptors (tests/hid) in a fake sysfs. seamwalk runs
# under the unit's own system call filter, NoNewPrivileges= and (should
# the unit ever set it) MemoryDenyWriteExecute= (tests/unit_sandbox.py),
# as the unit's user, and draws with llvmpipe; the same run with
# MemoryDenyWriteExecute=yes added must fail, or the run would prove
# nothing about the JIT. The systemd checks are skipped, saying so, where
# systemd-analyze is missing.
#   test_service.sh SEAMWALK SEAMWALK_PACK SOURCE_DIR WORK
set -uo pipefail
walker=$1 packer=$2 src=$3 work=$4
unit=$src/firmware/dist/seamwalk.service rules=$src/firmware/dist/70-seamwalk.rules
rm -rf "$work" && mkdir -p "$work"
failures=0 checks=0
check() { checks=$((checks + 1)); if ! "${@:2}"; then echo "FAIL: $1"; failures=$((failures + 1)); return 1; fi; }
has() { grep -Eq "$1" "$unit"; }

# ---- the unit's own lines ------------------------------------------------------------
check "Type=notify" has '^Type=notify$'
check "a watchdog" has '^WatchdogSec=[1-9][0-9]*s?$'
check "only the main process notifies" has '^NotifyAccess=main$'
check "llvmpipe's JIT: no MemoryDenyWriteExecute=yes" bash -c "! grep -Eq '^MemoryDenyWriteExecute=(yes|true|1)' '$unit'"
check "the store is the state directory" has '^StateDirectory=.*seamwalk/store'
check "the config it passes is /etc/seamwalk/seamwalk.ini" has '^ExecStart=.* --config /etc/seamwalk/seamwalk.ini '

# ---- systemd-analyze ------------------------------------------------------------------
if command -v systemd-analyze >/dev/null; then
  # verify: on a copy that runs this build's seamwalk (the installed path does
  # not exist here); any line it prints is a problem in the unit.
  sed "s|^ExecStart=/usr/local/bin/seamwalk |ExecStart=$walker |" "$unit" >"$work/seamwalk.service"
  systemd-analyze verify --man=no "$work/seamwalk.service" >"$work/verify" 2>&1
  echo "verify rc $?" >>"$work/verify"
  check "systemd-analyze verify: clean" bash -c "[ \"\$(cat '$work/verify')\" = 'verify rc 0' ]" ||
    cat "$work/verify"
  systemd-analyze security --offline=true "$unit" >"$work/security" 2>&1
  score=$(sed -n 's/.*Overall exposure level for seamwalk.service: \([0-9.]*\).*/\1/p' "$work/security")
  echo "systemd-analyze security: $score (issue 25 asks for at most 3.0; it was 8.4)"
  check "security: rated" [ -n "$score" ]
  check "security: at most 3.0" python3 -c "import sys; sys.exit(0 if float('${score:-99}') <= 3.0 else 1)"

  # ---- the hardening against llvmpipe's JIT ------------------------------------------
  # A walk of a few frames, written as PNGs, under the unit's filters, as the
  # unit's user (nobody here) where this test runs as root.
  "$packer" build "$src/assets/samples/teaspoon.txt" -o "$work/spoon.swpack" --quiet
  chmod -R a+rX "$work" && chmod a+w "$work"
  as_user=()
  if [ "$(id -u)" = 0 ] && setpriv --reuid=65534 --regid=65534 --clear-groups test -x "$walker" -a -r "$work/spoon.swpack"; then
    as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups env HOME=/nonexistent)
  fi
  # LeakSanitizer stops the world with ptrace, which the unit's filter
  # refuses: under a sanitizer build the leak check is left to the other
  # tests, or every run here would end "LeakSanitizer has encountered a
  # fatal error".
  walk_under() {  # walk_under UNIT NAME: exit status of seamwalk under UNIT's filters
    rm -rf "$work/$2-png"
    "${as_user[@]}" env ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" python3 "$src/tests/unit_sandbox.py" "$1" "$walker" --pack "$work/spoon.swpack" \
      --headless 160x120 --orbit --frames 8 --png-dir "$work/$2-png" --png-every 4 >"$work/$2.log" 2>&1
  }
  walk_under "$unit" unit
  rc=$?
  check "llvmpipe draws under the unit's filters (exit $rc${as_user:+, as nobody})" \
    bash -c "[ $rc = 0 ] && [ -s '$work/unit-png/frame_00004.png' ]" || tail -n 5 "$work/unit.log"
  { cat "$unit"; echo "MemoryDenyWriteExecute=yes"; } >"$work/mdwe.service"
  walk_under "$work/mdwe.service" mdwe
  rc=$?
  check "the same walk with MemoryDenyWriteExecute=yes fails (exit $rc): the run reaches the JIT" \
    [ "$rc" != 0 ]
else
  echo "skipped: systemd-analyze is not installed (Debian: systemd)"
fi

# ---- the udev rule ---------------------------------------------------------------------
# Every rule that gives the group a node names hidraw with the descriptor
# check or one gpiochip; no wildcard grant of every hidraw or every chip.
grants=$(grep -v '^#' "$rules" | grep 'GROUP="seamwalk"')
check "udev: one active grant" [ "$(printf '%s\n' "$grants" | grep -c .)" = 1 ]
check "udev: the grant is hidraw with the descriptor check" \
  bash -c "printf '%s\n' '$grants' | grep -q 'SUBSYSTEM==\"hidraw\".*PROGRAM=.*RESULT=='"
check "udev: no gpiochip wildcard" bash -c "! grep -v '^#' '$rules' | grep -q 'gpiochip\*\"' "
program=$(printf '%s\n' "$grants" | sed -n 's/.*PROGRAM="\([^"]*\)".*/\1/p')
result=$(printf '%s\n' "$grants" | sed -n 's/.*RESULT=="\([^"]*\)".*/\1/p')
# udev: %S the sysfs mount, %p the node's devpath; RESULT is a shell glob.
matches() {  # matches HEXFILE: the rule's PROGRAM on a fake sysfs holding that descriptor
  local dev=$work/sys/devices/hid/hidraw/hidraw0
  rm -rf "$work/sys" && mkdir -p "$dev/device"
  python3 -c "import sys; sys.stdout.buffer.write(bytes.fromhex(' '.join(
    l for l in open(sys.argv[1]) if not l.startswith('#'))))" "$1" >"$dev/device/report_descriptor"
  local cmd=${program//%S/$work/sys}
  cmd=${cmd//%p//devices/hid/hidraw/hidraw0}
  local out
  out=$($cmd) || return 2
  # shellcheck disable=SC2053  # the rule's RESULT is a glob, as udev reads it
  [[ $out == $result ]]
}
for pad in ds4_usb asus_gamepad logitech_f310_dinput saitek_joystick; do
  check "udev: $pad's hidraw goes to seamwalk" matches "$src/tests/hid/$pad.hex"
done
printf '05 01 09 06 a1 01 05 07 19 e0 29 e7\n' >"$work/keyboard.hex"       # boot keyboard
printf '06 d0 f1 09 01 a1 01 09 20 15 00 26\n' >"$work/fido.hex"           # FIDO U2F key
printf '05 01 09 02 a1 01 09 01 a1 00 05 09\n' >"$work/mouse.hex"          # mouse
printf '05 0c 09 01 a1 01 85 01 09 04 a1 01\n' >"$work/consumer.hex"       # consumer keys
for other in keyboard fido mouse consumer; do
  matches "$work/$other.hex"
  check "udev: a $other's hidraw stays root's" [ $? = 1 ]
done

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
