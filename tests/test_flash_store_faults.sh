#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# No store fault stops a boot, and boot-check says what the boot will do.
# For each fault the unit's user can meet (the service runs as seamwalk;
# here as nobody): a lock and state left by root's install, a lock it cannot
# open, a store directory it cannot write, a read-only mount, a state that
# cannot be written, an install holding the lock, a state it cannot read,
# seamwalk --store run as that user starts a verified slot (exit 0) and
# says why, and seamwalk-flash boot-check run as the same user just before
# names the same slot, run the same way, for the same reason, and changes
# nothing in the store.
#   test_flash_store_faults.sh SEAMWALK SEAMWALK_FLASH FIXTURE WORK
set -uo pipefail
walker=$1 flash=$2 fixture=$3 work=$4
if [ "$(id -u)" != 0 ]; then
  echo "skipped: needs root, to leave files as root and run as the unit's user (nobody)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work" && chmod 755 "$work"
unit=$work/unit cfg=$fixture/unit.ini
if ! setpriv --reuid=65534 --regid=65534 --clear-groups test -x "$flash" -a -r "$cfg" -a -x "$work"; then
  echo "skipped: the unit's user (nobody) cannot reach the build tree (a private home directory?)"
  exit 77
fi
failures=0 checks=0
check() { checks=$((checks + 1)); if ! "${@:2}"; then echo "FAIL: $1"; failures=$((failures + 1)); fi; }
as_unit_user() { setpriv --reuid=65534 --regid=65534 --clear-groups env HOME=/nonexistent "$@"; }
# A read-only mount of the store, in a mount namespace of its own.
read_only() {
  unshare -m sh -c 'mount --bind "$1" "$1" && mount -o remount,bind,ro "$1" && shift && exec "$@"' \
    sh "$unit" "$@"
}
# Every file, its owner, mode, size and time, and the state's text.
snapshot() { (cd "$unit" && ls -l --time-style=+%s && cat state state.copy 2>/dev/null) | cksum; }

# A unit as root's seamwalk-flash leaves it: slot A good (spoon-1), slot B
# pending (cup-2); every file root's. own: who owns the store directory.
make_unit() {  # make_unit OWNER [old-only]
  rm -rf "$unit" && mkdir -p "$unit"
  "$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/old.swpack" >/dev/null
  if [ "${2:-}" != old-only ]; then
    "$flash" mark-good --store "$unit" --config "$cfg" >/dev/null
    "$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/new.swpack" >/dev/null
  fi
  chown "$1" "$unit"
}

# fault NAME EXPECTED-KIND EXPECTED-WHY [PREFIX...]: boot-check, then the
# boot, as the unit's user (under PREFIX, if given); the same slot, kind and
# message, the kind and why as expected, and boot-check changed nothing.
fault() {
  local name=$1 want_kind=$2 want_why=$3
  shift 3
  local before after
  before=$(snapshot)
  "$@" setpriv --reuid=65534 --regid=65534 --clear-groups env HOME=/nonexistent \
    "$flash" boot-check --store "$unit" --config "$cfg" >"$work/check" 2>&1
  local check_rc=$?
  after=$(snapshot)
  "$@" setpriv --reuid=65534 --regid=65534 --clear-groups env HOME=/nonexistent \
    "$walker" --store "$unit" --keys "$fixture/keys" --headless 160x120 --orbit --frames 3 \
    --good-after-s 1e9 >"$work/log" 2>&1
  local boot_rc=$?
  # boot-check: "boot: MESSAGE" lines, then "boot: slot X 'NAME' version N (KIND), verified".
  local last msg slot name_= version= kind
  last=$(tail -n 1 "$work/check")
  msg=$(head -n -1 "$work/check" | sed 's/^boot: //')
  if [[ $last =~ ^boot:\ slot\ ([AB])\ \'([^\']*)\'\ version\ ([0-9]+)\ \((.*)\),\ verified$ ]]; then
    slot=${BASH_REMATCH[1]} name_=${BASH_REMATCH[2]} version=${BASH_REMATCH[3]} kind=${BASH_REMATCH[4]}
  else
    slot=none kind=none
  fi
  local ok=1
  [ "$check_rc" = 0 ] || { echo "  boot-check exited $check_rc"; ok=0; }
  [ "$boot_rc" = 0 ] || { echo "  the boot exited $boot_rc"; ok=0; }
  [ "$before" = "$after" ] || { echo "  boot-check changed the store"; ok=0; }
  [[ $kind =~ $want_kind ]] || { echo "  boot-check's kind '$kind', expected /$want_kind/"; ok=0; }
  grep -qE -- "$want_why" <<<"$msg" || { echo "  boot-check did not say /$want_why/"; ok=0; }
  grep -qFx "seamwalk: store: starting slot $slot ('$name_' version $version), $kind" "$work/log" ||
    { echo "  the boot did not start slot $slot ($kind)"; ok=0; }
  if [ -n "$msg" ] && ! grep -qFx "seamwalk: store: $msg" "$work/log"; then
    echo "  the boot did not say what boot-check said"; ok=0
  fi
  checks=$((checks + 1))
  if [ "$ok" = 1 ]; then
    echo "ok: $name: slot $slot ($kind)${msg:+: $msg}"
  else
    echo "FAIL: $name"; cat "$work/check" "$work/log"; failures=$((failures + 1))
  fi
}

# What a root install leaves in the unit's own directory: a root lock and
# state. flock needs no write access and the state is replaced by rename,
# so the trial runs and is recorded.
make_unit nobody
fault "lock and state left by root's install" "^pending: boot attempt 1$" "^$"
check "the trial was recorded" grep -q "^attempts 1$" "$unit/state"
check "in both copies" grep -q "^attempts 1$" "$unit/state.copy"

# A lock the unit's user cannot open at all (root's, mode 600).
make_unit nobody
chmod 600 "$unit/lock"
fault "a lock the user cannot open" "^good$" "lock: cannot open the lock: Permission denied: starting the good slot, no trial"
check "nothing recorded" grep -q "^attempts 0$" "$unit/state"

# The store directory root's: read-only to the unit's user.
make_unit root
fault "a store directory the user cannot write" "^good$" "cannot record the boot \(.*state.tmp: Permission denied\): starting the good slot, no trial"

# The same with no lock file: it cannot be made either.
make_unit root
rm -f "$unit/lock"
fault "no lock, and a store directory the user cannot write" "^good$" "cannot open the lock: No such file or directory: starting the good slot, no trial"

# A read-only mount (a store outside the unit's ReadWritePaths under
# ProtectSystem=strict).
make_unit nobody
fault "a read-only mount" "^good$" "cannot record the boot \(.*Read-only file system\): starting the good slot, no trial" read_only

# A state that cannot be written (state.tmp is in the way).
make_unit nobody
mkdir "$unit/state.tmp"
fault "an unwritable state" "^good$" "cannot record the boot \(.*state.tmp: Is a directory\)"

# An install holds the lock: the boot does not wait and starts no trial.
make_unit nobody
exec 9<"$unit/lock"
flock 9
fault "an install holding the lock" "^good$" "the store is busy \(an install is running\): starting the good slot, no trial"
exec 9<&-

# No good slot yet (a first install by root) and a read-only store: the
# verified pending slot runs unrecorded rather than nothing.
make_unit root old-only
fault "a first install, read-only" "^pending, unrecorded$" "no good slot, so the pending slot starts unrecorded"
make_unit nobody old-only
fault "a first install, read-only mount" "^pending, unrecorded$" "Read-only file system.*no good slot" read_only

# A state the unit's user cannot read (both copies root's, mode 600): no
# valid state, so the newest slot that verifies.
make_unit root
chmod 600 "$unit/state" "$unit/state.copy"
fault "a state the user cannot read" "^recovered" "state: Permission denied.*state.copy: Permission denied.*starting the newest slot that verifies"

# A damaged copy and a read-only mount: the other copy, no trial.
make_unit nobody
printf 'X' | dd of="$unit/state.copy" bs=1 seek=20 conv=notrunc status=none
fault "a damaged copy, read-only mount" "^good$" "state.copy:.*using state.*Read-only file system" read_only

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
