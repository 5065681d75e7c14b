#!/usr/bin/env bash
# CI's thread step: builds with ThreadSanitizer (cmake -DSW_TSAN=ON) the
# programs the threaded tests need and runs those tests: the lock-free
# primitives (test_steal_queue, test_handoff) and the threaded walk end to
# end (walk_threads: stalled workers, two workers, --sync-work), so every
# hand-over between the GL thread and the workers runs instrumented. A
# report fails the test (TSan exits 66). A few minutes on two cores; the
# rest of the suite is single-threaded and runs under ASan+UBSan.
#   run-tsan.sh [BUILD_DIR]   (default build-tsan)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-tsan}
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSW_TSAN=ON -DSW_WERROR=ON >/dev/null
cmake --build "$dir" -j"$jobs" --target seamwalk seamwalk-pack image_compare test_steal_queue \
  test_handoff
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$PWD/tests/tsan.supp"
ctest --test-dir "$dir" --output-on-failure -R '^(test_steal_queue|test_handoff|walk_threads)$'
