#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# CI's thread step: builds the tree with ThreadSanitizer (cmake -DSW_TSAN=ON)
# and runs under it every test that runs instrumented code (the
# Release-only sweeps are named in tests/firmware.cmake, with why). Every
# program that can start a thread is instrumented: the runtime (seamwalk:
# the loader, V and the workers), the lock-free primitives' tests and every
# test program linking the runtime. The host tool seamwalk-pack, the
# installer seamwalk-flash and the test programs that link only
# sw_core/sw_assets and start no thread are built without TSan
# (cmake/SwSanitizers.cmake, sw_without_tsan): TSan reports races between
# threads and has nothing to check in them (the host tool's own threads,
# the levels' workers, run instrumented in test_build_threads). The tests
# that run nothing else (label host_only, sw_host_only_test in
# tests/CMakeLists.txt) are left out: they would run the same
# uninstrumented code as the Release step. A report fails the test (TSan
# exits 66).
#   run-tsan.sh [--threaded] [BUILD_DIR]   (default build-tsan)
# --threaded runs only the threaded tests, a few minutes: the lock-free
# primitives (test_steal_queue, test_handoff), the threaded walk end to end
# (walk_threads: stalled, slow and starved workers, two workers, the
# visibility thread on and off, --sync-work), three walks whose frames
# all run through the visibility thread and the workers in lockstep
# (walk_teaset, seam_drawn_walk, walk_input_timeline), and the pack
# builder's levels made on four threads (build_threads_levels).
set -euo pipefail
cd "$(dirname "$0")/.."
# New build folders use Ninja, as in run-tests.sh.
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
threaded=0
[ "${1:-}" = "--threaded" ] && { threaded=1; shift; }
dir=${1:-build-tsan}
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSW_TSAN=ON -DSW_WERROR=ON >/dev/null
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$PWD/tests/tsan.supp"
if [ $threaded = 0 ]; then
  cmake --build "$dir" -j"$jobs"
  ctest --test-dir "$dir" --output-on-failure -j"$jobs" -LE host_only
  exit
fi
cmake --build "$dir" -j"$jobs" --target seamwalk seamwalk-pack image_compare test_steal_queue \
  test_handoff test_build_threads
ctest --test-dir "$dir" --output-on-failure -j"$jobs" \
  -R '^(test_steal_queue|test_handoff|walk_threads|walk_teaset|seam_drawn_walk|walk_input_timeline|build_threads_levels)$'
