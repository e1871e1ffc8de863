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
. "$(dirname "$0")/bench_lib.sh"
cd "$root"
dir=${SSDA_BENCH_DIR:-build/bench}

bash tools/setup-deps.sh >&2
bench_build "$dir" OFF ssda-bench-stream

bench_pair_args "$@"
shift "$pair_shift"
if [ ${#pair_args[@]} -eq 0 ]; then
  echo "bench-stream: give FIRST.png SECOND.png (no GOES-16 pair in $root/../shared/data/goes16)" >&2
  exit 2
fi
[ "${1:-}" = "--" ] && shift
exec "$dir/tools/bench/stream/ssda-bench-stream" "${pair_args[@]}" "$@"
