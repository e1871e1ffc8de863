# bench_lib.sh - sourced by the benchmark scripts (tools/bench-*.sh) before
# they enter the repository root:
#   . "$(dirname "$0")/bench_lib.sh"
# Defines root (the repository), caller (the folder the script was run in)
# and the helpers below.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
caller=$PWD

# A path given by the caller, made absolute (the scripts work from $root).
from_caller() { case $1 in /*) printf '%s' "$1" ;; *) printf '%s/%s' "$caller" "$1" ;; esac; }

# bench_build DIR TOOLS(ON|OFF) TARGET...: a Release build of the benchmarks.
bench_build() {
  local dir=$1 tools=$2
  shift 2
  cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DSSDA_BUILD_TESTS=OFF \
        -DSSDA_BUILD_TOOLS="$tools" -DSSDA_BUILD_BENCH=ON >&2
  cmake --build "$dir" --target "$@" -j "$(nproc 2>/dev/null || echo 2)" >&2
}

# bench_pair_args "$@": sets pair_args to --mask 4095 FIRST SECOND
# (FIRST and SECOND from the command line when given, made absolute; else
# the GOES-16 pair of ../shared/data/goes16 when it is there, else empty)
# and pair_shift to how many arguments were taken.
bench_pair_args() {
  local goes=$root/../shared/data/goes16
  pair_args=()
  pair_shift=0
  if [ $# -ge 2 ] && [ "$1" != "--" ]; then
    pair_args=(--mask 4095 "$(from_caller "$1")" "$(from_caller "$2")")
    pair_shift=2
  elif [ -f "$goes/goes16_c10_20221002_110117.png" ] &&
       [ -f "$goes/goes16_c10_20221002_110617.png" ]; then
    pair_args=(--mask 4095 "$goes/goes16_c10_20221002_110117.png"
               "$goes/goes16_c10_20221002_110617.png")
  fi
}
