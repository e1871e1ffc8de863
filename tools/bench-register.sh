#!/usr/bin/env bash
# The issue-17 benchmark in one command: builds `ssda` and ssda-bench-warp
# (Release) in build/bench, then prints
#   1. registration side by side (tools/bench/register/bench_register.py):
#      ssda register against OpenCV findTransformECC (affine, homography),
#      ORB + estimateAffine2D and GDAL gdalwarp -order N on ssda's points,
#      mapping error against known warps, the graffiti homographies and the
#      multiband bands (vs ECC, with a round trip), CPU time;
#   2. the streamed warp of a 20 000 x 2 000 px image in a 32 KB budget
#      against the same warp in RAM (ssda-bench-warp).
#   tools/bench-register.sh [DATA_DIR] [-- bench_register.py options, e.g. --reps 5]
# DATA_DIR defaults to ../shared/data (classic/, homography/graf/, multiband/).
# Needs /usr/bin/python3 with numpy and cv2 (python3-opencv), gdal-bin.
set -euo pipefail
. "$(dirname "$0")/bench_lib.sh"
cd "$root"
dir=${SSDA_BENCH_DIR:-build/bench}
data=$root/../shared/data
if [ $# -ge 1 ] && [ "$1" != "--" ]; then data=$(from_caller "$1"); shift; fi
[ "${1:-}" = "--" ] && shift

bash tools/setup-deps.sh python3-opencv python3-numpy gdal-bin >&2
bench_build "$dir" ON ssda_cli ssda-bench-warp

echo "## Registration (tools/bench-register.sh, $(date -u +%Y-%m-%d), $(nproc) cores)"
echo
/usr/bin/python3 tools/bench/register/bench_register.py --ssda "$dir/tools/cli/ssda" --data "$data" "$@"
echo
echo "## Streamed warp, 20 000 x 2 000 px in 32 KB"
echo
"$dir/tools/bench/register/ssda-bench-warp" --reps 3
"$dir/tools/bench/register/ssda-bench-warp" --reps 3 --resample bilinear --order 3
