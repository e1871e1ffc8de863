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

# track: a wavefront of grid rows over ssda_track_row (tools/cli/track_wave.c);
# --threads 1 --quiet is one ssda_track call. Unrelated images give vectors
# that differ from window to window, so every prediction reads neighbours
# that disagree (and ties go to the prediction): any window solved before
# its neighbours would show. Small steps give many rows.
"$gen" texture c.png --size 160x128 --seed 12
for pred in neighbour left none; do
  for pair in "a.png b.png" "a.png c.png"; do
    # shellcheck disable=SC2086
    run 0 track $pair --predict "$pred" --window 8 --search 24 --step 4 --threads 1 --json t1.json --quiet ||
      continue
    for t in 2 3 7 0; do
      # shellcheck disable=SC2086
      run 0 track $pair --predict "$pred" --window 8 --search 24 --step 4 --threads "$t" --json "t$t.json" \
        --overlay "to$t.png" --quiet || continue
      cmp -s <(untimed t1.json) <(untimed "t$t.json") ||
        fail "track $pair --predict $pred --threads $t: JSON differs from one ssda_track call"
    done
  done
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
