#!/usr/bin/env bash
# The first command to run: installs what is missing (when root; otherwise it
# says what to install), builds the library, the `ssda` tool and ssda-demo in
# build/demo (Release), and runs the demo. Its pictures land in
# ./ssda-demo-out/ of the project folder.
# Usage: tools/demo.sh [ssda-demo arguments, e.g. FIRST.png SECOND.png SOUND.wav]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)
build=build/demo

bash tools/setup-deps.sh

echo "==> building the library, ssda and ssda-demo in $build" >&2
mkdir -p "$build"
if ! cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSSDA_BUILD_TESTS=OFF \
       -DSSDA_BUILD_BENCH=OFF >"$build/configure.log" 2>&1; then
  cat "$build/configure.log" >&2
  echo "tools/demo.sh: configuring failed (log above)" >&2
  exit 1
fi
if ! cmake --build "$build" -j "$jobs" --target ssda_cli ssda_demo >"$build/build.log" 2>&1; then
  cat "$build/build.log" >&2
  echo "tools/demo.sh: building failed (log above)" >&2
  exit 1
fi

exec "$build/host_demo/ssda-demo" "$@"
