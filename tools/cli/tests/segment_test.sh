#!/usr/bin/env bash
# CLI tests of `ssda segment` (their own script, so the other groups'
# cli_test.sh is not touched):
#   segment_test.sh SSDA GEN CHECK WORKDIR
# GEN (seg_gen.c) makes RGB scenes with known regions and a gray image with a
# known mixture; CHECK (seg_check.c) measures labels against the truth
# (adjusted Rand index) and checks the JSON. Every case states its expected
# exit code; failed runs must leave no output.
. "$(dirname "$0")/cli_lib.sh" segment "$@"

"$gen" scene brightness bright.png bright-truth.png || exit 1
"$gen" scene hue hue.png hue-truth.png || exit 1
"$gen" scene brightness bright16.png bright16-truth.png --bits 16 || exit 1
"$gen" scene brightness holes.png holes-truth.png --nodata || exit 1
"$gen" mixture mix.png || exit 1
"$gen" blank blank.png || exit 1
"$gen" mixture tall.png 40x33000 || exit 1

# ---- usage ----
run 0 segment --help && grep -q "usage: ssda segment" out.txt || fail "segment --help"
run 0 help segment && grep -q "usage: ssda segment" out.txt || fail "help segment"
run 2 segment
run 2 segment a.png b.png
run 2 segment a.png --no-such-option
run 2 segment a.png --fit newton
run 2 segment a.png --init random
run 2 segment a.png --rule nearest
run 2 segment a.png --matrix identity
run 2 segment a.png --band 4
run 2 segment a.png --components 0
run 2 segment a.png --components 3,4
run 2 segment a.png --components 17
run 2 segment a.png --max-components 0
run 2 segment a.png --band-sigma 0
run 2 segment a.png --bins 8
run 2 segment a.png --gain-max 0
run 2 segment a.png --nodata -1
run 2 segment a.png --json
run 2 segment a.png --quiet && stderr_has "nothing to do"

# ---- known regions ----
# brightness: Z1 alone separates the three grays
run 0 segment bright.png --band 1 --components 3 -o lab.png --json b.json || true
chk ari lab.png bright-truth.png 0.95
chk json b.json 1 3
grep -q "^Z1: 3 components" out.txt || fail "summary: $(cat out.txt)"
# hue at equal brightness: Z2 separates them
run 0 segment hue.png --band 2 --components 3 -o hlab.png || true
chk ari hlab.png hue-truth.png 0.90
# 16-bit input, automatic K (BIC), the seed's search
run 0 segment bright16.png --band 1 -o lab16.png --json b16.json || true
chk ari lab16.png bright16-truth.png 0.90
chk json b16.json 1 0
run 0 segment bright.png --band 1 --components 3 --fit search -o slab.png || true
chk ari slab.png bright-truth.png 0.90
run 0 segment bright.png --band 1 --components 3 --fit search --seed-steps --init quantiles -o s2.png || true
chk png s2.png 120 90
# nodata: the zero corner stays 0 and is counted as masked
run 0 segment holes.png --band 1 --components 3 --nodata 0 -o hol.png --json hol.json || true
chk ari hol.png holes-truth.png 0.95
chk json hol.json 1 3
grep -q '"masked_pixels":[[:space:]]*210' hol.json || fail "masked pixels: $(grep masked hol.json)"
# every feature: three label files, the plot, the picture, JSON with the K-L part
run 0 segment bright.png --components 3,3,2 -o all.png --json all.json --plot h.png \
      --picture p.png --contours --matrix covariance --rule likely --features f.png || true
for k in 1 2 3; do chk png "all-z$k.png" 120 90; chk png "f-z$k.png" 120 90; done
chk json all.json 3 3
[ -s h.png ] || fail "no plot"
[ -s p.png ] || fail "no picture"
grep -q '"unlabelled_pixels":[[:space:]]*0' all.json || fail "--rule likely left pixels unlabelled"
# a tall image (40 x 33000, taller than cairo's 32767 px): the picture is
# drawn reduced to at most 4000 px tall, no crash (a segfault before)
run 0 segment tall.png --components 3 -o tall-lab.png --picture tall-p.png -q &&
  { chk png tall-lab.png 40 33000; [ -s tall-p.png ] || fail "no picture of the tall image"; }
# a gray image: the histogram part alone, means in pixel values
run 0 segment mix.png --components 3 --json mix.json --no-clean || true
chk json mix.json 1 3 50 120 200
grep -q '"kind":[[:space:]]*"gray"' mix.json || fail "gray kind"
run 0 segment mix.png --components 3 --json - -q && grep -q '"features"' out.txt || fail "--json -"

# ---- failures leave nothing ----
run 1 segment missing.png -o x.png --json x.json && stderr_has "missing.png"
absent x.png x.json
: >empty.png
run 1 segment empty.png -o x.png && stderr_has "empty"
absent x.png
run 1 segment blank.png --nodata 0 -o x.png --json x.json && stderr_has "nodata"
absent x.png x.json
run 1 segment bright.png --nodata 300 -o x.png && stderr_has "--nodata 300"
absent x.png
run 1 segment bright.png --components 3 -o no/such/dir/x.png --json x.json
absent x.json x-z1.png

finish
