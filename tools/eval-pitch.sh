#!/usr/bin/env bash
# Issue 4's evaluation in one command: ssda's AMDF pitch (early exit, and
# with tracking) against aubio's yin and yinfast on the same frames, on a
# synthetic set with exact f0 and on recordings with reference f0. Prints
# Markdown tables: GPE, FPE, VDE, differences per voiced frame vs a full
# AMDF, processor time. Not a test. See docs/pitch.md.
#   tools/eval-pitch.sh [ssda-eval-pitch options] [audio[=ref.csv] ...]
# Without audio arguments it uses ../shared/data/pitch/*.wav (or
# $SSDA_DATA_DIR/pitch) when present, each with its .csv or _f0.csv.
# Installs what is missing from Debian (libaubio-dev for the YIN rows; as
# root) and builds build/eval (Release). SSDA_EVAL_DIR sets the build dir.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
dir=${SSDA_EVAL_DIR:-build/eval}
data=${SSDA_DATA_DIR:-$root/../shared/data}

bash tools/setup-deps.sh libaubio-dev >&2
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DSSDA_BUILD_TESTS=OFF \
      -DSSDA_BUILD_TOOLS=ON -DSSDA_BUILD_BENCH=OFF >&2
cmake --build "$dir" --target ssda-eval-pitch -j "$(nproc 2>/dev/null || echo 2)" >&2

have_audio=0
skip=0
for a in "$@"; do # an argument that is neither an option nor an option's value is audio
  if [ "$skip" -eq 1 ]; then skip=0; continue; fi
  case $a in
    --synth-notes|--synth-rate|--hop-ms|--f0-min|--f0-max|--frame|--chunk|--threshold|--voicing|--lowpass|--dump) skip=1 ;;
    -*) ;;
    *) have_audio=1 ;;
  esac
done
args=("$@")
if [ "$have_audio" -eq 0 ]; then
  for wav in "$data"/pitch/*.wav; do
    [ -f "$wav" ] || continue
    for ref in "${wav%.wav}.csv" "${wav%.wav}_f0.csv"; do
      if [ -f "$ref" ]; then args+=("$wav=$ref"); break; fi
    done
  done
fi
exec "$dir/tools/eval/ssda-eval-pitch" --per-file "${args[@]}"
