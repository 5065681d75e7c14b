#!/usr/bin/env bash
# CI's thread step: builds with ThreadSanitizer (cmake -DSW_TSAN=ON) the
# programs the threaded tests need and runs those tests: the lock-free
# primitives (test_steal_queue, test_handoff), the threaded walk end to
# end (walk_threads: stalled, slow and starved workers, two workers, the
# visibility thread on and off, --sync-work), and three walks of the suite
# whose frames all run through the visibility thread and the workers in
# lockstep (walk_teaset, seam_drawn_walk, walk_input_timeline: the kiosk's
# input step feeding V), so every hand-over between the GL thread, V and
# the workers runs instrumented. A report fails the test (TSan exits 66).
# About six minutes on two cores. Not the whole suite: it would add about
# half an hour to CI; the rest runs under ASan+UBSan (walk_golden,
# walk_seams, walk_config and walk_errors passed under TSan by hand, with
# no report; soak_short cannot walk two loops in 20 s under TSan).
#   run-tsan.sh [BUILD_DIR]   (default build-tsan)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-tsan}
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSW_TSAN=ON -DSW_WERROR=ON >/dev/null
cmake --build "$dir" -j"$jobs" --target seamwalk seamwalk-pack image_compare test_steal_queue \
  test_handoff
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$PWD/tests/tsan.supp"
ctest --test-dir "$dir" --output-on-failure -j"$jobs" \
  -R '^(test_steal_queue|test_handoff|walk_threads|walk_teaset|seam_drawn_walk|walk_input_timeline)$'
