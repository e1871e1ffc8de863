#!/usr/bin/env bash
# The issue-2 benchmark in one command: installs what is missing, builds
# ssda-bench-track (Release), runs it and prints a Markdown table.
#   tools/bench-track.sh [FIRST.png SECOND.png] [-- extra ssda-bench-track options]
# Without files it uses the GOES-16 pair in ../shared/data/goes16/ when that
# directory exists (fill value 4095 masked), and always adds a synthetic pair.
# SSDA_BENCH_DIR sets the build directory (default build/bench).
set -euo pipefail
. "$(dirname "$0")/bench_lib.sh"
cd "$root"
dir=${SSDA_BENCH_DIR:-build/bench}

bash tools/setup-deps.sh >&2
bench_build "$dir" OFF ssda-bench-track

bench_pair_args "$@"
shift "$pair_shift"
[ "${1:-}" = "--" ] && shift
exec "$dir/tools/bench/ssda-bench-track" "${pair_args[@]}" "$@"
