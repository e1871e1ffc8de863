#!/usr/bin/env bash
# Every feature switch of include/ssda/config.h, alone and all together,
# compiled the way the library is (-Werror, the project's warnings) for each
# kernel set: the host's SSE2 and portable kernels, and with
# --cross the Cortex-M4F (ARMv7E-M DSP kernels) and Cortex-M0+ (portable,
# 32-bit long). Only the files a switch changes are compiled again
# (tools/check_config.py). Part of tools/test.sh; about a minute.
# Usage: tools/check-config.sh [--cross] [BUILD_ROOT]   (default build/config)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cross=0
if [ "${1:-}" = "--cross" ]; then cross=1; shift; fi
out=${1:-build/config}
mkdir -p "$out"
dirs=()
configure() { # <name> <cmake args...>
  local dir=$out/$1; shift
  if ! cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSDA_WERROR=ON \
       -DSSDA_BUILD_TESTS=OFF -DSSDA_BUILD_TOOLS=OFF -DSSDA_BUILD_BENCH=OFF -DSSDA_INSTALL=OFF \
       -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "$@" >"$dir.configure.log" 2>&1; then
    cat "$dir.configure.log" >&2; echo "check-config.sh: configure failed in $dir" >&2; exit 1
  fi
  dirs+=("$dir")
}
configure host-sse2
configure host-portable -DSSDA_KERNEL=portable
if [ "$cross" = 1 ]; then
  configure cortex-m4f -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/cortex-m4f.cmake"
  configure cortex-m0plus -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/cortex-m0plus.cmake" \
            -DCMAKE_BUILD_TYPE=MinSizeRel
fi
python3 tools/check_config.py include/ssda/config.h "${dirs[@]}"
