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

# bad counts: usage errors, nothing written
for bad in "" x -1 2x 257 99999999999999999999; do
  run 2 compare a.png b.png --json bad.json --threads "$bad" && stderr_has "--threads needs a count" && absent bad.json
done
run 2 compare a.png b.png --json bad.json --threads && stderr_has "--threads needs a count" && absent bad.json
run 0 compare --help && grep -q -- "--threads N" out.txt || fail "compare --help: --threads"

finish
