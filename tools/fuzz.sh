#!/usr/bin/env bash
# Fuzz the project (docs/fuzzing.md): build the libFuzzer targets of
# tools/fuzz with clang, ASan and UBSan, generate the seed corpus, and run
# each target for a given time, one after the other.
# Usage: tools/fuzz.sh [--time SECONDS] [--build DIR] [target ...]
#   --time   seconds per target (default 60)
#   --build  build folder (default build/fuzz); it keeps, per target:
#            corpus/<t>/ (grows from run to run), seeds/<t>/ (regenerated),
#            crashes/<t>/ (inputs that crashed), logs/<t>.log
#   targets  png wav cli match track pitch stream (default: all)
# Prints each target's executions and whether it crashed; exits 1 if any did.
# Reproduce a crash: DIR/tools/fuzz/fuzz_<t> DIR/crashes/<t>/crash-...
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

secs=60
build=build/fuzz
targets=()
while [ $# -gt 0 ]; do
  case $1 in
    --time) secs=$2; shift 2 ;;
    --time=*) secs=${1#*=}; shift ;;
    --build) build=$2; shift 2 ;;
    --build=*) build=${1#*=}; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
all=(png wav cli match track pitch stream)
[ ${#targets[@]} -eq 0 ] && targets=("${all[@]}")
for t in "${targets[@]}"; do
  case " ${all[*]} " in *" $t "*) ;; *) echo "fuzz.sh: unknown target '$t' (${all[*]})" >&2; exit 2 ;; esac
done

mkdir -p "$build"
build=$(cd "$build" && pwd)

# clang and its runtimes (libFuzzer, ASan, UBSan) come from Debian.
bash tools/setup-deps.sh clang-14 libclang-rt-14-dev

echo "==> ${build#"$root"/} (clang-14, libFuzzer, ASan + UBSan)" >&2
CC=clang-14 cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSDA_FUZZ=ON \
      -DSSDA_SANITIZE=ON -DSSDA_BUILD_TESTS=OFF -DSSDA_BUILD_BENCH=OFF -DSSDA_INSTALL=OFF >/dev/null
build_targets=(fuzz_seeds)
for t in "${targets[@]}"; do build_targets+=("fuzz_$t"); done
if ! cmake --build "$build" -j 2 --target "${build_targets[@]}" >"$build/build.log" 2>&1; then
  cat "$build/build.log"; echo "fuzz.sh: build failed" >&2; exit 1
fi

rm -rf "$build/seeds"
"$build/tools/fuzz/fuzz_seeds" "$build/seeds"
rm -rf "$build/tmp"  # private folders left by crashed runs
mkdir -p "$build/logs" "$build/tmp"

declare -A max_len=([png]=16384 [wav]=16384 [cli]=8192)
# The CLI and libsndfile talk on stderr; libFuzzer keeps its own reports.
declare -A extra=([cli]=-close_fd_mask=2 [wav]=-close_fd_mask=2)
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$root/tools/cli/tests/lsan.supp
export TMPDIR=$build/tmp  # the file targets' private folders (fuzz_cli works in one)

failed=0
printf '%-8s %12s %8s  %s\n' target executions corpus result
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/crashes/$t"
  log=$build/logs/$t.log
  rc=0
  (cd "$build/tmp" && exec "$build/tools/fuzz/fuzz_$t" -max_total_time="$secs" -timeout=30 \
      -rss_limit_mb=3072 -max_len="${max_len[$t]:-4096}" -print_final_stats=1 ${extra[$t]:-} \
      -artifact_prefix="$build/crashes/$t/" \
      "$build/corpus/$t" "$build/seeds/$t") >"$log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  corpus=$(find "$build/corpus/$t" -type f | wc -l)
  if [ "$rc" -eq 0 ]; then
    result=ok
  else
    result="CRASHED (exit $rc; $(ls -t "$build/crashes/$t" | head -n 1); log $log)"
    failed=1
  fi
  printf '%-8s %12s %8s  %s\n' "$t" "${execs:-?}" "$corpus" "$result"
done
[ "$failed" -eq 0 ] || { echo "fuzz.sh: a target crashed; see the logs" >&2; exit 1; }
