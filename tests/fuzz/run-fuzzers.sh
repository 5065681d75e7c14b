#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan+UBSan, the whole tree
# coverage-instrumented) and runs each for SECONDS (default 30), starting from
# a copy of its seed corpus so the repository's seeds stay as they are.
# A crash leaves its input in build-fuzz/crashes/ and fails the script.
#   bash tests/fuzz/run-fuzzers.sh [SECONDS] [TARGET...]
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"
bash cmake/install-deps.sh
seconds=${1:-30}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_pack fuzz_newell fuzz_bpt fuzz_scene fuzz_camera_path fuzz_iges fuzz_store fuzz_keys fuzz_config)

CC=clang CXX=clang++ cmake -S . -B build-fuzz -DSW_FUZZ=ON -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build build-fuzz -j"$(nproc 2>/dev/null || echo 2)" --target "${targets[@]}"

mkdir -p build-fuzz/crashes
for t in "${targets[@]}"; do
  seeds=tests/fuzz/corpus/${t#fuzz_}
  work=build-fuzz/corpus/$t
  rm -rf "$work" && mkdir -p "$work" && cp -r "$seeds"/. "$work"/
  echo "fuzzing $t for ${seconds}s"
  build-fuzz/tests/"$t" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix=build-fuzz/crashes/"$t"- "$work" 2>&1 | tail -n 12
done
echo "fuzzers ran without a crash"
