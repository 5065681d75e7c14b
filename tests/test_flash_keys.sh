#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The unit's trust anchor. A keys file its own user could change (group- or
# world-writable, owned by that user, in a directory that user owns or that
# others may write, or reached through such a directory or link) is refused
# by the boot, boot-check, status and install alike, naming the file or
# directory, its owner and mode. seamwalk-flash trusts the unit's keys only
# (its config's [pack] keys): --keys can narrow them, never add one. The
# signature is checked over the raw bytes before any section is parsed: a
# stranger's pack with a broken section is refused for its key, not its
# checksum, at install and at boot.
#   test_flash_keys.sh SEAMWALK SEAMWALK_FLASH FIXTURE WORK
set -uo pipefail
walker=$1 flash=$2 fixture=$3 work=$4
if [ "$(id -u)" != 0 ]; then
  echo "skipped: needs root, to make keys files root's and another user's"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work" && chmod 755 "$work"
unit=$work/unit
failures=0 checks=0
check() { checks=$((checks + 1)); if ! "${@:2}"; then echo "FAIL: $1"; cat "$work/out"; failures=$((failures + 1)); fi; }
both() { [ "$(cat "$work/rc")" = "$1" ] && grep -qE -- "$2" "$work/out"; }
unchanged() { [ "$(snapshot)" = "$before" ]; }
snapshot() { (cd "$unit" && cat state state.copy slot-*.swpack 2>/dev/null | cksum); }
config() {  # config KEYS: a unit config naming KEYS
  printf '[pack]\nkeys = %s\n' "$1" >"$work/unit.ini"
}
fl() { "$flash" "$@" --store "$unit" --config "$work/unit.ini" >"$work/out" 2>&1; echo $? >"$work/rc"; }
boot() {  # boot KEYS
  "$walker" --store "$unit" --keys "$1" --headless 160x120 --orbit --frames 3 \
    --good-after-s 1e9 >"$work/out" 2>&1
  echo $? >"$work/rc"
}

# A unit with slot A good, installed with the fixture's (root's) keys.
mkdir -p "$unit"
config "$fixture/keys"
fl install "$fixture/old.swpack"; check "install with root's keys" both 0 "installed 'spoon-1'"
fl mark-good; check "mark-good" both 0 "is good and active"
before=$(snapshot)

# ---- keys the unit's user could change ------------------------------------------
# refused NAME KEYS-PATH WHAT: every command and the boot refuse, naming WHAT.
refused() {
  local name=$1 keys=$2 what=$3
  config "$keys"
  fl install "$fixture/new.swpack"
  check "$name: install refuses" both 1 "$what"
  check "$name: install changed nothing" unchanged
  fl boot-check; check "$name: boot-check: no slot" both 6 "$what"
  fl status; check "$name: status says why the slots are not verified" both 0 "slots not verified: .*$what"
  fl repair; check "$name: repair refuses" both 1 "$what"
  boot "$keys"
  check "$name: the boot shows the message screen" both 3 "$what"
  check "$name: the boot's log says why" grep -q "no valid pack in" "$work/out"
}
k=$work/k && mkdir -p "$k"
cp "$fixture/keys" "$k/group-writable" && chmod 664 "$k/group-writable"
refused "group-writable keys" "$k/group-writable" "$k/group-writable: the trusted keys file is owned by uid 0 with mode 0664; trusted keys must be owned by root"
cp "$fixture/keys" "$k/world-writable" && chmod 646 "$k/world-writable"
refused "world-writable keys" "$k/world-writable" "the trusted keys file is owned by uid 0 with mode 0646"
cp "$fixture/keys" "$k/users" && chown 65534 "$k/users"
refused "keys owned by the unit's user" "$k/users" "$k/users: the trusted keys file is owned by uid 65534 with mode 0644"
# The old default: DIR/keys, in the store the unit's user owns and writes.
mkdir -p "$work/store" && cp "$fixture/keys" "$work/store/keys" && chown 65534 "$work/store"
refused "root's keys in the unit's user's store" "$work/store/keys" "$work/store: a directory above the trusted keys is owned by uid 65534 with mode 0755"
mkdir -p "$work/shared" && cp "$fixture/keys" "$work/shared/keys" && chmod 775 "$work/shared"
refused "keys in a group-writable directory" "$work/shared/keys" "$work/shared: a directory above the trusted keys is owned by uid 0 with mode 0775"
# A link in the unit's user's directory to root's keys: the user could
# point it anywhere.
mkdir -p "$work/links" && ln -s "$fixture/keys" "$work/links/keys" && chown 65534 "$work/links"
refused "a link in the unit's user's directory" "$work/links/keys" "$work/links: a directory above the trusted keys is owned by uid 65534"
# A link root made, in root's directory, to root's keys is fine.
mkdir -p "$work/etc" && ln -s "$fixture/keys" "$work/etc/keys"
config "$work/etc/keys"
fl boot-check; check "root's link to root's keys" both 0 "slot A 'spoon-1' version 1 \(good\), verified"
# The default, /etc/seamwalk/keys, when nothing names the keys.
if [ ! -e /etc/seamwalk/keys ]; then
  printf '[pack]\n' >"$work/unit.ini"
  fl boot-check; check "the default keys: /etc/seamwalk/keys" both 6 "/etc/seamwalk/keys: No such file or directory: the unit's trusted keys"
  "$walker" --store "$unit" --headless 160x120 --orbit --frames 3 >"$work/out" 2>&1; echo $? >"$work/rc"
  check "the boot's default keys: /etc/seamwalk/keys" both 3 "/etc/seamwalk/keys: No such file or directory"
fi

# ---- --keys narrows, never widens ---------------------------------------------------
config "$fixture/keys"
fl install "$fixture/stranger.swpack" --keys "$fixture/stranger.pub"
check "--keys with a key the unit does not trust: refused" both 3 "stranger.pub: key [0-9a-f]{8}\.\.\. is not among the unit's trusted keys \($fixture/keys\): --keys can only narrow them"
check "--keys: the unit unchanged" unchanged
cat "$fixture/owner.pub" "$fixture/stranger.pub" >"$work/both.pub"
fl install "$fixture/stranger.swpack" --keys "$work/both.pub"
check "--keys with the unit's key and another: refused" both 3 "is not among the unit's trusted keys"
check "--keys both: the unit unchanged" unchanged
fl boot-check --keys "$fixture/stranger.pub"
check "boot-check --keys with another key: no slot" both 6 "not among the unit's trusted keys"
fl install "$fixture/stranger.swpack"
check "a stranger's pack: refused" both 3 "not among the 1 trusted keys"
fl install "$fixture/new.swpack" --keys "$fixture/owner.pub"
check "--keys narrowed to the unit's own key: installs" both 0 "installed 'cup-2'"
fl rollback >/dev/null
before=$(snapshot)

# ---- the signature before any section is parsed -------------------------------------
# A stranger's pack with a section's byte changed: the parser would say
# checksum; checked first, the signature says whose it is.
cp "$fixture/stranger.swpack" "$work/broken-stranger.swpack"
printf 'X' | dd of="$work/broken-stranger.swpack" bs=1 seek=5000 conv=notrunc status=none
fl install "$work/broken-stranger.swpack"
check "a stranger's broken pack: refused for its key" both 3 "refused \(untrusted key\)"
check "not for a checksum" bash -c "! grep -qi checksum '$work/out'"
cp "$fixture/new.swpack" "$work/broken-own.swpack"
printf 'X' | dd of="$work/broken-own.swpack" bs=1 seek=5000 conv=notrunc status=none
fl install "$work/broken-own.swpack"
check "the owner's pack changed after signing: tampered" both 3 "refused \(tampered\).*|SIGNATURE: does not match the pack's bytes"
check "tampered: the unit unchanged" unchanged
# At boot: slot B made pending with the owner's pack, then its file
# replaced by the stranger's broken one.
fl install "$fixture/new.swpack"
cp "$work/broken-stranger.swpack" "$unit/slot-b.swpack"
boot "$fixture/keys"
check "boot: the stranger's slot refused for its key" grep -q "slot B does not start: .*not among the 1 trusted keys" "$work/out"
check "boot: not for a checksum" bash -c "! grep -q 'slot B does not start: .*checksum' '$work/out'"
check "boot: the good slot runs" both 0 "starting slot A \('spoon-1' version 1\), good"

# ---- the shipped config ---------------------------------------------------------------
ini=$(dirname "$0")/../firmware/dist/seamwalk.ini
check "the shipped config names /etc/seamwalk/keys" grep -q "^keys = /etc/seamwalk/keys$" "$ini"
check "the shipped config says pack = runs unsigned" grep -q "pack = FILE RUNS AN UNSIGNED PACK" "$ini"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
