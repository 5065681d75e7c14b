#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# seamwalk-flash from the command line: refusals (unsigned, wrong key, a
# flipped byte anywhere, truncated, older) change nothing on the unit; I/O
# faults (failing write, fsync, rename, ftruncate; a full disk) leave the old
# pack active and say why; and the whole flow: install, status, mark-good,
# rollback, standard input, the lock.
#   test_flash_cli.sh SEAMWALK_FLASH FAULT_SHIM FIXTURE WORK
set -uo pipefail
if [ "$(id -u)" != 0 ]; then  # the unit's trusted keys must be root's (firmware/store/STORE.md)
  echo "skipped: needs root, for trusted keys owned by root"
  exit 77
fi
flash=$1 shim=$2 fixture=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
unit=$work/unit
failures=0 checks=0
check() {  # check DESCRIPTION COMMAND...
  checks=$((checks + 1))
  if ! "${@:2}"; then echo "FAIL: $1"; failures=$((failures + 1)); fi
}
cfg=$fixture/unit.ini
fl() { "$flash" "$@" --store "$unit" --config "$cfg" >"$work/out" 2>&1; echo $? >"$work/rc"; }
rc() { [ "$(cat "$work/rc")" = "$1" ]; }
said() { grep -q -- "$1" "$work/out"; }
not_said() { ! grep -q -- "$1" "$work/out"; }
boots() {  # boots VERSION: boot-check starts that version, verified
  "$flash" boot-check --store "$unit" --config "$cfg" >"$work/boot" 2>&1 &&
    grep -q "' version $1 (.*verified" "$work/boot"
}
snapshot() { (cd "$unit" && cat state state.copy slot-*.swpack 2>/dev/null | cksum); }

# A unit with the old pack, good.
mkdir -p "$unit"
fl install "$fixture/old.swpack"; check "install old" rc 0
fl mark-good; check "mark-good old" rc 0
check "old boots" boots 1
before=$(snapshot)

# ---- refusals ----------------------------------------------------------------
refusals=0 refusal_trials=0
refuse() {  # refuse EXIT_CODE WORD PACK [ARGS...]
  refusal_trials=$((refusal_trials + 1))
  fl install "$3" "${@:4}"
  if rc "$1" && said "$2" && [ "$(snapshot)" = "$before" ] && boots 1 &&
     [ ! -e "$unit/journal" ]; then
    refusals=$((refusals + 1))
  else
    echo "FAIL: $3 was not refused with exit $1 and '$2', or the unit changed:"; cat "$work/out"
  fi
}
refuse 3 "not signed" "$fixture/unsigned.swpack"
refuse 3 "not among the 1 trusted keys" "$fixture/stranger.swpack"
refuse 4 "older than the active slot A's version 1" "$fixture/older.swpack"
refuse 1 "nokeys: No such file" "$fixture/new.swpack" --keys "$work/nokeys"
size=$(stat -c %s "$fixture/new.swpack")
# Flipped bytes: the first, the last and 40 spread over the file.
for i in $(seq 0 41); do
  at=$(( i == 0 ? 0 : i == 1 ? size - 1 : (i * 7919 * 131) % size ))
  cp "$fixture/new.swpack" "$work/flip.swpack"
  byte=$(od -An -tu1 -j "$at" -N1 "$work/flip.swpack" | tr -d ' ')
  printf "$(printf '\\%03o' $(( byte ^ 0x40 )))" |
    dd of="$work/flip.swpack" bs=1 seek="$at" conv=notrunc status=none
  refuse 3 "refused" "$work/flip.swpack"
done
for n in 0 1 63 64 1000 $((size / 2)) $((size - 160)) $((size - 1)); do
  head -c "$n" "$fixture/new.swpack" >"$work/cut.swpack"
  refuse 3 "refused" "$work/cut.swpack"
done
echo "refusals: $refusals of $refusal_trials bad packs refused, unit unchanged"
check "every bad pack refused" [ "$refusals" -eq "$refusal_trials" ]

# ---- I/O faults ----------------------------------------------------------------
faults=0 fault_trials=0
fault() {  # fault WHAT-IT-SAYS ENV=VALUE...
  fault_trials=$((fault_trials + 1))
  env LD_PRELOAD="$shim" ASAN_OPTIONS=verify_asan_link_order=0 "${@:2}" \
    "$flash" install --store "$unit" --config "$cfg" --chunk-kb 64 --quiet "$fixture/new.swpack" \
    >"$work/out" 2>&1
  local code=$?
  if [ "$code" = 1 ] && said "$1" && boots 1; then
    faults=$((faults + 1))
  else
    echo "FAIL: with $* the install exited $code or the unit would not boot the old pack:"
    cat "$work/out" "$work/boot"
  fi
  rm -rf "$unit/journal" "$unit"/slot-b.swpack   # each fault starts a fresh install
}
for n in 1 2 3 5 8 13; do fault "Input/output error" SW_FAULT_FAIL=write:$n; done
for n in 1 2 3 5 8 13 21; do fault "f.*sync.*Input/output error" SW_FAULT_FAIL=fsync:$n; done
for n in 1 2 3 5 8; do fault "rename.*Input/output error" SW_FAULT_FAIL=rename:$n; done
fault "ftruncate.*Input/output error" SW_FAULT_FAIL=ftruncate:1
for b in 0 100 50000 300000 $((size - 1)); do
  fault "No space left on device" SW_FAULT_FULL_AFTER=$b
done
echo "I/O faults: $faults of $fault_trials failed installs left the old pack active and said why"
check "every fault handled" [ "$faults" -eq "$fault_trials" ]

# ---- the flow --------------------------------------------------------------------
fl install - <"$fixture/new.swpack"; check "install from standard input" rc 0
check "no progress line on a pipe" not_said "writing slot"
check "it says where" said "installed 'cup-2' version 2 .* into slot B, verified"
fl status; check "status: pending B" said "pending: B (0 boots so far)"
check "status: slots verified" said "slot B: pending, 'cup-2' version 2, $size bytes, verified"
check "the new pack boots on trial" boots 2
fl mark-good; check "mark-good" rc 0
fl status; check "status: B active" said "active: B"
check "status: A still good" said "slot A: good, 'spoon-1' version 1"
fl rollback; check "rollback" rc 0
check "rollback says so" said "slot A ('spoon-1' version 1) is active again; slot B marked bad"
check "the old pack boots after rollback" boots 1
fl rollback; check "nothing more to roll back" rc 1
check "it says why" said "nothing to roll back to"
fl mark-good; check "mark-good with nothing pending fails" rc 1
fl install "$fixture/older.swpack" --allow-downgrade; check "--allow-downgrade" rc 0
check "the downgrade is pending" boots 0
fl rollback; check "a pending slot is dropped" said "dropped pending slot B"
exec 9>"$unit/lock"
flock 9
fl install "$fixture/new.swpack"; check "busy while locked" rc 5
check "busy says so" said "busy"
exec 9>&-
fl install "$fixture/new.swpack"; check "free again" rc 0
# On a terminal (script(1) gives it one): the progress line, then the result.
"$flash" rollback --store "$unit" --config "$cfg" >/dev/null
script -qec "'$flash' install --store '$unit' --config '$cfg' --chunk-kb 64 '$fixture/new.swpack'" /dev/null \
  >"$work/out" 2>&1
mib=$(python3 -c 'import os, sys; print("%.1f" % (os.path.getsize(sys.argv[1]) / 1048576))' \
  "$fixture/new.swpack")
check "progress on a terminal" said "writing slot B 100% ($mib of $mib MiB)"
check "and the result after it" said "installed 'cup-2' version 2"
printf 'garbage\n' >"$unit/state"
fl status; check "one damaged copy of the state: status goes on" rc 0
check "naming the file and line" said "state:1: expected seamwalk-store 1"
printf 'garbage\n' >"$unit/state.copy"
fl status; check "both copies damaged is an error" rc 1
check "naming each file and line" said "state.copy:1: expected seamwalk-store 1"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
