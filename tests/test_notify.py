#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""seamwalk's notifications to systemd (firmware/program/sw_notify.h, issue 25), read
from a NOTIFY_SOCKET this test binds itself, as systemd would for a
Type=notify unit: READY=1 exactly once, and only once the first frame is on
the display (its PNG, written before the frame is presented, exists when
READY=1 arrives); WATCHDOG=1 from the frame loop every quarter of WATCHDOG_USEC
while it walks, and none without WATCHDOG_USEC; STATUS= says
what runs before READY=1.
  test_notify.py SEAMWALK SEAMWALK_PACK SAMPLES WORK"""
import os, shutil, socket, subprocess, sys, time

walker, packer, samples, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
pack = os.path.join(work, 'spoon.swpack')
subprocess.run([packer, 'build', os.path.join(samples, 'teaspoon.txt'), '-o', pack, '--quiet'],
               check=True)
failures = checks = 0


def check(what, ok):
    global failures, checks
    checks += 1
    if not ok:
        failures += 1
        print('FAIL:', what)


def run(name, watchdog_us, duration_s):
    """One walk under a socket of our own: [(time, message, first PNG there)]."""
    path = os.path.join(work, name + '.sock')
    png = os.path.join(work, name + '-png')
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
    sock.bind(path)
    sock.settimeout(0.05)
    env = dict(os.environ, NOTIFY_SOCKET=path)
    env.pop('WATCHDOG_PID', None)
    env.pop('WATCHDOG_USEC', None)
    if watchdog_us:
        env['WATCHDOG_USEC'] = str(watchdog_us)
    # --frames 100000: no loop of frames ends within the walk, so the one-off
    # step after the first loop (the heap made resident, 120 MB and more
    # touched: 0.4-0.8 s on a loaded machine, well within a real
    # WatchdogSec=30s) is not in the 0.4 s watchdog this test holds the
    # frame loop to.
    proc = subprocess.Popen([walker, '--pack', pack, '--headless', '160x120', '--orbit',
                             '--frames', '100000', '--duration', str(duration_s), '--png-dir', png,
                             '--png-every', '1000000'], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    got, t0 = [], time.monotonic()
    while True:
        try:
            msg = sock.recv(4096).decode()
            got.append((time.monotonic() - t0, msg,
                        os.path.exists(os.path.join(png, 'frame_00000.png'))))
        except socket.timeout:
            if proc.poll() is not None:
                break
    err = proc.stderr.read().decode()
    sock.close()
    check(f'{name}: seamwalk exits 0 ({err.strip()[-300:]})', proc.returncode == 0)
    return got


# With a watchdog of 0.4 s: a ping every 0.1 s of a 1.5 s walk.
got = run('watchdog', 400000, 1.5)
msgs = [m for _, m, _ in got]
ready = [i for i, m in enumerate(msgs) if 'READY=1' in m.split('\n')]
check('READY=1 exactly once', len(ready) == 1)
if ready:
    check('READY=1 only once the first frame was shown', got[ready[0]][2])
    status = [m for m in msgs[:ready[0]] if m.startswith('STATUS=walking')]
    check('STATUS= says what walks before READY=1', len(status) == 1)
    if status:
        print('status:', status[0])
pings = [t for t, m, _ in got if 'WATCHDOG=1' in m.split('\n')]
gaps = [b - a for a, b in zip(pings, pings[1:])]
print(f'{len(pings)} WATCHDOG=1 in a 1.5 s walk, largest gap {max(gaps, default=0):.3f} s')
check('WATCHDOG=1 from the frame loop (at least 7 in 1.5 s)', len(pings) >= 7)
check('WATCHDOG=1 never more than WatchdogSec (0.4 s) apart', all(g < 0.4 for g in gaps))
check('not a ping per frame: one a quarter of WatchdogSec', all(g > 0.08 for g in gaps))

got = run('no-watchdog', 0, 0.5)
msgs = [m for _, m, _ in got]
check('without WATCHDOG_USEC: READY=1, no WATCHDOG=1',
      sum('READY=1' in m for m in msgs) == 1 and not any('WATCHDOG=1' in m for m in msgs))

print(f'{checks} checks, {failures} failed')
sys.exit(1 if failures else 0)
