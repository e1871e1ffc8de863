#!/usr/bin/env bash
# The project's test command (README, and CI through .ci/run).
# On a fresh machine it installs what is missing, then builds and runs every
# test: host build with -Werror (with the Python binding and its pytest
# suite), a host build with ASan + UBSan, the Unity suite on the library
# built without its fast path (SSDA_CFG_NO_FAST_PATH), the library compiled
# with each feature switch of config.h alone and all together, a 32-bit (-m32) host build with
# ASan + UBSan running the Unity suite, the line and
# branch coverage of lib/ (gcov/lcov, >= 95 % of branches), static analysis
# of lib/ (cppcheck + MISRA C 2012, clang-tidy), a 5-second run of every fuzz
# target (libFuzzer), the library tests as bare-metal images under
# qemu-system-arm on four Cortex-M boards,
# and the library alone for six cross targets at -Os and -O2 (-Werror).
# Usage: tools/test.sh            (build dirs under build/)
#        SSDA_SKIP_CROSS=1 tools/test.sh   host builds only
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)

# The Python binding's build and tests (tools/python, docs/python.md) use
# Debian's Python and its packages, never a pip download.
python_pkgs=(python3-dev python3-numpy python3-pytest python3-matplotlib python3-pil
             python3-setuptools python3-pip python3-venv)
skip_cross=${SSDA_SKIP_CROSS:-0}
if [ "$skip_cross" = 1 ]; then
  bash tools/setup-deps.sh "${python_pkgs[@]}"
else
  bash tools/setup-deps.sh "${python_pkgs[@]}" gcc-arm-none-eabi libnewlib-arm-none-eabi \
       gcc-riscv64-unknown-elf qemu-system-arm gcc-multilib qemu-user
fi
unity=$(bash tools/fetch-unity.sh)

configure_build_test() { # <dir> <cmake args...>
  local dir=$1; shift
  echo "==> $dir" >&2
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSDA_WERROR=ON \
        -DFETCHCONTENT_SOURCE_DIR_UNITY="$unity" "$@" >/dev/null
  if ! cmake --build "$dir" -j "$jobs" >"$dir/build.log" 2>&1; then
    cat "$dir/build.log"; echo "tools/test.sh: build failed in $dir" >&2; exit 1
  fi
  ctest --test-dir "$dir" --output-on-failure -j "$jobs"
}

# The host build also builds the Python binding with Debian's Python and
# runs its pytest suite and a pip install (tools/python, docs/python.md).
configure_build_test build/host -DSSDA_BUILD_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ASAN_OPTIONS=detect_leaks=1 \
  configure_build_test build/asan -DSSDA_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug

# The library without its exact fast path (SSDA_CFG_NO_FAST_PATH, issue 18):
# every search then takes the general evaluation, and the Unity suite must
# give the same results there (the fast path is an implementation switch
# only). The library and its tests alone, about half a minute.
configure_build_test build/nofast -DSSDA_CONFIG=SSDA_CFG_NO_FAST_PATH \
  -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=OFF -DSSDA_INSTALL=OFF

# Every feature switch of config.h alone and all together, compiled with
# -Werror for each kernel set (host SSE2 and portable; with the cross
# builds also the Cortex-M4F DSP and Cortex-M0+ ones): the test builds use
# the full library, so a switch alone could stop compiling unseen
# (tools/check-config.sh; about a minute).
echo "==> build/config (feature switches)" >&2
if [ "$skip_cross" = 1 ]; then
  bash tools/check-config.sh build/config
else
  bash tools/check-config.sh --cross build/config
fi

# Coverage of lib/ from the Unity tests (gcov + lcov; docs/coverage.md):
# line and branch figures per file, portable and SSE2 kernels merged; fails
# if lib/'s branch coverage drops below 95 %.
echo "==> build/coverage (gcov/lcov)" >&2
bash tools/coverage.sh build/coverage

# Static analysis of lib/ and include/: cppcheck with the MISRA C 2012 addon
# and clang-tidy (tools/lint.sh, docs/static-analysis.md); fails on any
# finding that is not a documented deviation. About a minute.
echo "==> build/lint (cppcheck + MISRA, clang-tidy)" >&2
bash tools/lint.sh build/lint

# Fuzz smoke run: every libFuzzer target of tools/fuzz for 5 s (clang,
# ASan + UBSan; tools/fuzz.sh, docs/fuzzing.md); fails on any crash.
echo "==> build/fuzz (libFuzzer smoke run)" >&2
bash tools/fuzz.sh --time 5 --build build/fuzz

# 32-bit host build (issue 22): size_t of 32 bits, as on the targets, where
# this library's real overruns were found, with ASan + UBSan: the whole Unity
# suite (about a minute). Natively where the kernel runs i386 binaries, else
# under qemu-i386 user mode (ASan's leak checker does not work there).
# -msse2 -mfpmath=sse: the SSE2 kernel at 32 bits (the targets cover the
# portable one), and the tests' float references without x87 excess precision.
m32_test() {
  local dir=build/m32 emu=() leaks=1
  mkdir -p "$dir"
  printf 'int main(void) { return 0; }\n' >"$dir/probe.c"
  if ! cc -m32 -fsanitize=address,undefined "$dir/probe.c" -o "$dir/probe" 2>"$dir/probe.log"; then
    cat "$dir/probe.log"; echo "tools/test.sh: cannot link -m32 with sanitizers (gcc-multilib)" >&2
    exit 1
  fi
  if ! "$dir/probe" 2>/dev/null; then
    echo "tools/test.sh: this kernel does not run i386 binaries: qemu-i386" >&2
    emu=(-DCMAKE_CROSSCOMPILING_EMULATOR=qemu-i386)
    leaks=0
  fi
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ASAN_OPTIONS=detect_leaks=$leaks \
    configure_build_test "$dir" -DCMAKE_C_FLAGS="-m32 -msse2 -mfpmath=sse" -DSSDA_SANITIZE=ON \
      -DCMAKE_BUILD_TYPE=Debug -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=OFF -DSSDA_INSTALL=OFF \
      "${emu[@]}"
}

# Cross: tests on emulated Cortex-M3 (-Os), M4F and M7 (-O2) and M33 (-Os)
# under QEMU with semihosting (cmake/SsdaTarget.cmake, tests/target/, docs/target.md); a
# guest that hangs is stopped by the CTest timeout.
qemu_test() { # <toolchain> <build type>
  local dir=build/qemu-$1
  echo "==> $dir (qemu-system-arm)" >&2
  cmake -S . -B "$dir" -DCMAKE_TOOLCHAIN_FILE="cmake/toolchains/$1.cmake" \
        -DCMAKE_BUILD_TYPE="$2" -DSSDA_WERROR=ON -DFETCHCONTENT_SOURCE_DIR_UNITY="$unity" >/dev/null
  if ! cmake --build "$dir" -j "$jobs" >"$dir/build.log" 2>&1; then
    cat "$dir/build.log"; echo "tools/test.sh: build failed in $dir" >&2; exit 1
  fi
  ctest --test-dir "$dir" --output-on-failure -j "$jobs" --timeout 600
}

# The library alone, warning-free (-Werror) at -Os and -O2 for every target.
cross_lib() { # <toolchain>
  local bt dir
  for bt in MinSizeRel RelWithDebInfo; do
    dir=build/cross-$1-$bt
    cmake -S . -B "$dir" -DCMAKE_TOOLCHAIN_FILE="cmake/toolchains/$1.cmake" \
          -DCMAKE_BUILD_TYPE="$bt" -DSSDA_WERROR=ON -DSSDA_BUILD_TESTS=OFF >/dev/null
    if ! cmake --build "$dir" -j "$jobs" >"$dir/build.log" 2>&1; then
      cat "$dir/build.log"; echo "tools/test.sh: cross build failed in $dir" >&2; exit 1
    fi
  done
  echo "==> $1: library builds at -Os and -O2" >&2
}

if [ "$skip_cross" != 1 ]; then
  m32_test
  qemu_test cortex-m3 MinSizeRel
  qemu_test cortex-m4f RelWithDebInfo
  qemu_test cortex-m7 RelWithDebInfo
  qemu_test cortex-m33 MinSizeRel
  for t in cortex-m0plus cortex-m3 cortex-m4f cortex-m7 cortex-m33 rv32imc; do
    cross_lib "$t"
  done
  # The sealed library on a cross target without QEMU tests (the QEMU builds
  # run lib_symbols in their CTest): only the public API and ssda__ names.
  m0=build/cross-cortex-m0plus-MinSizeRel
  cmake -DNM="$(sed -n 's/^CMAKE_NM:FILEPATH=//p' "$m0/CMakeCache.txt")" \
        -DLIB="$m0/lib/libssda.a" -DINCLUDE=include -P cmake/CheckSymbols.cmake
fi
echo "tools/test.sh: all test builds passed" >&2
