#!/usr/bin/env bash
# Seed 001 (symbolic registration) side by side with OpenCV, one run:
# `ssda shape` vs cv2.matchShapes on silhouettes, `ssda symreg` vs ORB +
# estimateAffinePartial2D / estimateAffine2D (RANSAC) on pairs with known
# turns, scales and gains (tools/eval/symbolic_bench.py, docs/symbolic.md).
#   tools/bench-symbolic.sh [--quick] [-o FILE.md]
# Builds build/symbolic (Release). Real data from ../shared/data (or
# SSDA_DATA_DIR) when present: shapes/, classic/camera.png,
# aerial/RGB.byte.png, homography/graf/img1.png; the synthetic scene always.
# Needs /usr/bin/python3 with cv2 and numpy (python3-opencv, python3-numpy).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
dir=${SSDA_SYMBOLIC_DIR:-build/symbolic}
data=${SSDA_DATA_DIR:-$root/../shared/data}
args=()
out=$dir/symbolic.md
while [ $# -gt 0 ]; do
  case $1 in
    --quick) args+=(--quick); shift ;;
    -o) out=$2; shift 2 ;;
    *) echo "usage: $0 [--quick] [-o FILE.md]" >&2; exit 2 ;;
  esac
done
bash tools/setup-deps.sh python3-opencv python3-numpy >&2
unity=$(bash tools/fetch-unity.sh)
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DFETCHCONTENT_SOURCE_DIR_UNITY="$unity" >/dev/null
cmake --build "$dir" -j 2 --target ssda_cli ssda_cli_gen_symreg >"$dir.build.log" 2>&1 \
  || { cat "$dir.build.log" >&2; exit 1; }
[ -d "$data/shapes" ] && args+=(--shapes "$data/shapes")
[ -f "$data/classic/camera.png" ] && args+=(--scene "camera.png (classic, 512 x 512)=$data/classic/camera.png")
[ -f "$data/aerial/RGB.byte.png" ] && args+=(--scene "Landsat RGB.byte.png (aerial, luma)=$data/aerial/RGB.byte.png")
[ -f "$data/homography/graf/img1.png" ] && args+=(--scene "graffiti img1.png (luma)=$data/homography/graf/img1.png")
/usr/bin/python3 tools/eval/symbolic_bench.py --ssda "$dir/tools/cli/ssda" \
  --gen "$dir/tools/cli/tests/ssda_cli_gen_symreg" --out "$out" "${args[@]}"
echo "bench-symbolic.sh: tables in $out" >&2
