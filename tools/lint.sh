#!/usr/bin/env bash
# Static analysis of the library (lib/ and include/), with the project's real
# compile flags (compile_commands.json of a lib-only CMake configure):
#   cppcheck 2.10 + MISRA C 2012 addon, warning/style/performance/portability,
#     on the portable kernel configuration at 64 and 32 bits, the minimal
#     configuration (every SSDA_CFG_NO_* switch), the pitch with its
#     configuration fixed at compile time (SSDA_CFG_PITCH_FIXED: all parts,
#     and the reduced core), and the SSE2 and ARMv7E-M kernels through
#     their feature macros;
#   clang-tidy 14 with the repository's .clang-tidy, on the portable,
#     minimal and fixed-pitch configurations, the SSE2 kernel (x86-64) and the ARMv7E-M
#     kernel (thumbv7em, Cortex-M4, freestanding).
# Installs cppcheck and clang-tidy from Debian if missing. Exits non-zero on
# any finding that is not a documented deviation: the deviations are the
# rules listed in tools/cppcheck-suppressions.txt, the checks excluded in
# .clang-tidy, and the few NOLINT / cppcheck-suppress comments in lib/, each
# with its reason in docs/static-analysis.md.
# Usage: tools/lint.sh [build dir]          (default build/lint)
#        SSDA_LINT_AUDIT=1 tools/lint.sh    cppcheck without any suppression:
#                                           every finding counted per rule
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
out=${1:-build/lint}
jobs=$(nproc 2>/dev/null || echo 2)
audit=${SSDA_LINT_AUDIT:-0}

bash tools/setup-deps.sh cppcheck clang-tidy python3
tidy=$(command -v clang-tidy-14 || command -v clang-tidy)
echo "lint: $(cppcheck --version), $("$tidy" --version | grep -o 'LLVM version [0-9.]*')" >&2

mkdir -p "$out"
out=$(cd "$out" && pwd)

# The library alone, portable kernel: the flags every target shares.
cmake -S . -B "$out/portable" -DSSDA_KERNEL=portable -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
      -DSSDA_BUILD_TESTS=OFF -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=OFF \
      -DSSDA_INSTALL=OFF >/dev/null
db="$out/portable/compile_commands.json"
# The minimal cores of docs/target.md: every feature switch of
# include/ssda/config.h set, so the code that replaces a left-out feature is
# checked too.
minimal=$(grep -o 'SSDA_CFG_NO_[A-Z0-9_]*' include/ssda/config.h | sort -u | paste -sd';' -)
cmake -S . -B "$out/minimal" -DSSDA_KERNEL=portable -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
      -DSSDA_BUILD_TESTS=OFF -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=OFF \
      -DSSDA_INSTALL=OFF -DSSDA_CONFIG="$minimal" >/dev/null

# The pitch with its configuration fixed at compile time (SSDA_CFG_PITCH_FIXED,
# docs/pitch.md), twice: every part built in (tools/lint-pitch-fixed.h), and
# the reduced core of docs/target.md (tests/config/pitch_fixed_settings.h,
# whose PITCH_FIXED_SIDE sets the switches). Only the pitch's files: the
# setting changes nothing else.
fixed_pass() { # <name> <settings file> [SSDA_CONFIG]
  cmake -S . -B "$out/$1" -DSSDA_KERNEL=portable -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
        -DSSDA_BUILD_TESTS=OFF -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=OFF \
        -DSSDA_INSTALL=OFF -DSSDA_CONFIG_FILE="$2" -DSSDA_CONFIG="${3:-}" >/dev/null
  python3 - "$out/$1/compile_commands.json" <<'PY'
import json, re, sys
db = json.load(open(sys.argv[1]))
json.dump([e for e in db if re.search(r"/lib/pitch[a-z_]*\.c$", e["file"])],
          open(sys.argv[1], "w"), indent=1)
PY
}
fixed_pass fixed "$root/tools/lint-pitch-fixed.h"
fixed_pass fixed-reduced "$root/tests/config/pitch_fixed_settings.h" PITCH_FIXED_SIDE

# The accelerated kernels: the portable command line of the kernel file, with
# the other kernel's file and macro, and for ARM the target flags and the
# freestanding string.h of the rv32 build (no Arm C library on the host).
portable_cmd=$(grep -o '"command": "[^"]*kernel_portable.c"' "$db" | sed 's/^"command": "//; s/"$//')
kernel_cmd() { # <kernel> <extra flags>
  printf '%s' "$portable_cmd" |
    sed "s/kernel_portable/kernel_$1/g; s/SSDA_KERNEL_portable/SSDA_KERNEL_$1/; s|^\([^ ]*\) |\1 $2 |"
}
mkdir -p "$out/kernels"
cc_dir=$(grep -o '"directory": "[^"]*"' "$db" | head -1 | sed 's/^"directory": "//; s/"$//')
cat >"$out/kernels/compile_commands.json" <<EOF
[
{ "directory": "$cc_dir",
  "command": "$(kernel_cmd sse2 "--target=x86_64-linux-gnu -msse2")",
  "file": "$root/lib/kernel/kernel_sse2.c" },
{ "directory": "$cc_dir",
  "command": "$(kernel_cmd armv7em "--target=thumbv7em-none-eabi -mcpu=cortex-m4 -mthumb -ffreestanding -I$root/cmake/toolchains/freestanding")",
  "file": "$root/lib/kernel/kernel_armv7em.c" }
]
EOF

# ---- cppcheck + MISRA C 2012 ------------------------------------------------
cpp_common=(--addon=misra --enable=warning,style,performance,portability --std=c99
            --error-exitcode=0 -q -j "$jobs" --library=std
            --template='{file}:{line}:{column}: {severity}: {message} [{id}]')
if [ "$audit" != 1 ]; then
  cpp_common+=(--inline-suppr --suppressions-list=tools/cppcheck-suppressions.txt)
fi
cppcheck_pass() { # <name> <cppcheck args...>
  local name=$1; shift
  mkdir -p "$out/cppcheck-$name"
  # the addon writes its dump files into the build dir, never next to sources
  cppcheck "${cpp_common[@]}" --cppcheck-build-dir="$out/cppcheck-$name" "$@" \
           2>"$out/cppcheck-$name.txt" >/dev/null
}
kernel_inc=(-I include -I lib)
cppcheck_pass portable64 --platform=unix64 --project="$db"
cppcheck_pass portable32 --platform=unix32 --project="$db"
minimal_supp=()
if [ "$audit" != 1 ]; then
  minimal_supp=(--suppressions-list=tools/cppcheck-suppressions-minimal.txt)
fi
cppcheck_pass minimal --platform=unix32 "${minimal_supp[@]}" \
              --project="$out/minimal/compile_commands.json"
cppcheck_pass fixed --platform=unix32 --project="$out/fixed/compile_commands.json"
cppcheck_pass fixed-reduced --platform=unix32 "${minimal_supp[@]}" \
              --project="$out/fixed-reduced/compile_commands.json"
cppcheck_pass sse2 --platform=unix64 "${kernel_inc[@]}" -DSSDA_KERNEL_sse2=1 -D__SSE2__=1 \
              lib/kernel/kernel_sse2.c
cppcheck_pass armv7em --platform=unix32 "${kernel_inc[@]}" -DSSDA_KERNEL_armv7em=1 \
              -D__ARM_FEATURE_DSP=1 -D__ARM_FEATURE_SIMD32=1 lib/kernel/kernel_armv7em.c
# A header seen by several passes is reported once.
cat "$out"/cppcheck-*.txt | sed "s|^$root/||" | grep -v '^$' | sort -u >"$out/cppcheck.txt" || true
n_cpp=$(wc -l <"$out/cppcheck.txt")

# ---- clang-tidy -------------------------------------------------------------
tidy_files() { # <compile db dir>
  grep -o '"file": "[^"]*"' "$1/compile_commands.json" | sed 's/^"file": "//; s/"$//'
}
: >"$out/clang-tidy.raw"
for d in "$out/portable" "$out/minimal" "$out/fixed" "$out/fixed-reduced" "$out/kernels"; do
  tidy_files "$d" | xargs -P "$jobs" -n 1 "$tidy" -p "$d" --quiet --extra-arg=-Wcomma \
    >>"$out/clang-tidy.raw" 2>/dev/null || true
done
grep -E '^[^ ].*: (warning|error): ' "$out/clang-tidy.raw" | sed "s|^$root/||" | sort -u \
  >"$out/clang-tidy.txt" || true
n_tidy=$(wc -l <"$out/clang-tidy.txt")

# ---- report -----------------------------------------------------------------
if [ "$audit" = 1 ]; then
  echo "lint audit: cppcheck findings per id, no suppression ($n_cpp in all):" >&2
  grep -o '\[[^]]*\]$' "$out/cppcheck.txt" | sort | uniq -c | sort -rn >&2 || true
fi
# In-place suppressions: each one is a record I<n> of docs/static-analysis.md.
inplace=$(grep -rnE 'NOLINT|cppcheck-suppress' lib include || true)
if [ "$audit" = 1 ] && [ -n "$inplace" ]; then
  echo "lint audit: in-place suppressions:" >&2
  printf '%s\n' "$inplace" >&2
fi
if [ "$n_cpp" -ne 0 ]; then cat "$out/cppcheck.txt"; fi
if [ "$n_tidy" -ne 0 ]; then cat "$out/clang-tidy.txt"; fi
echo "lint: cppcheck $n_cpp, clang-tidy $n_tidy finding(s) outside the documented deviations" \
     "($(printf '%s' "$inplace" | grep -c . || true) suppressed in place;" \
     "docs/static-analysis.md; full output in $out)" >&2
[ "$n_cpp" -eq 0 ] && [ "$n_tidy" -eq 0 ]
