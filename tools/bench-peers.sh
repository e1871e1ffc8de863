#!/usr/bin/env bash
# Issue 7 in one command: ssda side by side with what a user would pick
# instead (OpenCV cv::matchTemplate, aubio yin/yinfast), same inputs, same
# process run, single thread. See docs/benchmarks.md.
#   tools/bench-peers.sh [-o DIR] [--quick] [--reps N]
# Installs what is missing from Debian (libopencv-dev, libaubio-dev, g++;
# as root), builds build/peers (Release), runs ssda-peers-match and
# ssda-peers-pitch on synthetic inputs plus the shared data when present
# (../shared/data, or SSDA_DATA_DIR: the GOES-16 pair with its fill value
# 4095 masked, classic/camera.png, the pitch recordings), and writes to DIR
# (default build/peers/results):
#   benchmarks.md  the Markdown tables (also printed at the end)
#   ratios.png     chart of the speed ratios (peer time / ssda time)
#   ratios.tsv     the ratios behind the chart
# --quick: 3 repetitions, fewer sizes and songs (a smoke run, about a minute).
# SSDA_PEERS_DIR sets the build directory.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
dir=${SSDA_PEERS_DIR:-build/peers}
data=${SSDA_DATA_DIR:-$root/../shared/data}
out=$dir/results
quick=()
reps=()
while [ $# -gt 0 ]; do
  case $1 in
    -o) out=$2; shift 2 ;;
    --quick) quick=(--quick); shift ;;
    --reps) reps=(--reps "$2"); shift 2 ;;
    *) echo "usage: $0 [-o DIR] [--quick] [--reps N]" >&2; exit 2 ;;
  esac
done

bash tools/setup-deps.sh g++ libopencv-dev libaubio-dev >&2
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DSSDA_BUILD_TESTS=OFF \
      -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=ON >&2
cmake --build "$dir" --target ssda-peers-match ssda-peers-pitch ssda-peers-chart \
      -j "$(nproc 2>/dev/null || echo 2)" >&2
bin=$dir/tools/bench/peers

match_args=()
goes=$data/goes16
if [ -f "$goes/goes16_c10_20221002_110117.png" ] && [ -f "$goes/goes16_c10_20221002_110617.png" ]; then
  match_args+=(--pair "$goes/goes16_c10_20221002_110117.png" "$goes/goes16_c10_20221002_110617.png"
               --pair-name "GOES-16" --mask 4095)
fi
[ -f "$data/classic/camera.png" ] && match_args+=(--image "$data/classic/camera.png")
pitch_args=()
for wav in "$data"/pitch/*.wav; do
  [ -f "$wav" ] || continue
  for ref in "${wav%.wav}.csv" "${wav%.wav}_f0.csv"; do
    if [ -f "$ref" ]; then pitch_args+=("$wav=$ref"); break; fi
  done
done

mkdir -p "$out"
tmp=$(mktemp -d "$out/.run.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
load_start=$(cut -d' ' -f1-3 /proc/loadavg)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- lib include 2>/dev/null || commit="$commit with uncommitted changes in lib/ or include/"
{
  echo "# ssda side by side with its peers"
  echo
  echo "Command: \`$(echo tools/bench-peers.sh ${quick[*]} ${reps[*]})\` ($(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit)."
  echo "Host: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores, $(${CC:-cc} --version | head -1);"
  echo "every measurement single-threaded. Load average (1/5/15 min) at the start: $load_start."
} > "$tmp/head.md"
"$bin/ssda-peers-match" "${quick[@]}" "${reps[@]}" --ratios "$tmp/match.tsv" "${match_args[@]}" > "$tmp/match.md"
"$bin/ssda-peers-pitch" "${quick[@]}" "${reps[@]}" --ratios "$tmp/pitch.tsv" "${pitch_args[@]}" > "$tmp/pitch.md"
echo "Load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)." >> "$tmp/head.md"

cat "$tmp/head.md" <(echo) "$tmp/match.md" <(echo) "$tmp/pitch.md" > "$tmp/benchmarks.md"
cat "$tmp/match.tsv" "$tmp/pitch.tsv" > "$tmp/ratios.tsv"
"$bin/ssda-peers-chart" "$tmp/ratios.png" \
    --subtitle "right of 1: ssda faster, left of 1: the peer faster (log scale); $(nproc)-core host, single thread, medians" \
    "$tmp/ratios.tsv"
mv "$tmp/benchmarks.md" "$tmp/ratios.tsv" "$tmp/ratios.png" "$out/"
cat "$out/benchmarks.md"
echo >&2
echo "bench-peers: results in $out/ (benchmarks.md, ratios.png, ratios.tsv)" >&2
