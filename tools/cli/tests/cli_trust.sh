#!/usr/bin/env bash
# Vectors a tracking unit can trust (issue 15): the statuses flat,
# ambiguous and at_limit, the tie rule toward the prediction, the
# sub-pixel vectors and the options that set them; the warnings; the
# summary's and compare's counts over ok windows only. One CTest group:
#   cli_trust.sh trust SSDA GEN CHECK WORKDIR
. "$(dirname "$0")/cli_lib.sh" "$@"

# windows entirely inside the filled rectangle 32..95 x 32..95 of a 128 x 128
# grid of 16 px windows: the 4 x 4 at 32, 48, 64, 80 (search areas may reach
# out: they are searched only without the flat test)
"$gen" texture a.png --size 128x128 --seed 3 --fill 90,32,32,95,95
"$gen" texture b.png --size 128x128 --seed 3 --shift 3,-2 --fill 90,32,32,95,95

# flat windows are found before any search and are not trusted
run 0 track a.png b.png --json t.json --quiet &&
  chk track-json t.json 3 -2 1.0 --count flat 16 --count edge 28 &&
  grep -q '"status":"flat"' t.json && grep -q '"texture":0.00000000' t.json &&
  grep -q '"flat":1.25000000' t.json || fail "flat windows"
grep -q 'status:  [0-9]* ok, 16 flat' out.txt || fail "summary lacks the flat count: $(cat out.txt)"
grep -q "median of the [0-9]* ok vectors dx=+3.00 dy=-2.00" out.txt || fail "median of ok vectors: $(cat out.txt)"
# without the flat test: every placement of a constant window ties; the
# uniqueness test calls them ambiguous (another placement exactly as good)
run 0 track a.png b.png --flat 0 --json t.json --quiet &&
  chk track-json t.json 3 -2 1.0 --count flat 0 --count ambiguous 16 &&
  grep -q '"unique":1.00000000' t.json && grep -q '"flat":null' t.json || fail "--flat 0"
# and without either: the tie goes to the zero-SAD placement nearest to the
# neighbours' prediction, (3, -2), not to the top-left one (+8, +8): none
# at the limit
run 0 track a.png b.png --flat 0 --unique off --json t.json --quiet &&
  chk track-json t.json 3 -2 0.75 --count ok 36 --count at_limit 0 &&
  grep -q '"unique":null' t.json && ! grep -q '"dx":8,"dy":8' t.json ||
  fail "tie rule toward the prediction"
run 0 track a.png b.png --flat 0 --unique off --predict none --json t.json --quiet &&
  chk track-json t.json 3 -2 0.5 --count at_limit 0 && ! grep -q '"dx":8,"dy":8' t.json ||
  fail "tie rule toward zero motion"
# a level above the texture: every window flat, and said
run 0 track a.png b.png --flat 200 --quiet && stderr_has "nothing to track: of 64 windows 0 excluded (no texture), 36 flat"

# motion beyond the +-8 of 16 px windows in 32 px areas: at_limit, warned
"$gen" texture c.png --size 128x128 --seed 5
"$gen" texture d.png --size 128x128 --seed 5 --shift 11,0
run 0 track c.png d.png --json t.json --quiet &&
  chk track-json t.json 8 0 0 --no-ok --count ok 0 &&
  stderr_has "searched windows are 'at_limit'" && stderr_has "try --search 48x48" &&
  stderr_has "no window is 'ok'"
run 0 track c.png d.png --search 48 --json t.json --quiet &&
  chk track-json t.json 11 0 1.0 --count at_limit 0 && ! grep -q "at_limit'" err.txt ||
  fail "a larger --search finds the motion"

# sub-pixel vectors: within half a pixel of the whole ones (the checker),
# equal to them with --no-subpixel or outside the exact modes
run 0 track a.png b.png --json t.json --quiet && grep -q '"sub_dx":' t.json &&
  grep -q '"subpixel":true' t.json || fail "sub_dx in the JSON"
run 0 track a.png b.png --no-subpixel --json t.json --quiet &&
  chk track-json t.json 3 -2 1.0 --whole && grep -q '"subpixel":false' t.json || fail "--no-subpixel"
run 0 track a.png b.png --threshold auto-ramp --json t.json --quiet &&
  chk track-json t.json 3 -2 0.8 --whole && grep -q '"unique":null,"subpixel":false' t.json ||
  fail "inexact mode: no uniqueness, no fit"

# options
run 0 track a.png b.png --unique 1.5 --unique-radius 1 --json t.json --quiet &&
  grep -q '"unique":{"ratio":1.50000000,"radius":1}' t.json || fail "--unique 1.5 --unique-radius 1"
run 2 track a.png b.png --unique 1.0 && stderr_has "bad --unique '1.0'"
run 2 track a.png b.png --unique-radius 3 && stderr_has "bad --unique-radius '3'"
run 2 track a.png b.png --flat -1 && stderr_has "bad --flat '-1'"
run 2 track a.png b.png --unique 1.2 --threshold auto-ramp && stderr_has "--unique needs an exact search"

# compare counts ok windows only, and says what it left out
run 0 compare a.png b.png && grep -q "on 20 ok windows (of 64: 16 flat" out.txt ||
  fail "compare over ok windows: $(cat out.txt)"
run 0 track a.png b.png --overlay o.png --quiet && [ -s o.png ] || fail "overlay with statuses"

# issue 14 item 1: a fixed threshold below every SAD, bounds on (the
# default). Every position is cut; positions rejected by their bound before
# any pixel was summed do not win the fallback (it was x=0 y=0 "SAD 0"),
# and the SAD reported is the full one at the position reported: the same
# as a brute-force match of the search cropped there
"$gen" texture ms.png --size 96x80 --seed 1
"$gen" texture mw.png --size 16x16 --seed 99
run 0 match ms.png mw.png --threshold fixed:100 --json && grep -q '"exact":false,"all_cut":true' out.txt ||
  fail "all-cut fallback: $(cat out.txt)"
fx=$(sed 's/.*"x":\([0-9]*\),.*/\1/' out.txt) fy=$(sed 's/.*"y":\([0-9]*\),.*/\1/' out.txt)
fs=$(sed 's/.*"sad":\([0-9]*\),.*/\1/' out.txt)
[ "$fx,$fy" != "0,0" ] || fail "the fallback is a position rejected by its bound: $(cat out.txt)"
"$gen" crop ms.png mc.png "$fx,$fy,16,16"
run 0 match mc.png mw.png --threshold none --json && grep -q "\"sad\":$fs," out.txt ||
  fail "the fallback's SAD $fs is not the full SAD at ($fx, $fy): $(cat out.txt)"
run 0 match ms.png mw.png --threshold fixed:100 && grep -q "SAD: *$fs  (full SAD of the fallback" out.txt ||
  fail "text output does not label the fallback: $(cat out.txt)"
run 0 match ms.png mw.png --threshold ramp:1 --json && grep -q '"all_cut":true' out.txt &&
  fs=$(sed 's/.*"sad":\([0-9]*\),.*/\1/' out.txt) fx=$(sed 's/.*"x":\([0-9]*\),.*/\1/' out.txt) &&
  fy=$(sed 's/.*"y":\([0-9]*\),.*/\1/' out.txt) && "$gen" crop ms.png mc.png "$fx,$fy,16,16" &&
  run 0 match mc.png mw.png --threshold none --json && grep -q "\"sad\":$fs," out.txt ||
  fail "ramp: the fallback's SAD is not the full SAD"
finish
