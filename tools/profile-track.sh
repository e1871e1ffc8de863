#!/usr/bin/env bash
# Where the time of a whole `ssda track` run goes (issue 18, item 4), and
# the whole process timed against other builds of the tool.
#   tools/profile-track.sh [--reps N] [--command track|compare] [--vs OTHER_SSDA]...
#                          [--variant "EXTRA ARGS"]... FIRST.png SECOND.png [options]
# Builds build/profile (RelWithDebInfo, the CLI only; SSDA_PROFILE_DIR
# changes it), then
#  1. samples N runs with `perf record` (when perf is installed and allowed)
#     and prints the share of processor samples per stage: PNG decoding
#     (libpng, zlib), gray conversion, the search (every function of
#     libssda.a), the C library, the kernel (page faults of fresh buffers,
#     file reads), JSON (cJSON), the rest of the tool;
#  2. times N runs of this build (once per --variant: e.g. "--threads 1"
#     and "--threads 2") and of each --vs binary (once per --variant too),
#     interleaved (run k of
#     every one before run k+1 of any), and prints the median wall time and
#     processor time (user + system) of each, with the load average before
#     and after: on a shared machine wall time includes waiting for a core,
#     processor time does not.
# --command compare profiles `ssda compare` instead (its NCC reference).
# Every run writes its JSON to a temporary file (as a user would), and
# each --vs binary's JSON must equal this build's but for timings and
# pixel_ops (printed when they differ: builds may count table work apart).
# Example (the GOES-16 pair of ../shared/data):
#   tools/profile-track.sh --reps 9 ../shared/data/goes16/goes16_c10_20221002_110117.png \
#       ../shared/data/goes16/goes16_c10_20221002_110617.png --mask-value 4095
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=${SSDA_PROFILE_DIR:-$root/build/profile}
reps=7
cmd=track
others=()
variants=()
while [ $# -gt 0 ]; do
  case $1 in
    --reps) reps=$2; shift 2 ;;
    --command) cmd=$2; shift 2 ;;
    --variant) variants+=("$2"); shift 2 ;;
    --vs) others+=("$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"); shift 2 ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || { echo "usage: $0 [--reps N] [--command track|compare] [--vs OTHER_SSDA]... [--variant ARGS]... FIRST.png SECOND.png [options]" >&2; exit 2; }
[ ${#variants[@]} -gt 0 ] || variants=("")
first=$1 second=$2; shift 2
opts=("$@")

(cd "$root" && cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSDA_BUILD_TESTS=OFF \
      -DSSDA_BUILD_BENCH=OFF >/dev/null &&
  cmake --build "$dir" --target ssda_cli -j "$(nproc 2>/dev/null || echo 2)" >/dev/null)
ssda=$dir/tools/cli/ssda
lib=$dir/lib/libssda.a
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
untimed() { sed -E 's/"[a-z_]*time_s":[-0-9.e+]*,?//g' "$1"; }

echo "# \`ssda $cmd\` end to end"
echo
echo "Command: \`tools/profile-track.sh --reps $reps --command $cmd$(printf ' --vs %s' "${others[@]+"${others[@]}"}" | sed 's| --vs $||')$(printf ' --variant "%s"' "${variants[@]}" | sed 's| --variant ""||g') $(basename "$first") $(basename "$second") ${opts[*]+${opts[*]}}\`"
echo "($(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores)."
echo "Load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)."
echo

# ---- 1. where the processor time goes ----------------------------------------
if command -v perf >/dev/null && perf record -q -o "$tmp/probe.data" true >/dev/null 2>&1; then
  nm --defined-only "$lib" 2>/dev/null | awk '$2 ~ /^[tT]$/ {print $3}' | sort -u >"$tmp/libsyms"
  perf record -q -F 4000 -o "$tmp/perf.data" -- bash -c '
    for i in $(seq "$1"); do "$2" "$7" "$3" "$4" "${@:8}" --quiet --json "$5" >/dev/null; done
  ' _ "$reps" "$ssda" "$first" "$second" "$tmp/p.json" "" "$cmd" ${variants[0]} "${opts[@]+"${opts[@]}"}" 2>/dev/null
  perf report -i "$tmp/perf.data" --comm ssda --no-children --sort dso,sym -g none -F overhead,dso,sym \
      --field-separator=$'\t' 2>/dev/null | grep -v '^#' | grep -v '^$' >"$tmp/report.tsv" || true
  awk -F'\t' -v syms="$tmp/libsyms" '
    BEGIN { while ((getline s < syms) > 0) lib[s] = 1 }
    { p = $1; sub(/%/, "", p); p += 0; dso = $2; sym = $3
      sub(/^\[[.k]\] /, "", sym); sub(/[ \t]+$/, "", sym); sub(/[ \t]+$/, "", dso)
      if (dso ~ /libpng|libz\./) c = "PNG decoding (libpng, zlib)"
      else if (sym ~ /^(row_to_gray|widen_to_16)$/) c = "gray conversion (tools/common/png_io.c, cli_args.c)"
      else if (dso == "ssda" && (sym in lib)) c = "the search (libssda.a)"
      else if (sym ~ /^ncc_search/) c = "NCC reference (compare, ncc_ref.c)"
      else if (dso ~ /cjson/ || sym ~ /^json_/) c = "JSON (cJSON, json_out.c)"
      else if (dso ~ /kernel/) c = "kernel (page faults of new buffers, reads)"
      else if (dso ~ /^libc\.|ld-linux/) c = "C library (memcpy, malloc, printf) and loader"
      else c = "the rest of the tool"
      share[c] += p; total += p }
    END { printf "| stage | share of processor samples |\n|---|---:|\n"
          n = 0; for (c in share) order[n++] = c
          for (i = 0; i < n; i++) for (j = i + 1; j < n; j++) if (share[order[j]] > share[order[i]]) { t = order[i]; order[i] = order[j]; order[j] = t }
          for (i = 0; i < n; i++) printf "| %s | %.1f %% |\n", order[i], 100 * share[order[i]] / total }
  ' "$tmp/report.tsv"
  echo
  echo "($(perf report -i "$tmp/perf.data" --comm ssda --stdio 2>/dev/null | grep -m1 -o 'Samples: [^ ]* ' | sed 's/Samples: //')samples at 4 kHz over $reps runs, \`perf record\`.)"
else
  echo "(perf is not installed or not allowed here: no profile; \`apt-get install linux-perf\`,"
  echo "kernel.perf_event_paranoid <= 2.)"
fi
echo

# ---- 2. whole runs, interleaved ----------------------------------------------
# runs: this build once per variant, then each other binary once per variant
bins=() vargs=() names=()
for v in "${variants[@]}"; do
  bins+=("$ssda"); vargs+=("$v"); names+=("this build${v:+ $v}")
done
for o in "${others[@]+"${others[@]}"}"; do
  for v in "${variants[@]}"; do
    bins+=("$o"); vargs+=("$v"); names+=("$o${v:+ $v}")
  done
done
declare -A wall cpu
TIMEFORMAT='%R %U %S'
for ((k = 0; k < reps; k++)); do
  for ((b = 0; b < ${#bins[@]}; b++)); do
    # shellcheck disable=SC2086  # a variant is several words on purpose
    t=$( { time "${bins[$b]}" "$cmd" "$first" "$second" ${vargs[$b]} "${opts[@]+"${opts[@]}"}" --quiet \
             --json "$tmp/run$b.json" >/dev/null 2>"$tmp/err$b"; } 2>&1 ) ||
      { cat "$tmp/err$b" >&2; exit 1; }
    read -r r u s <<<"$t"
    wall[$b]+="$r "
    cpu[$b]+="$(echo "$u + $s" | bc -l) "
  done
done
# pixel_ops may differ between builds (the shared bound tables of issue 18
# count table work per call): said, not refused; anything else refused
ops() { grep -o '"pixel_ops":[0-9]*' "$1" | head -1 | cut -d: -f2; }
for ((b = 1; b < ${#bins[@]}; b++)); do
  cmp -s <(untimed "$tmp/run0.json" | sed -E 's/"pixel_ops":[0-9]+//') \
         <(untimed "$tmp/run$b.json" | sed -E 's/"pixel_ops":[0-9]+//') ||
    { echo "profile-track: '${names[$b]}' writes other JSON than '${names[0]}'" >&2; exit 1; }
  [ "$(ops "$tmp/run0.json")" = "$(ops "$tmp/run$b.json")" ] ||
    echo "(pixel_ops: ${names[0]} $(ops "$tmp/run0.json"), ${names[$b]} $(ops "$tmp/run$b.json"); the rest of the JSON is the same.)"
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
echo "| binary | median wall s | median processor s (user + system) |"
echo "|---|---:|---:|"
for ((b = 0; b < ${#bins[@]}; b++)); do
  echo "| ${names[$b]} | $(median <<<"${wall[$b]}") | $(median <<<"${cpu[$b]}") |"
done
echo
echo "($reps interleaved runs each; the JSON of every run is the same but for timings.)"
echo "Load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)."
