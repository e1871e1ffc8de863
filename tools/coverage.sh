#!/usr/bin/env bash
# Line and branch coverage of lib/ (and include/ inline code) from the Unity
# tests, with gcov + lcov. Installs lcov if missing, builds the tests twice
# with gcc --coverage at -O0 (SSDA_COVERAGE=ON, cmake/SsdaCoverage.cmake):
#   portable  SSDA_KERNEL=portable   (the reference kernel, lib/kernel/kernel_portable.c)
#   sse2      SSDA_KERNEL=sse2       (the host's default kernel, lib/kernel/kernel_sse2.c;
#                                     x86 hosts only)
# runs CTest in each, merges the two tracefiles (the shared lib/*.c counts
# add up; each kernel file comes from its own build) and prints per-file and
# total figures. lib/kernel/kernel_armv7em.c cannot run on the host and is not
# in the figures: it is tested bit-identical to the portable kernel under
# QEMU (tools/test.sh, docs/target.md).
# The HTML report goes to <build dir>/html/index.html.
# Exits non-zero if the branch coverage of lib/ is below SSDA_COVERAGE_MIN_BRANCH
# (percent, default below).
# Usage: tools/coverage.sh [build dir]      (default build/coverage)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
out=${1:-build/coverage}
min_branch=${SSDA_COVERAGE_MIN_BRANCH:-95.0}
jobs=$(nproc 2>/dev/null || echo 2)
rc=(--rc lcov_branch_coverage=1)

bash tools/setup-deps.sh lcov
unity=$(bash tools/fetch-unity.sh)
mkdir -p "$out"
out=$(cd "$out" && pwd)

kernels=(portable)
if [[ $(${CC:-gcc} -dM -E -x c /dev/null) == *__SSE2__* ]]; then
  kernels+=(sse2)
else
  echo "coverage: no SSE2 on this host; lib/kernel/kernel_sse2.c not measured" >&2
fi

traces=()
for k in "${kernels[@]}"; do
  dir=$out/$k
  echo "==> coverage build $dir (SSDA_KERNEL=$k)" >&2
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Debug -DSSDA_COVERAGE=ON -DSSDA_KERNEL="$k" \
        -DSSDA_WERROR=ON -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=OFF -DSSDA_INSTALL=OFF \
        -DFETCHCONTENT_SOURCE_DIR_UNITY="$unity" >/dev/null
  if ! cmake --build "$dir" -j "$jobs" >"$dir/build.log" 2>&1; then
    cat "$dir/build.log"; echo "coverage: build failed in $dir" >&2; exit 1
  fi
  lcov --quiet --zerocounters --directory "$dir"
  ctest --test-dir "$dir" --output-on-failure -j "$jobs" >"$dir/ctest.log" 2>&1 || {
    cat "$dir/ctest.log"; echo "coverage: tests failed in $dir" >&2; exit 1; }
  tail -n 3 "$dir/ctest.log" | sed -n '/tests passed/p' >&2
  # The library's objects only: a test that calls an inline function of a
  # lib/ header has its own copy of it, which is test code, not lib/'s.
  lcov --quiet "${rc[@]}" --capture --directory "$dir/lib" --base-directory "$root" \
       --output-file "$dir/all.info" 2>"$dir/lcov.log"
  traces+=(--add-tracefile "$dir/all.info")
done

lcov --quiet "${rc[@]}" "${traces[@]}" --output-file "$out/merged.info"
lcov --quiet "${rc[@]}" --extract "$out/merged.info" "$root/lib/*" "$root/include/*" \
     --output-file "$out/lib.info"
genhtml --quiet "${rc[@]}" --branch-coverage --legend --title "ssda lib/ (${kernels[*]})" \
        --prefix "$root" --output-directory "$out/html" "$out/lib.info" >/dev/null

# Branches excluded with LCOV_EXCL_BR_LINE (each one has a reason beside it).
excluded=$(grep -rn 'LCOV_EXCL' lib include | grep -c . || true)

echo "coverage of lib/ and include/ (kernels: ${kernels[*]}; lib/kernel/kernel_armv7em.c runs under QEMU only)"
# Per file: lines hit/found, branches hit/found (lcov's LH/LF/BRH/BRF).
awk -v root="$root/" '
  /^SF:/  { f = substr($0, 4); sub("^" root, "", f) }
  /^LF:/  { lf = substr($0, 4) }
  /^LH:/  { lh = substr($0, 4) }
  /^BRF:/ { bf = substr($0, 5) }
  /^BRH:/ { bh = substr($0, 5) }
  /^end_of_record/ { print f, lh + 0, lf + 0, bh + 0, bf + 0; lh = lf = bh = bf = 0 }
  ' "$out/lib.info" | sort >"$out/lib.txt"
status=0
awk -v min="$min_branch" -v excl="$excluded" '
  function pct(h, n) { return n ? sprintf("%5.1f%%", 100.0 * h / n) : "    - " }
  function row(name, lh, lf, bh, bf) {
    printf "%-32s %s %5d/%-5d %s %5d/%-5d\n", name, pct(lh, lf), lh, lf, pct(bh, bf), bh, bf
  }
  BEGIN { printf "%-32s %18s %18s\n", "file", "lines", "branches" }
  { row($1, $2, $3, $4, $5); tlh += $2; tlf += $3; tbh += $4; tbf += $5 }
  END {
    row("total", tlh, tlf, tbh, tbf)
    printf "lines with LCOV_EXCL markers in lib/ and include/: %d; threshold: branches >= %s%%\n", excl, min
    if (tbf == 0 || 100.0 * tbh / tbf < min) {
      printf "coverage: branch coverage of lib/ %.1f%% is below %s%%\n", tbf ? 100.0 * tbh / tbf : 0, min > "/dev/stderr"
      exit 1
    }
  }' "$out/lib.txt" || status=1
# Where the branches not taken are (file:line, not taken of that line's).
awk -v root="$root/" -F'[:,]' '
  /^SF:/   { f = substr($0, 4); sub("^" root, "", f) }
  /^BRDA:/ { k = f ":" $2; n[k]++; if ($5 == "-" || $5 == "0") miss[k]++ }
  END { for (k in miss) printf "  %s  %d of %d branches not taken\n", k, miss[k], n[k] }
  ' "$out/lib.info" | sort -t: -k1,1 -k2,2n >"$out/uncovered.txt"
if [ -s "$out/uncovered.txt" ]; then
  echo "branches not taken ($(wc -l <"$out/uncovered.txt") lines; reasons in docs/coverage.md):"
  cat "$out/uncovered.txt"
fi
echo "HTML report: $out/html/index.html"
exit "$status"
