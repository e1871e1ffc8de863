#!/usr/bin/env bash
# CLI tests of --threads (tools/common/parallel.c): the same output for any
# thread count, and bad counts refused with exit 2.
#   threads_test.sh threads SSDA GEN CHECK WORKDIR
. "$(dirname "$0")/cli_lib.sh" "$@"

# JSON without its timings (the only members that may differ between runs)
untimed() { sed -E 's/"[a-z_]*time_s":[-0-9.e+]*,?//g' "$1"; }

"$gen" texture a.png --size 160x128 --seed 11
"$gen" texture b.png --size 160x128 --seed 11 --shift 2,-3

# compare: the NCC reference on 1, 2, 3 and 7 threads (more threads than
# cores, and a count that does not divide the windows), and the default
run 0 compare a.png b.png --threads 1 --json c1.json --overlay o1.png --quiet &&
  chk compare-json c1.json 100 && chk track-json c1.json 2 -3 1.0
for t in 2 3 7 0; do
  run 0 compare a.png b.png --threads "$t" --json "c$t.json" --overlay "o$t.png" --quiet || continue
  cmp -s <(untimed c1.json) <(untimed "c$t.json") || fail "compare --threads $t: JSON differs from 1 thread"
  cmp -s o1.png "o$t.png" || fail "compare --threads $t: overlay differs from 1 thread"
done
run 0 compare a.png b.png --json cd.json --quiet &&
  { cmp -s <(untimed c1.json) <(untimed cd.json) || fail "compare (default threads): JSON differs"; }
run 0 compare --threads=2 a.png b.png --window 8 --search 24 --step 8 --json c8a.json --quiet &&
  run 0 compare a.png b.png --window 8 --search 24 --step 8 --threads 1 --json c8b.json --quiet &&
  { cmp -s <(untimed c8a.json) <(untimed c8b.json) || fail "compare --threads=2, 8x8: JSON differs"; }
run 0 compare a.png b.png --threads 2 && grep -q "on 2 threads" out.txt || fail "compare summary: thread count"

# track: a wavefront of grid rows over ssda_track_row (tools/cli/track_wave.c),
# on one thread too; fixed bands of 8 columns here (39 grid columns). Unrelated images give vectors
# that differ from window to window, so every prediction reads neighbours
# that disagree (and ties go to the prediction): any window solved before
# its neighbours would show. Small steps give many rows.
"$gen" texture c.png --size 160x128 --seed 12
# The summary's median motion (track_median_motion: a selection, not a
# sort) against the JSON's ok vectors sorted here; sub_dx, sub_dy are
# multiples of 1/256 written exactly, so awk's mean of the middle two is
# the tool's value.
median_of() {
  grep '"status":"ok"' "$1" | grep -o "\"sub_$2\":[-0-9.]*" | cut -d: -f2 | sort -g |
    awk '{v[NR] = $1} END {if (NR % 2) m = v[(NR + 1) / 2]; else m = (v[NR / 2] + v[NR / 2 + 1]) / 2
                           printf "%d ok vectors dx=%+.2f", NR, m}'
}
parities=""
for pred in neighbour left none; do
  for pair in "a.png b.png" "a.png c.png"; do
    # shellcheck disable=SC2086
    run 0 track $pair --predict "$pred" --window 8 --search 24 --step 4 --threads 1 --json t1.json --quiet ||
      continue
    want=$(median_of t1.json dx)
    grep -qF "median of the $want" out.txt || fail "track $pair --predict $pred: summary '$(grep median out.txt)', JSON gives '$want'"
    parities="$parities $(( $(grep -c '"status":"ok"' t1.json) % 2 ))"
    for t in 2 3 7 0; do
      # shellcheck disable=SC2086
      run 0 track $pair --predict "$pred" --window 8 --search 24 --step 4 --threads "$t" --json "t$t.json" \
        --overlay "to$t.png" --quiet || continue
      cmp -s <(untimed t1.json) <(untimed "t$t.json") ||
        fail "track $pair --predict $pred --threads $t: JSON differs from 1 thread"
    done
  done
done
case $parities in *0*) ;; *) fail "no even count of ok vectors among the medians checked ($parities)" ;; esac
case $parities in *1*) ;; *) fail "no odd count of ok vectors among the medians checked ($parities)" ;; esac

# 16-bit samples with a fill value (masked windows and areas), unrelated
# images: 49 grid columns, 7 bands a row (the last one column wide)
"$gen" texture g1.png --size 200x96 --seed 21 --kind gray16 --max 4000 --fill 4095,60,30,100,60
"$gen" texture g2.png --size 200x96 --seed 22 --kind gray16 --max 4000 --fill 4095,60,30,100,60
if run 0 track g1.png g2.png --mask-value 4095 --window 8 --search 24 --step 4 --threads 1 --json g1.json --quiet; then
  grep -q '"masked":[1-9]' g1.json || fail "16-bit pair: no masked window"
  for t in 2 3 7; do
    run 0 track g1.png g2.png --mask-value 4095 --window 8 --search 24 --step 4 --threads "$t" --json "g$t.json" \
      --quiet || continue
    cmp -s <(untimed g1.json) <(untimed "g$t.json") || fail "16-bit track --threads $t: JSON differs from 1 thread"
  done
fi

# Shared bound tables (issue 18, tools/cli/track_wave.c): in RAM every grid
# row is solved in fixed bands of columns, one ssda_track_row call each,
# which builds the bound tables of its band's search areas and counts them
# in pixel_ops; the bands depend on the grid alone, so the counts above are
# the same for any N. The streamed run (--mem) gives every search its own
# tables: the same windows, positions and completed sums, more pixel_ops
# (here 8 windows 4 px apart share the table columns of their 24 px areas).
num() { grep -o "\"$2\":[0-9]*" "$1" | head -1 | cut -d: -f2; }
windows_of() { grep '^  {"x"' "$1"; }
for pred in neighbour none; do
  run 0 track a.png c.png --predict "$pred" --window 8 --search 24 --step 4 --threads 2 --json s.json --quiet &&
    run 0 track a.png c.png --predict "$pred" --window 8 --search 24 --step 4 --mem 1M --json m.json --quiet ||
    continue
  cmp -s <(windows_of s.json) <(windows_of m.json) || fail "--predict $pred: --mem windows differ from RAM"
  for k in positions completed check_pixels windows ok ambiguous at_limit flat; do
    [ "$(num s.json "$k")" = "$(num m.json "$k")" ] || fail "--predict $pred: $k in RAM differs from --mem"
  done
  [ "$(num s.json pixel_ops)" -lt "$(num m.json pixel_ops)" ] ||
    fail "--predict $pred: pixel_ops in RAM $(num s.json pixel_ops) not below per-window tables' $(num m.json pixel_ops)"
done

run 0 track a.png b.png --threads 1 --json tq.json --quiet && run 0 track a.png b.png --threads 2 --json tp.json &&
  { cmp -s <(untimed tq.json) <(untimed tp.json) || fail "track with a progress bar: JSON differs"; }
run 0 track --help && grep -q -- "--threads N" out.txt || fail "track --help: --threads"
run 2 track a.png b.png --threads x && stderr_has "--threads needs a count"

# bad counts: usage errors, nothing written
for bad in "" x -1 2x 257 99999999999999999999; do
  run 2 compare a.png b.png --json bad.json --threads "$bad" && stderr_has "--threads needs a count" && absent bad.json
done
run 2 compare a.png b.png --json bad.json --threads && stderr_has "--threads needs a count" && absent bad.json
run 0 compare --help && grep -q -- "--threads N" out.txt || fail "compare --help: --threads"

finish
