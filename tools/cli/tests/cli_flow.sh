#!/usr/bin/env bash
# The correlation parts of the tool (issue 16): `ssda match --metric` and
# `ssda flow`, `ssda track --metric`. Four CTest groups:
#   cli_flow.sh match|flow|track|subpixel SSDA GEN CHECK WORKDIR FLOWTOOL
. "$(dirname "$0")/cli_lib.sh" "$@"
flowtool=$6

case $group in
match)
  "$gen" texture a.png --size 96x80 --seed 5
  # a window of a at (37, 32), made darker and flatter (x 0.5 + 90, rounded)
  "$flowtool" crop a.png w.png 37 32 24 20
  "$flowtool" gain w.png g.png 0.5 90
  run 0 match a.png w.png --metric ncc --json && chk match-json out.txt 37 32 0 true &&
    grep -q '"rho":1.000000' out.txt && grep -q '"metric":"ncc"' out.txt ||
    fail "exact copy: $(cat out.txt)"
  run 0 match a.png g.png --metric ncc --json && chk match-json out.txt 37 32 - true ||
    fail "ncc under gain and offset: $(cat out.txt)"
  # inverted contrast: absncc finds it with rho = -1, ncc does not
  "$flowtool" gain w.png inv.png -1 255
  run 0 match a.png inv.png --metric absncc --json && chk match-json out.txt 37 32 - true &&
    grep -q '"rho":-1.000000' out.txt || fail "absncc on the inverse: $(cat out.txt)"
  run 0 match a.png inv.png --metric ncc --json && grep -q '"x":37,"y":32' out.txt &&
    fail "ncc took the inverse"
  # the text says rho and the SAD there
  run 0 match a.png g.png --metric ncc && grep -q "^rho: " out.txt && grep -q "^SAD there: " out.txt ||
    fail "text output: $(cat out.txt)"
  # SAD keeps its JSON, plus rho at its best placement
  run 0 match a.png w.png --json && grep -q '"sad":0' out.txt && grep -q '"rho":1.000000' out.txt ||
    fail "sad JSON lacks rho: $(cat out.txt)"
  # usage
  run 2 match a.png w.png --metric l2 && stderr_has "bad --metric 'l2'"
  run 2 match a.png w.png --metric ncc --threshold none && stderr_has "are SAD options"
  run 2 match a.png w.png --metric ncc --scan coarse && stderr_has "are SAD options"
  run 0 match a.png w.png --metric ncc --predict 3,4 --json && chk match-json out.txt 37 32 0 true
  # a flat window has no rho: refused by name, not placed at (0, 0) as "exact"
  "$flowtool" gain w.png flat.png 0 77
  run 1 match a.png flat.png --metric ncc --json && stderr_has "window 'flat.png' is flat" &&
    [ ! -s out.txt ] || fail "flat window: $(cat out.txt)"
  run 0 match a.png flat.png --json || fail "flat window by SAD"
  # a window above the correlation's 65536 pixels: the message says what to do
  "$gen" texture big.png --size 300x300 --seed 6
  "$flowtool" crop big.png bw.png 10 10 260 260
  run 1 match big.png bw.png --metric ncc && stderr_has "at most 65536 pixels" &&
    stderr_has "crop or reduce 'bw.png'" && stderr_has "--metric sad"
  run 0 match big.png bw.png --json && grep -q '"x":10,"y":10' out.txt || fail "large window by SAD"
  ;;

flow)
  "$gen" texture r.png --size 120x100 --seed 7
  "$gen" texture n.png --size 120x100 --seed 7 --shift 2,-3
  "$flowtool" gain n.png nb.png 1.3 -25
  run 0 flow r.png nb.png --region 20,20,70,60 --json f.json --overlay f.png &&
    "$flowtool" check f.json 2 -3 0.95 || fail "flow under a brightness change"
  [ -s f.png ] || fail "no overlay"
  grep -q "^templates: " out.txt && grep -q "^origin: " out.txt || fail "summary: $(cat out.txt)"
  run 0 flow r.png nb.png --region 20,20,70,60 -q --json q.json &&
    "$flowtool" check q.json 2 -3 0.95 || fail "flow -q"
  [ -s out.txt ] && fail "-q still printed: $(cat out.txt)"
  run 0 flow r.png nb.png --region 20,20,70,60 --tp 16 --tp-step 8 --relax 30 --json f.json &&
    "$flowtool" check f.json 2 -3 0.95 --relaxed || fail "relaxed field"
  run 0 flow r.png nb.png --region 20,20,70,60 --relax-median --subpixel --json - &&
    grep -q '"cleaning":"median"' out.txt || fail "median cleaning: $(head -c 300 out.txt)"
  run 0 flow r.png nb.png --region 20,20,70,60 --metric absncc --radius 0.5 --min-radius 2 \
      --min-std 5 --relax 10 --relax-keep --json f.json && "$flowtool" check f.json 2 -3 0.9
  grep -q "note:" err.txt && fail "a note on a small run: $(cat err.txt)"
  # a long job says so before it starts (killed here after the note: the
  # whole of a 1200 x 1000 image at the defaults is 46 000 templates)
  "$gen" texture big.png --size 1200x1000 --seed 3
  timeout 3 "$ssda" flow big.png big.png >/dev/null 2>err.txt
  stderr_has "templates, up to " && stderr_has "--region X,Y,W,H, a larger --tp-step"
  # errors leave no output
  run 1 flow r.png nb.png --region 110,90,30,30 --json e.json --overlay e.png &&
    stderr_has "must lie inside REF" && absent e.json e.png
  run 1 flow r.png missing.png --json e.json && absent e.json
  run 2 flow r.png && stderr_has "need REF.png and NEXT.png"
  run 2 flow r.png nb.png --tp 1 && stderr_has "bad --tp '1'"
  run 2 flow r.png nb.png --region 1,2,3 && stderr_has "bad --region '1,2,3'"
  run 2 flow r.png nb.png --metric sad && stderr_has "bad --metric 'sad'"
  run 2 flow r.png nb.png --relax-keep && stderr_has "--relax-keep needs --relax N"
  run 2 flow r.png nb.png --relax 5 --relax-median && stderr_has "not both"
  run 0 flow --help && grep -q "composite template" out.txt || fail "help"
  # the overlay's colours as draw.c draws them (red is track's at_limit)
  grep -q "yellow as matched, pink those the" out.txt || fail "help: overlay colours"
  # ssda track cleans its grid too (same fields)
  "$gen" texture n2.png --size 120x100 --seed 7 --shift 2,-3
  run 0 track r.png n2.png --relax 30 --json t.json --quiet &&
    grep -q '"relax_dx":2.0000,"relax_dy":-3.0000' t.json && grep -q '"cleaning":"relax"' t.json ||
    fail "track --relax: $(head -c 400 t.json)"
  run 0 track r.png n2.png --relax-median --json t.json --quiet &&
    grep -q '"cleaning":"median"' t.json && grep -q '"relax_dx"' t.json || fail "track --relax-median"
  # the overlay draws the cleaned field too (it drew only the raw vectors)
  run 0 track r.png n2.png --overlay plain.png --quiet &&
    run 0 track r.png n2.png --relax 30 --overlay relaxed.png --quiet &&
    ! cmp -s plain.png relaxed.png || fail "track --relax: the overlay shows no cleaned vectors"
  run 2 track r.png n2.png --relax 3 --relax-median && stderr_has "not both"
  run 2 track r.png n2.png --relax x && stderr_has "bad --relax 'x'"
  ;;

track)
  # a known motion (2, -3) and a gain and offset change (x 0.6 + 60)
  "$gen" texture r.png --size 120x100 --seed 7
  "$gen" texture n.png --size 120x100 --seed 7 --shift 2,-3
  "$flowtool" gain n.png nb.png 0.6 60
  for m in sad ncc absncc; do
    # rho and sad of every ok window (at least 20 of the 24 searched: the
    # statuses of issue 15 may call a few ambiguous or at_limit) against a
    # double-precision recomputation;
    # with ncc/absncc the placement is the brute-force argmax of rho (|rho|)
    run 0 track r.png nb.png --metric $m --json t.json --quiet &&
      "$flowtool" track-rho r.png nb.png t.json $m 20 &&
      grep -q "\"metric\":\"$m\"" t.json && grep -q '"metric_time_s"' t.json ||
      fail "track --metric $m: $(head -c 400 t.json)"
  done
  # the correlation vectors are the known motion in every ok window
  run 0 track r.png nb.png --metric ncc --json t.json --quiet &&
    "$flowtool" track-check t.json 2 -3 1.0 || fail "ncc vectors under gain"
  grep -q "^metric:  ncc" out.txt || fail "summary line: $(cat out.txt)"
  # inverted contrast: absncc tracks it (rho = -1 at the motion), ncc does not
  # inverted (a trough of rho; SAD calls the windows ambiguous: --unique off)
  "$flowtool" gain n.png ni.png -1 255
  run 0 track r.png ni.png --metric absncc --unique off --json t.json --quiet &&
    "$flowtool" track-check t.json 2 -3 1.0 && grep -q '"rho":-1.000000' t.json ||
    fail "absncc on the inverse"
  run 0 track r.png ni.png --metric ncc --json t.json --quiet &&
    "$flowtool" track-check t.json 2 -3 0.5 && fail "ncc tracked the inverse"
  # With ncc/absncc every searched window (not only SAD's ok ones) is
  # searched again and takes its status from the correlation search: on the
  # inverse SAD calls most windows ambiguous or at_limit, absncc finds the
  # motion in all of them.
  stat_of() { grep -o "\"$1\":[0-9]*" "$2" | tail -n 1 | cut -d: -f2; }
  run 0 track r.png ni.png --json s.json --quiet
  searched=$(($(stat_of ok s.json) + $(stat_of ambiguous s.json) + $(stat_of at_limit s.json)))
  [ "$(stat_of ok s.json)" -lt "$searched" ] || fail "SAD left no window non-ok: no test"
  run 0 track r.png ni.png --metric absncc --json t.json --quiet &&
    "$flowtool" track-status t.json >st.txt && grep -qx "ok $searched at_limit 0" st.txt &&
    "$flowtool" track-check t.json 2 -3 1.0 &&
    "$flowtool" track-rho r.png ni.png t.json absncc "$searched" ||
    fail "absncc on SAD's non-ok windows: $(cat st.txt)"
  grep -q "^status:  $searched ok, 0 flat, 0 ambiguous, 0 at_limit" out.txt ||
    fail "summary counts: $(cat out.txt)"
  # the true motion (9, -3) lies beyond the range (-8..8): the correlation's
  # best is on the border in every window, which is then at_limit
  "$gen" texture far.png --size 120x100 --seed 7 --shift 9,-3
  "$flowtool" gain far.png fari.png -1 255
  run 0 track r.png fari.png --metric absncc --json t.json --overlay t.png &&
    "$flowtool" track-status t.json >st.txt && grep -qx "ok 0 at_limit $searched" st.txt &&
    "$flowtool" track-rho r.png fari.png t.json absncc 0 ||
    fail "absncc beyond the range: $(cat st.txt)"
  stderr_has "$searched of $searched searched windows are 'at_limit'"
  grep -q "^status:  0 ok, 0 flat, 0 ambiguous, $searched at_limit" out.txt ||
    fail "summary counts: $(cat out.txt)"
  # an axis with one placement has no border (track.h): --search 16x32 over
  # a vertical motion is ok, not at_limit, in every window
  "$gen" texture n0.png --size 120x100 --seed 7 --shift 0,-3
  "$flowtool" gain n0.png n0b.png 0.6 60
  run 0 track r.png n0b.png --search 16x32 --metric ncc --json t.json --quiet &&
    "$flowtool" track-status t.json >st.txt && grep -q "at_limit 0$" st.txt &&
    "$flowtool" track-check t.json 0 -3 1.0 || fail "one placement along x: $(cat st.txt)"
  # with cleaning and an overlay; without --metric no rho
  # (sub-pixel vectors relaxed: every ok window within 0.05 px of the motion)
  run 0 track r.png nb.png --metric ncc --relax 10 --json t.json --overlay t.png --quiet &&
    "$flowtool" track-sub t.json 2 -3 0.05 1.0 --relaxed && [ -s t.png ] || fail "ncc + relax"
  run 0 track r.png nb.png --json t.json --quiet && grep -q '"rho"' t.json && fail "rho without --metric"
  grep -q '"metric":"sad"' t.json || fail "default metric not named"
  run 2 track r.png nb.png --metric l1 && stderr_has "bad --metric 'l1'"
  "$gen" texture big.png --size 260x260 --seed 3
  run 2 track big.png big.png --window 257x256 --search 258x258 --metric ncc &&
    stderr_has "at most 65536 pixels" && grep -q "warning" err.txt &&
    fail "refused only after the grid and the tracking: $(cat err.txt)"
  run 0 track --help && grep -q -- "--metric M" out.txt || fail "help"
  # a stronger change (x 0.5 + 100): SAD leaves most windows at_limit; the
  # correlation searches those too and decides their status itself
  "$flowtool" gain n.png nh.png 0.5 100
  run 0 track r.png nh.png --json t.json --quiet && grep -q '"at_limit":1[0-9],' t.json ||
    fail "SAD under x 0.5 + 100: expected 10-19 at_limit: $(grep -o '"ok":.*' t.json)"
  searched=$(($(stat_of ok t.json) + $(stat_of ambiguous t.json) + $(stat_of at_limit t.json)))
  run 0 track r.png nh.png --metric ncc --json t.json --quiet &&
    "$flowtool" track-check t.json 2 -3 1.0 && "$flowtool" track-status t.json >st.txt &&
    grep -qx "ok $searched at_limit 0" st.txt ||
    fail "ncc: SAD's at_limit and ambiguous windows: $(grep -o '"ok":.*' t.json)"
  # an 8-bit image against raw 12-bit counts in a 16-bit PNG: said, since
  # the widened levels (v x 257) are 16 times the counts'
  "$gen" texture h12.png --size 120x100 --seed 7 --shift 2,-3 --kind gray16 --max 4000
  run 0 track r.png h12.png --metric ncc --json t.json --quiet &&
    stderr_has "'r.png' is 8-bit, widened to 16 (v x 257), but the 16-bit 'h12.png' reaches only" &&
    "$flowtool" track-check t.json 2 -3 1.0 || fail "8-bit against 12-bit counts"
  "$gen" texture h16.png --size 120x100 --seed 7 --shift 2,-3 --kind gray16
  run 0 track r.png h16.png --json t.json --quiet && grep -q "note" err.txt &&
    fail "a note on a full-range pair: $(cat err.txt)"
  # a motion beyond the range (9 px, range +-8): the correlation's best on
  # the border is at_limit, never ok
  "$gen" texture n9.png --size 120x100 --seed 7 --shift 9,0
  run 0 track r.png n9.png --metric ncc --json t.json --quiet &&
    grep -q '"at_limit":[1-9]' t.json && ! grep -q '"dx":8,.*"status":"ok"' t.json ||
    fail "ncc on the border: $(grep -o '"ok":.*' t.json)"
  # its warning does not blame a brightness change, which rho does not see
  stderr_has "'at_limit'" && grep -qF "brightness" err.txt && fail "ncc warning: $(cat err.txt)"
  ;;

subpixel)
  # track's sub-pixel vectors with --metric and with cleaning. A texture
  # moved by (9, -5) px and shrunk 4 x: a motion of (2.25, -1.25) px.
  "$gen" texture r4.png --size 480x400 --seed 7
  "$gen" texture n4.png --size 480x400 --seed 7 --shift 9,-5
  "$flowtool" shrink r4.png r.png 4 && "$flowtool" shrink n4.png n.png 4
  # the plain SAD tracking: sub-pixel vectors near the motion
  run 0 track r.png n.png --json t.json --quiet &&
    "$flowtool" track-sub t.json 2.25 -1.25 0.2 0.9 || fail "SAD sub-pixel vectors"
  # the correlation's vectors replace SAD's, their fractions too: under a
  # gain and offset change SAD's fractions belong to other placements
  "$flowtool" gain n.png nb.png 0.6 60
  run 0 track r.png nb.png --metric ncc --json t.json --quiet &&
    "$flowtool" track-sub t.json 2.25 -1.25 0.2 0.9 || fail "ncc: sub_dx, sub_dy are not rho's"
  # inverted (a trough of rho; SAD calls the windows ambiguous: --unique off)
  "$flowtool" gain n.png ni.png -1 255
  run 0 track r.png ni.png --metric absncc --unique off --json t.json --quiet &&
    "$flowtool" track-sub t.json 2.25 -1.25 0.2 0.9 || fail "absncc: sub_dx, sub_dy are not rho's"
  run 0 track r.png nb.png --metric ncc --no-subpixel --json t.json --quiet &&
    "$flowtool" track-check t.json 2 -1 0.9 && "$flowtool" track-sub t.json 2 -1 0 0.9 &&
    grep -q '"subpixel":false' t.json || fail "ncc --no-subpixel: whole pixels"
  # the cleaning reads the sub-pixel vectors: a vector it keeps keeps its fraction
  for clean in "--relax 30" "--relax-median"; do
    run 0 track r.png n.png $clean --json t.json &&
      "$flowtool" track-sub t.json 2.25 -1.25 0.2 0.9 --relaxed ||
      fail "track $clean: cleaned vectors lost their fraction"
    grep -q "^cleaning: .* of the [0-9]* ok vectors changed" out.txt || fail "summary: $(cat out.txt)"
  done
  # --relax-keep: a vector whose class stays its own is its input exactly
  run 0 track r.png n.png --relax 30 --relax-keep --json t.json --quiet &&
    "$flowtool" track-sub t.json 2.25 -1.25 0.2 0.9 --relaxed --kept &&
    grep -q '"relax_keep":true' t.json || fail "track --relax-keep"
  run 2 track r.png n.png --relax-keep && stderr_has "--relax-keep needs --relax N"
  ;;
esac
finish
