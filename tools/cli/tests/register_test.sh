#!/usr/bin/env bash
# CLI tests of `ssda register` (issue 17):
#   register_test.sh SSDA GEN CHECK WORKDIR
# GEN (gen_register.c) makes a pair with a known 2nd-order map, CHECK
# (check_register.c) reads the outputs back with jansson, giflib and libpng.
# Every case states its expected exit code; failed runs leave no output.
. "$(dirname "$0")/cli_lib.sh" register "$@"

"$gen" . || { echo "FAIL: gen_register" >&2; exit 1; }

# the known map recovered (order 2, 4x4 grid), every output written
run 0 register ref.png mov.png -o out.png --json reg.json --flicker f.gif --checker c.png \
      --diff d.png --stack s.png && {
  chk map reg.json truth.txt 0.5
  chk png out.png 320 240 1 8
  chk png s.png 320 240 3 8
  chk png c.png 320 240 1 8
  chk png d.png 320 240 1 8
  chk gif f.gif 2 320 240
  chk aligned out.png ref.png 6
  grep -q "control points accepted" out.txt || fail "no summary"
}
# nearest resampling (the seed), order 1 and 3, 16-bit
run 0 register ref.png mov.png -o n.png --resample nearest --order 3 --grid 5x4 --json n.json -q &&
  { chk map n.json truth.txt 0.5; chk aligned n.png ref.png 8; [ -s out.txt ] && fail "-q printed"; }
run 0 register ref16.png mov16.png -o o16.png --json o16.json -q &&
  { chk map o16.json truth.txt 0.5; chk png o16.png 320 240 1 16; }
run 0 register ref.png mov.png --order 1 --json o1.json -q && chk map o1.json truth.txt 1.5
# across a gain change (8-bit REF, 12-bit counts in 16 bits): |rho| is blind to gain
run 0 register ref.png mov16.png --json g.json -q && chk map g.json truth.txt 0.5
# inverted contrast: |rho| (the default) matches, rho alone finds too few
run 0 register ref.png inv.png --json inv.json -q && {
  chk map inv.json truth.txt 0.5
  grep -q '"rho":-0\.[6-9]' inv.json || fail "no negative rho in inv.json"
}
run 1 register ref.png inv.png --metric ncc -o x.png && { stderr_has "order 2 needs at least 6"; absent x.png; }
# SSDA (the seed's fast alternative) on the same-gain pair
run 0 register ref.png mov.png --metric sad --json sad.json -q && chk map sad.json truth.txt 0.5
# "sad" is measured by the sad metric only: null, never 0, under the correlation
grep -q '"status":"ok","sad":[1-9]' sad.json && grep -q '"status":"ok","sad":null' reg.json &&
  ! grep -q '"sad":0[,}]' reg.json || fail "sad in the points: $(grep -o '"status[^}]*' reg.json | head -3)"
# streamed in 4 KB: the same output as in RAM
run 0 register ref.png mov.png -o m.png --mem 4K -q && chk same m.png out.png
# the least --mem (20 rows of an 80 px cell of REF + a row of a 40 px area
# of MOV, 8-bit): the same output; a byte less is refused, naming it
run 0 register ref.png mov.png -o m1640.png --mem 1640 -q && chk same m1640.png out.png
run 1 register ref.png mov.png -o x.png --mem 1639 && { stderr_has "needs: --mem 1640"; absent x.png; }
run 0 register ref.png mov.png -o m2.png --mem 4K && grep -q "streamed in 4096 bytes" out.txt ||
  fail "no streamed summary"
# the offset given instead of found, the same map
run 0 register ref.png mov.png --offset 7,-5 --json off.json -q && chk map off.json truth.txt 0.5
# shading removal first
run 0 register ref.png mov.png --shade --json sh.json -q && chk map sh.json truth.txt 0.6
# several MOVs: -o each, a stack of three bands, the JSON's registrations
run 0 register ref.png mov.png mov.png -o a.png -o b.png --stack s3.png --json two.json -q && {
  chk map two.json truth.txt 0.5 0; chk map two.json truth.txt 0.5 1; chk png s3.png 320 240 3 8
  chk same a.png b.png
}
# fewer -o than MOVs: the MOV without one is written nowhere, and a
# warning names it; --json (or --stack, --flicker) takes it: no warning
run 0 register ref.png mov.png mov16.png -o w1.png -q && {
  stderr_has "warning: 2 MOV images and 1 -o output: 'mov16.png' is registered but written nowhere"
  [ -s w1.png ] || fail "w1.png not written"
}
run 0 register ref.png mov.png mov16.png -o w2.png --json w2.json -q &&
  grep -q "written nowhere" err.txt && fail "warned with --json: $(cat err.txt)"
run 0 register ref.png mov.png mov.png mov16.png --checker wc.png -q &&
  stderr_has "'mov.png' and the MOVs after it are registered but written nowhere"
# JSON on stdout
run 0 register ref.png mov.png --json - && grep -q '"coeffs_x"' out.txt || fail "--json - printed no JSON"

# a map from fewer than half the cells: a warning on stderr, also with -q (a
# tiny outlier bound drops pairs down to terms + 1 = 4 of 16)
run 0 register ref.png mov.png --order 1 --max-residual 0.01 --json w.json -q &&
  stderr_has "only 4 of 16 cells gave the map's control points"
run 0 register ref.png mov.png --json w2.json -q && [ -s err.txt ] && fail "warning on a good run: $(cat err.txt)"
grep -q '"weak":false' w2.json || fail "a good run's fit is not weak=false in w2.json"
# a weakly determined map (order 3 on 4 x 4 cells: 16 points for 10 terms):
# a warning on stderr, also with -q, and "weak":true in the JSON
run 0 register ref.png mov.png --order 3 --json w3.json -q &&
  stderr_has "the order-3 map is weakly determined (16 points for 10 terms" &&
  { grep -q '"weak":true' w3.json || fail "no weak:true in w3.json"; }
# too few control points: exit 1, the counts named, no output at all
run 1 register ref.png flat.png -o x.png --json x.json --flicker x.gif && {
  stderr_has "found 0 control points of 16 cells; order 2 needs at least 6"; absent x.png x.json x.gif
}
run 1 register ref.png flat.png -o x.png --order 3 --grid 3x3 && {
  stderr_has "needs at least 10"; absent x.png
}
# bad input and usage
run 1 register ref.png nothere.png -o x.png && absent x.png
run 1 register tiny.png tiny.png -o x.png && absent x.png && stderr_has "smaller than the 20 px window"
run 2 register ref.png mov.png -o x.png --mem 255 && absent x.png
run 2 register ref.png -o x.png && absent x.png
run 2 register ref.png mov.png && stderr_has "no output"
run 2 register ref.png mov.png -o x.png --order 4
run 2 register ref.png mov.png -o x.png --grid 0x3
# a grid too fine for the window (320 x 240, 20 px windows): usage, naming what fits
run 2 register ref.png mov.png -o x.png --search 10 && absent x.png &&
  stderr_has "--search 10 is smaller than the 20 px window"
run 2 register ref.png mov.png -o x.png --window 50 && stderr_has "--search 40 is smaller than the 50 px window"
run 2 register ref.png mov.png -o x.png --grid 17x4 && absent x.png &&
  stderr_has "cells of 18 x 60 px" && stderr_has "at most 16x12 cells"
run 1 register ref.png mov.png -o x.png --window 250 --search 300 && absent x.png && stderr_has "smaller than the 250 px window"
run 2 register ref.png mov.png -o x.png --metric foo
run 2 register ref.png mov.png -o x.png --min-rho 0
run 2 register ref.png mov.png -o x.png --resample cubic
run 2 register ref.png mov.png -o x.png -o y.png && absent x.png y.png
run 2 register ref.png mov.png mov.png mov.png mov.png --stack x.png && absent x.png
run 0 register --help && grep -q "usage: ssda register" out.txt || fail "no --help"

finish
