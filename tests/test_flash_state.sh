#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The store's state is kept twice (state, state.copy): one damaged, empty
# or missing copy loses nothing (the boot, boot-check, status, install,
# rollback and mark-good go on from the other, and say which); with both
# gone the boot starts the newest slot that verifies, boot-check says the
# same, the commands that change the state refuse and say to repair, and
# seamwalk-flash repair rebuilds the state from the slots.
#   test_flash_state.sh SEAMWALK SEAMWALK_FLASH FIXTURE WORK
set -uo pipefail
if [ "$(id -u)" != 0 ]; then  # the unit's trusted keys must be root's (firmware/store/STORE.md)
  echo "skipped: needs root, for trusted keys owned by root"
  exit 77
fi
walker=$1 flash=$2 fixture=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
unit=$work/unit cfg=$fixture/unit.ini
failures=0 checks=0
check() { checks=$((checks + 1)); if ! "${@:2}"; then echo "FAIL: $1"; cat "$work/out"; failures=$((failures + 1)); fi; }
fl() { "$flash" "$@" --store "$unit" --config "$cfg" >"$work/out" 2>&1; echo $? >"$work/rc"; }
boot() {
  "$walker" --store "$unit" --keys "$fixture/keys" --headless 160x120 --orbit --frames 3 \
    --good-after-s 1e9 >"$work/out" 2>&1
  echo $? >"$work/rc"
}
rc() { [ "$(cat "$work/rc")" = "$1" ]; }
said() { grep -qE -- "$1" "$work/out"; }
both() { [ "$(cat "$work/rc")" = "$1" ] && grep -qE -- "$2" "$work/out"; }
# A unit with slot A good (spoon-1, version 1) and B pending (cup-2, version 2).
make_unit() {
  rm -rf "$unit" && mkdir -p "$unit"
  "$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/old.swpack" >/dev/null &&
    "$flash" mark-good --store "$unit" --config "$cfg" >/dev/null &&
    "$flash" install --store "$unit" --config "$cfg" --quiet "$fixture/new.swpack" >/dev/null
}
flip() {  # flip FILE: one bit of the byte in the middle
  python3 -c "import sys; p=sys.argv[1]; b=bytearray(open(p,'rb').read()); b[len(b)//2]^=1; open(p,'wb').write(b)" "$1"
}
damage() {  # damage HOW FILE
  case $1 in
    flipped) flip "$2" ;;
    empty) : >"$2" ;;
    missing) rm -f "$2" ;;
  esac
}

# ---- one copy damaged, empty or missing: nothing lost ------------------------------
for how in flipped empty missing; do
  for copy in state state.copy; do
    other=$([ "$copy" = state ] && echo state.copy || echo state)
    what="$how $copy"
    make_unit; damage "$how" "$unit/$copy"
    fl boot-check
    check "$what: boot-check goes by $other" both 0 "using $other"
    check "$what: boot-check starts B on trial" said "slot B 'cup-2' version 2 \(pending: boot attempt 1\), verified"
    fl status
    check "$what: status exits 0" rc 0
    check "$what: status names the copy" said "^state: .*$copy.*repair rewrites it from $other"
    check "$what: status keeps the knowledge" said "^pending: B \(0 boots so far\)"
    boot
    check "$what: the boot says which copy" both 0 "using $other"
    check "$what: the boot starts the trial" said "starting slot B \('cup-2' version 2\), pending: boot attempt 1"
    check "$what: the record rewrote both copies" cmp -s "$unit/state" "$unit/state.copy"
    make_unit; damage "$how" "$unit/$copy"
    fl rollback; check "$what: rollback" both 0 "dropped pending slot B"
    make_unit; damage "$how" "$unit/$copy"
    fl mark-good; check "$what: mark-good" both 0 "slot B .* is good and active"
    make_unit; damage "$how" "$unit/$copy"
    fl install "$fixture/old.swpack" --allow-downgrade; check "$what: install" both 0 "installed 'spoon-1'"
    make_unit; damage "$how" "$unit/$copy"
    fl repair; check "$what: repair rewrites it" both 0 "rewriting the state from $other"
    check "$what: repair made the copies equal" cmp -s "$unit/state" "$unit/state.copy"
    fl status; check "$what: repaired, status as before" both 0 "^pending: B \(0 boots so far\)"
    check "$what: and no damage left" bash -c "! grep -q '^state: ' '$work/out'"
  done
done

# ---- both copies gone: the newest slot that verifies, then repair ------------------------
for how in flipped empty missing; do
  what="both $how"
  make_unit; damage "$how" "$unit/state"; damage "$how" "$unit/state.copy"
  fl boot-check
  check "$what: boot-check says so" both 0 "starting the newest slot that verifies, unrecorded"
  check "$what: boot-check starts B, the newest" said "slot B 'cup-2' version 2 \(recovered: .*\), verified"
  boot
  check "$what: the boot starts B" both 0 "starting slot B \('cup-2' version 2\), recovered"
  check "$what: the boot wrote no state" bash -c "[ ! -s '$unit/state' ] || ! '$flash' status --store '$unit' --config '$cfg' >/dev/null 2>&1"
  fl status
  check "$what: status fails" rc 1
  check "$what: status names both copies, or says none is there" \
    said "no valid store state .*/state[:,].*/state.copy|no state file beside the slot files"
  check "$what: status shows the slot files" said "^slot B file: 'cup-2' version 2, .*verified"
  for cmd in rollback mark-good; do
    fl "$cmd"; check "$what: $cmd refuses, says repair" both 1 "\(seamwalk-flash repair rebuilds it"
  done
  fl install "$fixture/new.swpack"; check "$what: install refuses, says repair" both 1 "seamwalk-flash repair"
  fl repair
  check "$what: repair rebuilds from the slots" both 0 "slot A 'spoon-1' version 1 verifies: good"
  check "$what: repair makes the newest active" said "state written \(generation 1\): active B, pending -"
  fl boot-check; check "$what: repaired, B boots as good" both 0 "slot B 'cup-2' version 2 \(good\), verified"
  fl rollback; check "$what: repaired, A is there to roll back to" both 0 "slot A .* is active again"
done

# Both copies damaged and the newest slot does not verify: the other one.
make_unit; flip "$unit/state"; flip "$unit/state.copy"
printf 'X' | dd of="$unit/slot-b.swpack" bs=1 seek=5000 conv=notrunc status=none
fl boot-check
check "damaged B: boot-check says B does not verify" said "slot B does not verify"
check "damaged B: boot-check starts A" both 0 "slot A 'spoon-1' version 1 \(recovered: .*\), verified"
boot
check "damaged B: the boot says so" said "slot B does not start"
check "damaged B: the boot starts A" both 0 "starting slot A \('spoon-1' version 1\), recovered"
fl repair
check "damaged B: repair leaves B empty" said "repair: slot B: .*: empty"
check "damaged B: A active" said "active A, pending -"

# repair takes the store's lock: while an install holds it, busy.
make_unit; flip "$unit/state"
exec 9<"$unit/lock"
flock 9
fl repair; check "repair while an install holds the lock: busy" both 5 "busy"
exec 9<&-
check "busy: the damaged copy is still there" bash -c "! cmp -s '$unit/state' '$unit/state.copy'"

# A state lost beside the slots (both copies removed) is not an empty store.
make_unit; rm -f "$unit/state" "$unit/state.copy"
fl boot-check
check "no state beside slots: said" both 0 "no state file beside the slot files"
# An empty store is still an empty store.
rm -rf "$unit" && mkdir -p "$unit"
fl boot-check; check "an empty store: no slot" both 6 "^boot: no valid slot"

# A slot file whose signed name holds an escape sequence (put there by
# hand, never signed by the owner): refused for it, and status, repair and
# the boot print no control byte of it.
no_controls() { ! LC_ALL=C grep -q "$(printf '[\001-\010\013-\037\177]')" "$work/out"; }
make_unit; rm -f "$unit/state" "$unit/state.copy"
python3 -c "import sys; p=sys.argv[1]; b=open(p,'rb').read(); i=b.index(b'spoon-1\0')
open(p,'wb').write(b[:i] + b'sp\x1b[2Jn' + b[i+7:])" "$unit/slot-a.swpack"
fl status
check "escape in a slot's name: status says why" \
  said "^slot A file: .*slot-a.swpack: SIGNATURE.name: a control byte \(0x1b\) at byte 2"
check "escape in a slot's name: status prints no control byte" no_controls
fl repair
check "escape in a slot's name: repair leaves A empty" said "repair: slot A: .*a control byte"
check "escape in a slot's name: repair prints no control byte" no_controls
rm -f "$unit/state" "$unit/state.copy"
boot
check "escape in a slot's name: the boot starts B" both 0 "starting slot B \('cup-2' version 2\)"
check "escape in a slot's name: the boot prints no control byte" no_controls

# A unit on trial walks its pending slot mapped (a file only root can
# write); an install meanwhile replaces that slot: the walk's bytes stay as
# they were (the install writes a new file), and the slot holds the new pack.
make_unit
rm -f "$work/mapped"*
python3 - "$unit/slot-b.swpack" "$work/mapped" <<'PYEOF2' &
import mmap, os, sys, time
f = open(sys.argv[1], 'rb')
m = mmap.mmap(f.fileno(), 0, prot=mmap.PROT_READ)
before = bytes(m)
open(sys.argv[2] + '.ready', 'w').close()
for _ in range(3000):
    if os.path.exists(sys.argv[2] + '.go'):
        break
    time.sleep(0.01)
same = bytes(m) == before
open(sys.argv[2], 'w').write('same' if same else 'changed')
PYEOF2
mapper=$!
for _ in $(seq 300); do [ -e "$work/mapped.ready" ] && break; sleep 0.01; done
fl install "$fixture/old.swpack"
check "an install over the walked slot: it installs" rc 0
touch "$work/mapped.go"; wait "$mapper"
check "an install over the walked slot: the walk's mapped bytes unchanged" \
  grep -qx same "$work/mapped"
check "an install over the walked slot: the slot holds the new pack" cmp -s "$fixture/old.swpack" "$unit/slot-b.swpack"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
