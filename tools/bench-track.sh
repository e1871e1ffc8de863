#!/usr/bin/env bash
# The issue-2 benchmark in one command: installs what is missing, builds
# ssda-bench-track (Release), runs it and prints a Markdown table.
#   tools/bench-track.sh [FIRST.png SECOND.png] [-- extra ssda-bench-track options]
# Without files it uses the GOES-16 pair in ../shared/data/goes16/ when that
# directory exists (fill value 4095 masked), and always adds a synthetic pair.
# SSDA_BENCH_DIR sets the build directory (default build/bench).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
dir=${SSDA_BENCH_DIR:-build/bench}

bash tools/setup-deps.sh >&2
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DSSDA_BUILD_TESTS=OFF \
      -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=ON >&2
cmake --build "$dir" --target ssda-bench-track -j "$(nproc 2>/dev/null || echo 2)" >&2

args=()
if [ $# -ge 2 ] && [ "$1" != "--" ]; then
  args=(--mask 4095 "$1" "$2"); shift 2
else
  goes=$root/../shared/data/goes16
  if [ -f "$goes/goes16_c10_20221002_110117.png" ] && [ -f "$goes/goes16_c10_20221002_110617.png" ]; then
    args=(--mask 4095 "$goes/goes16_c10_20221002_110117.png" "$goes/goes16_c10_20221002_110617.png")
  fi
fi
[ "${1:-}" = "--" ] && shift
exec "$dir/tools/bench/ssda-bench-track" "${args[@]}" "$@"
