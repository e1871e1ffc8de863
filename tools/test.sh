#!/usr/bin/env bash
# The project's test command (README, and CI through .ci/run).
# On a fresh machine it installs what is missing, then builds and runs every
# test: host build with -Werror, and a host build with ASan + UBSan.
# Usage: tools/test.sh            (build dirs under build/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)

bash tools/setup-deps.sh
unity=$(bash tools/fetch-unity.sh)

configure_build_test() { # <dir> <cmake args...>
  local dir=$1; shift
  echo "==> $dir" >&2
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSDA_WERROR=ON \
        -DFETCHCONTENT_SOURCE_DIR_UNITY="$unity" "$@" >/dev/null
  if ! cmake --build "$dir" -j "$jobs" >"$dir/build.log" 2>&1; then
    cat "$dir/build.log"; echo "tools/test.sh: build failed in $dir" >&2; exit 1
  fi
  ctest --test-dir "$dir" --output-on-failure -j "$jobs"
}

configure_build_test build/host
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ASAN_OPTIONS=detect_leaks=1 \
  configure_build_test build/asan -DSSDA_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug
echo "tools/test.sh: all test builds passed" >&2
