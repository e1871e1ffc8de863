#!/usr/bin/env bash
# Issue 20's measurements in one command (a benchmark, not a test): builds
# `ssda` and ssda-bench-segment (Release) and prints, side by side in one run:
#   1. parameter errors of EM and the seed's search on sampled mixtures with
#      known parameters (tools/bench/seg_bench.c);
#   2. on real images, the log-likelihood of our EM fit against scikit-learn's
#      GaussianMixture on the pixels with the same K, and the time of each
#      (one thread); on scenes with known regions, the adjusted Rand index of
#      our labels, GaussianMixture, multi-Otsu and k-means
#      (tools/bench/seg_compare.py, /usr/bin/python3 with numpy, scikit-learn,
#      scikit-image).
#   tools/bench-segment.sh [--reps R] [IMAGE:NODATA:K1,K2,K3 ...]
# Without images it uses the data folder given as SSDA_DATA (default
# ../shared/data beside the repository, found from this script's folder
# wherever it is run from) when present: the Landsat scene
# (nodata 0; the seed's 6, 5, 4 components), the graffiti wall img1 (RGB,
# 6, 5, 4), camera and moon (gray, 4 and 3),
# and band 3 of the MicaSense capture (16-bit gray, 4). Data is read where it
# is, never copied. Relative IMAGE and SSDA_DATA paths are taken from the
# folder it is run in. SSDA_BENCH_DIR sets the build directory (default
# build/bench-segment, in the repository).
set -euo pipefail
. "$(dirname "$0")/bench_lib.sh"
cd "$root"
dir=${SSDA_BENCH_DIR:-build/bench-segment}
reps=5
if [ "${1:-}" = "--reps" ]; then reps=$2; shift 2; fi

bash tools/setup-deps.sh python3-numpy python3-sklearn python3-skimage >&2
bench_build "$dir" ON ssda_cli ssda-bench-segment

images=()
for spec in "$@"; do # PATH:NODATA:K1,K2: only PATH is a path
  path=${spec%%:*}
  images+=("$(from_caller "$path")${spec#"$path"}")
done
data=$root/../shared/data
[ -n "${SSDA_DATA:-}" ] && data=$(from_caller "$SSDA_DATA")
if [ ${#images[@]} -eq 0 ] && [ -d "$data" ]; then
  for spec in "aerial/RGB.byte.png:0:6,5,4" "homography/graf/img1.png::6,5,4" \
              "classic/camera.png::4" "classic/moon.png::3" \
              "multiband/IMG_0001_3.png::4"; do
    [ -f "$data/${spec%%:*}" ] && images+=("$data/$spec")
  done
fi
args=()
for i in "${images[@]}"; do args+=(--image "$i"); done

# one thread everywhere: numpy's BLAS, OpenMP in scikit-learn
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1
echo "## ssda segment: measurements ($(date -u +%F), $(uname -m), load average $(cut -d' ' -f1-3 /proc/loadavg))"
echo
echo "    tools/bench-segment.sh --reps $reps ${images[*]:-}"
echo
"$dir/tools/bench/ssda-bench-segment" --reps "$reps"
echo
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 tools/bench/seg_compare.py "$dir/tools/cli/ssda" "$work" --reps "$reps" "${args[@]}"
echo
echo "(load average after: $(cut -d' ' -f1-3 /proc/loadavg))"
