#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# seamwalk runs itself again once with glibc's heap on huge pages
# (sw_heap_huge_pages, firmware/program/sw_heap.h), seen from outside: where the
# kernel's THP mode is "madvise", the running walk's [heap] mapping carries
# the huge-page advice (VmFlags "hg" in /proc/PID/smaps), also when other
# tunables are set; where it is not, there is none to give; with
# GLIBC_TUNABLES=glibc.malloc.hugetlb=0 (the opt-out) there is none. The
# start still counts from the first run (first_frame_ms is a figure, not
# negative, under a minute). The environment itself is no witness: glibc
# rewrites GLIBC_TUNABLES in place as it reads it.
#   test_huge_heap.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
build=$1 src=$2
walker=$build/firmware/seamwalk pid=""
work=$(mktemp -d "${TMPDIR:-/tmp}/sw_huge.XXXXXX") || exit 1
trap '[ -n "$pid" ] && kill "$pid" 2>/dev/null; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
pack=$work/teaset.swpack
"$build/assets/seamwalk-pack" build "$src/assets/samples/teaset.ini" -o "$pack" --quiet ||
  fail "the teaset's pack"

# advised TUNABLES: "hg" when the walk's [heap] is advised for huge pages,
# "4k" when not, once the walk has drawn a frame (its pose log's first row).
advised() {
  rm -f "$work/poses"
  GLIBC_TUNABLES=$1 "$walker" --pack "$pack" --headless 64x48 --frames 100000 --navigate \
    --pose-log "$work/poses" --stats "$work/stats.json" > "$work/out" 2>&1 &
  pid=$!
  for _ in $(seq 600); do
    grep -q '^[0-9]' "$work/poses" 2>/dev/null && break
    kill -0 "$pid" 2>/dev/null || fail "the walk ended: $(cat "$work/out")"
    sleep 0.1
  done
  local flags
  flags=$(awk '/\[heap\]/ { h = 1 } h && /^VmFlags:/ { print; exit }' "/proc/$pid/smaps")
  [ -n "$flags" ] || fail "no [heap] mapping in /proc/$pid/smaps"
  case " $flags " in *" hg "*) echo hg ;; *) echo 4k ;; esac
  kill -TERM "$pid"
  wait "$pid" || fail "the walk failed: $(cat "$work/out")"
}

want=4k
grep -q '\[madvise\]' /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null && want=hg
got=$(advised "")
[ "$got" = "$want" ] || fail "the heap is '$got', expected '$want'"
echo "ok   the walk's heap: $got (THP: $(cat /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null))"
python3 - "$work/stats.json" <<'PY' || fail "first_frame_ms"
import json, sys
ms = json.load(open(sys.argv[1]))["first_frame_ms"]
assert 0 <= ms < 60000, ms
print("ok   first_frame_ms %.1f, counted from the first run" % ms)
PY
got=$(advised "glibc.malloc.mmap_threshold=131072")
[ "$got" = "$want" ] || fail "with another tunable set the heap is '$got', expected '$want'"
echo "ok   with another tunable set: $got"
got=$(advised "glibc.malloc.hugetlb=0")
[ "$got" = 4k ] || fail "the opt-out's heap is '$got'"
echo "ok   GLIBC_TUNABLES=glibc.malloc.hugetlb=0 keeps 4 KiB pages"
