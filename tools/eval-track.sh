#!/usr/bin/env bash
# Issue 15's evaluation in one command: how far `ssda track`'s vectors can be
# trusted on pairs with known motion (synthetic scenes made by the tool:
# textures, radar-like echoes over an exact no-echo 0, clouds over clear sky,
# a brightness change, motion beyond the search range, 16-bit counts; and,
# when present, the real data in ../shared/data: photographs moved by a known
# flow, the aerial scene with its nodata region, the PIV pair against
# OpenPIV's field, the GOES-16 pair without truth, and scikit-image's
# Middlebury stereo pair with ground-truth disparity), beside OpenCV's
# Farneback flow and matchTemplate on the same windows. A benchmark, not a
# test: prints Markdown (docs/tracking.md quotes it).
#   tools/eval-track.sh [track_eval.py options]        e.g. --config 'whole=--no-subpixel'
#   tools/eval-track.sh --study [track_study.py options]  the data behind the defaults
# Installs what is missing from Debian (python3-numpy, python3-opencv; as
# root), builds build/eval (Release). SSDA_EVAL_DIR sets the build dir,
# SSDA_DATA_DIR the data directory.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
dir=${SSDA_EVAL_DIR:-build/eval}
data=${SSDA_DATA_DIR:-$root/../shared/data}
skdata=/usr/lib/python3/dist-packages/skimage/data

script=tools/eval/track_eval.py
if [ "${1:-}" = "--study" ]; then
  script=tools/eval/track_study.py
  shift
fi
bash tools/setup-deps.sh python3-numpy python3-opencv >&2
if [ "$script" = tools/eval/track_eval.py ]; then
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DSSDA_BUILD_TESTS=OFF \
        -DSSDA_BUILD_TOOLS=ON -DSSDA_BUILD_BENCH=OFF >&2
  cmake --build "$dir" --target ssda_cli -j "$(nproc 2>/dev/null || echo 2)" >&2
  set -- --ssda "$dir/tools/cli/ssda" "$@"
fi

args=()
have() { [ -f "$1" ]; }
if have "$data/classic/camera.png"; then args+=(--photo "camera=$data/classic/camera.png"); fi
if have "$data/classic/moon.png"; then args+=(--photo "moon=$data/classic/moon.png"); fi
if have "$data/aerial/RGB.byte.png"; then args+=(--nodata-photo "aerial=$data/aerial/RGB.byte.png:0"); fi
if have "$data/piv/B001_openpiv.txt"; then
  args+=(--piv "$data/piv/B001_1.png" "$data/piv/B001_2.png" "$data/piv/B001_openpiv.txt")
fi
if have "$skdata/motorcycle_disp.npz"; then args+=(--stereo "$skdata"); fi
if have "$data/goes16/goes16_c10_20221002_110117.png"; then
  args+=(--goes "$data/goes16/goes16_c10_20221002_110117.png" "$data/goes16/goes16_c10_20221002_110617.png")
fi
# /usr/bin/python3: Debian's numpy and OpenCV (a pyenv python3 on PATH has neither)
exec /usr/bin/python3 "$script" "${args[@]}" "$@"
