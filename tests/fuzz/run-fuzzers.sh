#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan+UBSan, the whole tree
# coverage-instrumented) and runs each for SECONDS (default 30), as many at
# once as there are cores, starting from a copy of its seed corpus so the
# repository's seeds stay as they are.
# A crash leaves its input in build-fuzz/crashes/ and fails the script.
#   bash tests/fuzz/run-fuzzers.sh [SECONDS] [TARGET...]
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"
bash cmake/install-deps.sh
# New build folders use Ninja (an existing folder keeps its generator): a
# fresh Release build took 61 s against make's 95 s on two cores.
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
seconds=${1:-30}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_pack fuzz_newell fuzz_bpt fuzz_scene fuzz_camera_path fuzz_iges fuzz_store fuzz_keys fuzz_config)

CC=clang CXX=clang++ cmake -S . -B build-fuzz -DSW_FUZZ=ON -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build build-fuzz -j"$(nproc 2>/dev/null || echo 2)" --target "${targets[@]}"

# As many fuzzers at once as there are cores (a libFuzzer run is one process
# on one core); each writes its own log, printed when it ends; a crash fails
# the script.
mkdir -p build-fuzz/crashes build-fuzz/logs
fuzz_one() {  # fuzz_one TARGET
  local t=$1 seeds=tests/fuzz/corpus/${1#fuzz_} work=build-fuzz/corpus/$1
  rm -rf "$work" && mkdir -p "$work" && cp -r "$seeds"/. "$work"/
  build-fuzz/tests/"$t" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix=build-fuzz/crashes/"$t"- "$work" > build-fuzz/logs/"$t".log 2>&1
}
jobs=$(nproc 2>/dev/null || echo 2)
failed=() running=()
report() {  # report INDEX: waits for running[INDEX], prints its log's tail
  local t=${running[$1]}
  wait "${pids[$1]}" || failed+=("$t")
  echo "fuzzed $t for ${seconds}s"
  tail -n 12 build-fuzz/logs/"$t".log
}
pids=()
for t in "${targets[@]}"; do
  if [ ${#running[@]} -ge "$jobs" ]; then
    report 0
    running=("${running[@]:1}") pids=("${pids[@]:1}")
  fi
  fuzz_one "$t" & pids+=($!) running+=("$t")
done
for i in "${!running[@]}"; do report "$i"; done
[ ${#failed[@]} -eq 0 ] || { echo "fuzzers that failed: ${failed[*]} (inputs in build-fuzz/crashes/)"; exit 1; }
echo "fuzzers ran without a crash"
