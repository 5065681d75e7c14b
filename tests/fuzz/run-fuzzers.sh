#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the libFuzzer targets with clang (ASan+UBSan, the whole tree
# coverage-instrumented, optimised: -O1 -g, asserts kept) and runs every
# target the build defines (build-fuzz/fuzz-targets.txt, written by
# tests/fuzz/fuzz.cmake), or those named, for SECONDS each (default 30), as
# many at once as there are cores (SW_FUZZ_JOBS). Each target runs with
# its dictionary (tests/fuzz/dict/) on a kept corpus: build-fuzz/corpus/NAME
# (SW_FUZZ_CORPUS=DIR for another place, e.g. a CI cache), never emptied,
# into which its repository seeds and the real model files of its formats
# (SW_FUZZ_MODELS, default ../shared/models; up to 256 kB each, copied
# there, never into the repository) are added, so each run starts where
# the last one ended. Caps: 25 s an input and 2 GB (the STEP target
# through OpenCASCADE: 60 s, 3 GB); an input past them is a finding.
# A crash, a timeout or an out-of-memory leaves its input in
# build-fuzz/crashes/ and fails the script. The last lines: executions
# per target.
#   bash tests/fuzz/run-fuzzers.sh [SECONDS] [TARGET...]
#   bash tests/fuzz/run-fuzzers.sh 300       # the 5-minute local run, every target
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"
bash cmake/install-deps.sh
# New build folders use Ninja (an existing folder keeps its generator): a
# fresh Release build took 61 s against make's 95 s on two cores.
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}
seconds=${1:-30}
shift || true
jobs=${SW_FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}
corpus_root=${SW_FUZZ_CORPUS:-$top/build-fuzz/corpus}
models=${SW_FUZZ_MODELS:-$top/../shared/models}

# -O1 -g without NDEBUG: the code's asserts stay, and an IGES input that
# took 70 s unoptimised runs at Release speed.
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DSW_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" >/dev/null
list=build-fuzz/fuzz-targets.txt
targets=("$@")
[ ${#targets[@]} -gt 0 ] || mapfile -t targets < <(awk '{print $1}' "$list")
for t in "${targets[@]}"; do
  grep -q "^$t " "$list" || { echo "run-fuzzers: no fuzz target $t in this build ($list)"; exit 2; }
done
cmake --build build-fuzz -j"$jobs" --target "${targets[@]}"

mkdir -p build-fuzz/crashes build-fuzz/logs
fuzz_one() {  # fuzz_one TARGET: its kept corpus grown, then fuzzed
  local t=$1 seeds dict exts
  read -r _ seeds dict exts < <(grep "^$t " "$list")
  local work=$corpus_root/$t
  mkdir -p "$work"
  cp -rn "$seeds"/. "$work"/
  if [ "$exts" != - ] && [ -d "$models" ]; then
    for ext in ${exts//,/ }; do
      find "$models" -maxdepth 1 -type f -iname "*.$ext" -size -257k -exec cp -n {} "$work"/ \;
    done
  fi
  local flags=(-max_total_time="$seconds" -print_final_stats=1 -timeout=25 -rss_limit_mb=2048
               -artifact_prefix=build-fuzz/crashes/"$t"-)
  [ "$dict" = - ] || flags+=(-dict="$dict")
  # OpenCASCADE: slower inputs, more memory, and singletons it never frees:
  # no leak check per input, and at exit its own allocations suppressed
  # (tests/occt-lsan.supp: without them the run ends in a leak report of
  # those singletons, and fails, however clean the inputs were).
  local lsan=${LSAN_OPTIONS:-}
  if [ "$t" = fuzz_step_occt ]; then
    flags+=(-timeout=60 -rss_limit_mb=3072 -detect_leaks=0)
    lsan="suppressions=$PWD/tests/occt-lsan.supp:print_suppressions=0${lsan:+:$lsan}"
  fi
  LSAN_OPTIONS=$lsan build-fuzz/tests/"$t" "${flags[@]}" "$work" >build-fuzz/logs/"$t".log 2>&1
}

failed=() running=() pids=()
report() {  # report INDEX: waits for running[INDEX], prints its log's tail
  local t=${running[$1]}
  local ok=1
  wait "${pids[$1]}" || { ok=0; failed+=("$t"); }
  echo "fuzzed $t for ${seconds}s"
  if [ $ok = 0 ]; then
    # What failed and where: the finding's first line and the top of its
    # stack, which the log's tail (the run's statistics) leaves out.
    grep -m1 -A24 -E '^==[0-9]+==.*(ERROR|WARNING)|^ALARM|^SUMMARY' build-fuzz/logs/"$t".log || true
    echo "  ..."
  fi
  tail -n 12 build-fuzz/logs/"$t".log
}
for t in "${targets[@]}"; do
  if [ ${#running[@]} -ge "$jobs" ]; then
    report 0
    running=("${running[@]:1}") pids=("${pids[@]:1}")
  fi
  fuzz_one "$t" & pids+=($!) running+=("$t")
done
for i in "${!running[@]}"; do report "$i"; done

echo "executions in ${seconds} s (corpus kept in $corpus_root):"
for t in "${targets[@]}"; do
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' build-fuzz/logs/"$t".log | tail -1)
  files=$(find "$corpus_root/$t" -type f | wc -l)
  printf '  %-22s %12s executions, corpus %s files\n' "$t" "${runs:-?}" "$files"
done
[ ${#failed[@]} -eq 0 ] || { echo "fuzzers that failed: ${failed[*]} (inputs in build-fuzz/crashes/)"; exit 1; }
echo "fuzzers ran without a crash"
