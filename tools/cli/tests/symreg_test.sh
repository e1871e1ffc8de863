#!/usr/bin/env bash
# CLI tests of `ssda symreg` and `ssda shape` (seed 001):
#   symreg_test.sh SSDA GEN WORKDIR
# GEN (gen_symreg.c) renders scene pairs with a known similarity and gain,
# silhouettes with a known turn and scale, and checks the JSON outputs.
# cli_lib.sh takes GROUP SSDA GEN CHECK WORKDIR: no CHECK here.
. "$(dirname "$0")/cli_lib.sh" symreg "$1" "$2" "" "$3"
is_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "'$1' is not a PNG"; }

# usage
for c in symreg shape; do
  run 0 "$c" --help && grep -q "usage: ssda $c" out.txt || fail "ssda $c --help"
  run 2 "$c"
  run 2 "$c" a.png
  run 2 "$c" a.png b.png c.png
  run 2 "$c" a.png b.png --no-such-option
done
run 2 symreg a.png b.png --strength 0
run 2 symreg a.png b.png --area 100,50
run 2 symreg a.png b.png --samples 48
run 2 symreg a.png b.png --scale 2,1
run 2 symreg a.png b.png --min-pairs 2
run 2 symreg a.png b.png --json
run 2 shape a.png b.png --order 17
run 2 shape a.png b.png --samples 16 --order 10 && stderr_has "needs more than 20 samples"

# a registration: turned 30 degrees, scaled 1.2, darker, shifted
truth=$("$gen" scene ref.png mov.png --angle 30 --scale 1.2 --gain 0.8 --shift 6,-4 --size 256) \
  || fail "gen scene"
run 0 symreg ref.png mov.png --json reg.json --overlay ov.png -o warped.png \
  || sed 's/^/  out: /' out.txt >&2
# shellcheck disable=SC2086
"$gen" check-affine reg.json $truth 2.0 256 || fail "symreg affine"
is_png ov.png
is_png warped.png
grep -q "^affine:" out.txt || fail "summary lacks the affine"
# JSON to stdout, no summary
run 0 symreg ref.png mov.png --json - && grep -q '"affine"' out.txt || fail "--json -"
grep -q "^loops:" out.txt && fail "summary printed with --json -"
# a turn past 90 degrees and a brighter MOV
truth=$("$gen" scene ref2.png mov2.png --angle 135 --scale 0.8 --gain 1.3 --size 256 --seed 11) \
  || fail "gen scene 2"
run 0 symreg ref2.png mov2.png --json reg2.json -q
# shellcheck disable=SC2086
"$gen" check-affine reg2.json $truth 2.0 256 || fail "symreg affine (135 deg)"

# nothing to register: exit 1 naming the counts, no output left
"$gen" scene flat.png flat2.png --flat --size 128 >/dev/null || fail "gen flat"
run 1 symreg flat.png flat2.png --json f.json --overlay f.png -o f2.png
stderr_has "too few loops: REF has 0, MOV 0; a registration needs at least 6"
absent f.json f.png f2.png
run 1 symreg ref.png flat2.png --json f.json
stderr_has "too few loops"
absent f.json
run 1 symreg no-such.png mov.png --json f.json
absent f.json

# shapes: B is A turned 40 degrees and 1.5 times larger
"$gen" silhouette a.png --size 200 || fail "gen silhouette"
"$gen" silhouette b.png --size 260 --angle 40 --scale 1.5 || fail "gen silhouette b"
run 0 shape a.png b.png --json sh.json
"$gen" check-shape sh.json 1.5 40 0.01 0.5 || fail "shape s, phi"
grep -q "^s 1.5" out.txt || fail "shape summary: $(cat out.txt)"
run 0 shape a.png b.png --json - -q && grep -q '"alpha"' out.txt || fail "shape --json -"
"$gen" silhouette e.png --size 64 --empty || fail "gen empty"
run 1 shape a.png e.png --json f.json && stderr_has "no object pixel"
absent f.json
run 0 shape a.png a.png --invert --json inv.json -q  # the black ground as the object

finish
