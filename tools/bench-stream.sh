#!/usr/bin/env bash
# The issue-3 benchmark in one command: installs what is missing, builds
# ssda-bench-stream (Release), runs it and prints a Markdown table:
# grid tracking (16x16 windows, 32x32 areas, step 16) from file-backed
# streamed sources in 4, 16 and 64 KB arenas against the same job in RAM.
#   tools/bench-stream.sh [FIRST.png SECOND.png] [-- extra ssda-bench-stream options]
# Without files it uses the GOES-16 pair in ../shared/data/goes16/ (fill
# value 4095 masked). Extra options: --reps N, --arenas 4K,16K,64K,
# --tile WxH, --read-size N, --predict none|left|median, --no-bounds, --tmpdir DIR.
# SSDA_BENCH_DIR sets the build directory (default build/bench).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
dir=${SSDA_BENCH_DIR:-build/bench}

bash tools/setup-deps.sh >&2
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DSSDA_BUILD_TESTS=OFF \
      -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=ON >&2
cmake --build "$dir" --target ssda-bench-stream -j "$(nproc 2>/dev/null || echo 2)" >&2

args=()
if [ $# -ge 2 ] && [ "$1" != "--" ]; then
  args=(--mask 4095 "$1" "$2"); shift 2
else
  goes=$root/../shared/data/goes16
  if [ -f "$goes/goes16_c10_20221002_110117.png" ] && [ -f "$goes/goes16_c10_20221002_110617.png" ]; then
    args=(--mask 4095 "$goes/goes16_c10_20221002_110117.png" "$goes/goes16_c10_20221002_110617.png")
  else
    echo "bench-stream: give FIRST.png SECOND.png (no GOES-16 pair in $goes)" >&2
    exit 2
  fi
fi
[ "${1:-}" = "--" ] && shift
exec "$dir/tools/bench/stream/ssda-bench-stream" "${args[@]}" "$@"
