#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The .deb packages as a unit and a host would install them: cpack makes
# them from this build (cmake/SwPackage.cmake), dpkg-deb -x unpacks both
# into one staging root, and there the files are exactly where they belong,
# the control data is right (shlibdeps' Depends, the conffile, the
# maintainer scripts), the unit runs the installed seamwalk and passes
# systemd-analyze verify, the installed programs run, the sysusers.d file
# makes the user and every man page renders. Last, `cmake --install` with
# another prefix points the unit at that prefix.
#   test_package.sh BUILD_DIR SOURCE_DIR VERSION WORK
set -uo pipefail
build=$1 src=$2 version=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
failures=0 checks=0
check() {  # check DESCRIPTION COMMAND...: counts, and says FAIL (returning 1) when it fails
  checks=$((checks + 1))
  "${@:2}" && return 0
  echo "FAIL: $1"
  failures=$((failures + 1))
  return 1
}
same() { [ "$1" = "$2" ] || { printf '  got:      %s\n  expected: %s\n' "$1" "$2"; return 1; }; }
for tool in cpack dpkg-deb systemd-analyze systemd-sysusers man; do
  command -v $tool >/dev/null || { echo "FAIL: $tool is missing (cmake/install-deps.sh)"; exit 1; }
done

cpack --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; echo "FAIL: cpack"; exit 1; }
runtime=$work/seamwalk_${version}_$(dpkg --print-architecture).deb
host=$work/seamwalk-pack_${version}_$(dpkg --print-architecture).deb
for deb in "$runtime" "$host"; do
  [ -f "$deb" ] || { ls "$work"; echo "FAIL: no $deb"; exit 1; }
done

# ---- what each package holds: exactly these files -------------------------------------
files() { dpkg-deb -c "$1" | awk '$6 !~ /\/$/ {print $6}' | sort | tr '\n' ' '; }
check "seamwalk's files" same "$(files "$runtime")" "./etc/seamwalk/seamwalk.ini \
./usr/bin/seamwalk ./usr/bin/seamwalk-flash ./usr/lib/systemd/system/seamwalk.service \
./usr/lib/sysusers.d/seamwalk.conf ./usr/lib/udev/rules.d/70-seamwalk.rules \
./usr/share/doc/seamwalk/copyright ./usr/share/man/man1/seamwalk.1 \
./usr/share/man/man5/seamwalk.ini.5 ./usr/share/man/man8/seamwalk-flash.8 "
check "seamwalk-pack's files" same "$(files "$host")" "./usr/bin/seamwalk-pack \
./usr/share/doc/seamwalk-pack/copyright ./usr/share/man/man1/seamwalk-pack.1 "
owners() { dpkg-deb -c "$1" | awk '{print $2}' | sort -u; }
check "seamwalk: every file root's" same "$(owners "$runtime")" root/root
check "seamwalk-pack: every file root's" same "$(owners "$host")" root/root

# ---- control data ------------------------------------------------------------------------
depends=$(dpkg-deb -f "$runtime" Depends)
for lib in libc6 libegl1 libgles2 libsodium23 libinih1 libsystemd0 libevdev2; do
  check "seamwalk Depends on $lib (dpkg-shlibdeps)" grep -q "\b$lib\b" <<<"$depends"
done
check "seamwalk Depends on systemd-sysusers for its postinst" \
  grep -q "systemd | systemd-standalone-sysusers" <<<"$depends"
check "seamwalk-pack Depends on libc6 and libsodium23" \
  bash -c "dpkg-deb -f '$host' Depends | grep -q 'libc6.*libsodium23'"
check "seamwalk-pack does not Depend on the display libraries" \
  bash -c "! dpkg-deb -f '$host' Depends | grep -q 'libegl1\|libgbm1\|libhidapi'"
dpkg-deb -e "$runtime" "$work/control"
check "conffiles: the config, and only it" same "$(cat "$work/control/conffiles")" \
  "/etc/seamwalk/seamwalk.ini"
check "postinst runs systemd-sysusers" grep -q "^ *systemd-sysusers .*seamwalk.conf" \
  "$work/control/postinst"
for script in postinst postrm; do
  check "$script: executable, sh syntax" bash -c "[ -x '$work/control/$script' ] && sh -n '$work/control/$script'"
done

# ---- the installed tree ------------------------------------------------------------------
root=$work/root
dpkg-deb -x "$runtime" "$root" && dpkg-deb -x "$host" "$root" || { echo "FAIL: dpkg-deb -x"; exit 1; }
unit=$root/usr/lib/systemd/system/seamwalk.service
check "the unit runs the installed seamwalk with the installed config" \
  grep -q "^ExecStart=/usr/bin/seamwalk --config /etc/seamwalk/seamwalk.ini " "$unit"
check "the unit is the source's but for ExecStart" bash -c "diff <(grep -v '^ExecStart=' \
  '$src/firmware/dist/seamwalk.service') <(grep -v '^ExecStart=' '$unit')"
check "the config is the shipped example" cmp -s "$src/firmware/dist/seamwalk.ini" \
  "$root/etc/seamwalk/seamwalk.ini"
check "the udev rule is the source's" cmp -s "$src/firmware/dist/70-seamwalk.rules" \
  "$root/usr/lib/udev/rules.d/70-seamwalk.rules"
# verify with --root checks the unit where it is installed, ExecStart's
# /usr/bin/seamwalk included (it is looked up under the root); the units it
# pulls in (sysinit.target, multi-user.target, ...) are the host's, copied
# next to it since a staging root has no systemd of its own.
cp -rn /lib/systemd/system/. "$root/usr/lib/systemd/system/"
systemd-analyze verify --man=no --root="$root" seamwalk.service >"$work/verify" 2>&1
rc=$?
check "systemd-analyze verify --root: clean" bash -c "[ $rc = 0 ] && [ ! -s '$work/verify' ]" ||
  cat "$work/verify"
for p in seamwalk seamwalk-flash seamwalk-pack; do
  check "installed $p --version" same "$("$root/usr/bin/$p" --version 2>&1)" "$p $version"
done
systemd-sysusers --root="$root" --dry-run >"$work/sysusers" 2>&1
check "sysusers.d: makes the system user seamwalk" grep -q "Creating user 'seamwalk'" "$work/sysusers" ||
  cat "$work/sysusers"
pages=$(find "$root/usr/share/man" -type f | sort)
check "four man pages" same "$(printf '%s\n' "$pages" | grep -c .)" 4
for page in $pages; do
  MANWIDTH=80 man --warnings -l "$page" >"$work/page" 2>"$work/page.err"
  rc=$?
  check "man -l $(basename "$page"): renders, no warning" \
    bash -c "[ $rc = 0 ] && [ -s '$work/page' ] && [ ! -s '$work/page.err' ]" || cat "$work/page.err"
done

# ---- another prefix ----------------------------------------------------------------------
DESTDIR=$work/opt cmake --install "$build" --prefix /opt/sw --component runtime >/dev/null
check "--prefix /opt/sw: the unit runs /opt/sw/bin/seamwalk with /opt/sw/etc's config" \
  grep -q "^ExecStart=/opt/sw/bin/seamwalk --config /opt/sw/etc/seamwalk/seamwalk.ini " \
  "$work/opt/opt/sw/lib/systemd/system/seamwalk.service"
check "--prefix /opt/sw: both are there" test -x "$work/opt/opt/sw/bin/seamwalk" -a \
  -f "$work/opt/opt/sw/etc/seamwalk/seamwalk.ini"

echo "$checks checks, $failures failed"
[ "$failures" -eq 0 ]
