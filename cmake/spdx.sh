#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Puts the licence's SPDX line (LICENSE) into every tracked source file we own
# that lacks one: C, C++, CMake, shell and Python, after a #! line if there is
# one. Test data and corpora have none of those extensions and are left alone.
#   cmake/spdx.sh [--check] [PATHSPEC...]
# --check changes nothing and lists the files without the line (exit 1 if any).
# PATHSPECs (git's, e.g. ':!firmware/walk') narrow the files looked at.
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
if [ "${1:-}" = "--check" ]; then check=1; shift; fi
tag="SPDX-License-Identifier: MIT"
missing=0
while IFS= read -r f; do
  grep -q "SPDX-License-Identifier:" "$f" && continue
  missing=$((missing + 1))
  if [ $check = 1 ]; then echo "$f"; continue; fi
  case $f in
    *.c|*.h|*.cpp) line="/* $tag */" ;;
    *) line="# $tag" ;;
  esac
  if head -n 1 "$f" | grep -q '^#!'; then
    sed -i "1a $line" "$f"
  else
    sed -i "1i $line" "$f"
  fi
done < <(git ls-files -- '*.c' '*.h' '*.cpp' '*.cmake' '*CMakeLists.txt' '*.sh' '*.py' \
           .ci/run "$@" | sort -u)
[ $check = 0 ] || [ $missing = 0 ]
