#!/usr/bin/env bash
# CLI tests of the `ssda` tool, one group per CTest entry:
#   cli_test.sh GROUP SSDA GEN CHECK WORKDIR
# GEN (gen_inputs.c) makes inputs with known motion and f0, CHECK
# (check_outputs.c) checks JSON/CSV/PNG outputs against the known answers.
# Every case states its expected exit code; failed runs must leave no output.
. "$(dirname "$0")/cli_lib.sh" "$@"

case $group in
usage)
  run 0 --help && grep -q "usage: ssda" out.txt || fail "ssda --help"
  run 0 --version && grep -q "^ssda [0-9]" out.txt || fail "ssda --version"
  for c in match track compare grad pitch; do
    run 0 "$c" --help && grep -q "usage: ssda $c" out.txt || fail "ssda $c --help"
    run 2 "$c"                       # no arguments
    run 2 "$c" a b c d               # too many
    run 2 "$c" --no-such-option x.png
  done
  run 0 help track && grep -q "usage: ssda track" out.txt || fail "ssda help track"
  run 2
  run 2 frobnicate
  run 2 match a.png b.png --threshold fixed
  run 2 match a.png b.png --threshold ramp:0
  run 2 match a.png b.png --threshold auto-ramp:x
  run 2 match a.png b.png --scan diagonal
  run 2 match a.png b.png --scan predict          # needs --predict
  run 2 match a.png b.png --predict 3
  run 2 match a.png b.png --json=yes              # a flag takes no value
  run 2 match a.png b.png --json x.json && stderr_has "unexpected argument 'x.json' (match --json prints to stdout"
  run 2 track a.png b.png --window 0
  run 2 track a.png b.png --window 16x
  run 2 track a.png b.png --roi 1,2,3
  run 2 track a.png b.png --predict sideways
  run 2 track a.png b.png --mem lots
  run 2 track a.png b.png --json                  # needs a value
  run 2 track a.png b.png --scan coarse && stderr_has "--scan coarse needs --predict none"
  run 2 compare a.png b.png --scan coarse --predict left && stderr_has "--scan coarse needs --predict none"
  run 2 pitch a.wav --fmin 300 --fmax 200
  # the defaults count: --fmin above the default --fmax is a usage error (it
  # was exit 1, refused after reading the file)
  run 2 pitch a.wav --fmin 3000 && stderr_has "must be below --fmax (1000 Hz, the default)"
  run 2 pitch a.wav --fmax 40 && stderr_has "--fmin (50 Hz) must be below --fmax (40 Hz)"
  run 2 pitch a.wav --threshold 0 && stderr_has "(above 0, below 1)"
  run 2 pitch a.wav --hop-ms -1
  run 2 grad a.png b.png --bits 12
  run 2 grad a.png b.png --shift 40
  ;;

kinds)
  # Every PNG kind libpng reads becomes the documented gray (checked pixel by
  # pixel against an independent computation in gen_inputs), and the tool
  # finds the same match in colour, palette, 16-bit and interlaced images.
  "$gen" kinds . || exit 1
  for k in gray1 gray2 gray4 gray8 gray16 ga8 rgb8 rgba8 rgb16 palette palette_trns interlaced; do
    chk png-same "$k.png" "$k.expect.png"
  done
  "$gen" texture t8.png --size 80x72 --seed 5
  "$gen" crop t8.png w8.png 29,33,16,12
  for k in rgb8 rgba8 ga8 palette interlaced; do
    "$gen" texture "t_$k.png" --size 80x72 --seed 5 --kind "$k"
    run 0 match "t_$k.png" w8.png --json && cp out.txt "m_$k.json" && chk match-json "m_$k.json" 29 33 0 true
  done
  "$gen" texture t16.png --size 80x72 --seed 5 --kind gray16
  "$gen" crop t16.png w16.png 29,33,16,12
  run 0 match t16.png w16.png --json && cp out.txt m16.json && chk match-json m16.json 29 33 0 true
  grep -q '"bits":16' m16.json || fail "16-bit match not reported as 16-bit"
  # a 16-bit search and an 8-bit window: the window is widened (v * 257)
  "$gen" texture t16w.png --size 80x72 --seed 5 --kind rgb16
  run 0 match t16w.png w8.png --json && cp out.txt m_mixed.json && chk match-json m_mixed.json 29 33 - true
  ;;

match)
  "$gen" texture s.png --size 96x80 --seed 2
  "$gen" crop s.png w.png 37,21,16,16
  for t in auto none fixed:5000; do
    for sc in raster "predict --predict 30,20"; do
      # shellcheck disable=SC2086
      run 0 match s.png w.png --threshold "$t" --scan $sc --json && cp out.txt m.json &&
        chk match-json m.json 37 21 0 true
    done
  done
  run 0 match s.png w.png --bounds --order spread --json && cp out.txt m.json && chk match-json m.json 37 21 0 true
  # inexact modes: the crop's zero SAD is never cut, so they find it too, flagged not exact
  for t in ramp:8 ramp:8:3 auto-ramp auto-ramp:1.5; do
    run 0 match s.png w.png --threshold "$t" --json && cp out.txt m.json && chk match-json m.json 37 21 0 false || echo "  (threshold $t)" >&2
  done
  # coarse-to-fine: a position on its 8 px grid with SAD 0 is always found;
  # elsewhere it may miss (flagged not exact either way)
  "$gen" crop s.png wg.png 32,16,16,16
  run 0 match s.png wg.png --scan coarse --json && cp out.txt m.json && chk match-json m.json 32 16 0 false
  run 0 match s.png w.png --scan coarse --coarse-step 4 --json && cp out.txt m.json && chk match-json m.json - - - false
  # a fixed threshold below every SAD: all cut, the fallback is flagged not exact
  "$gen" texture other.png --size 16x16 --seed 99
  run 0 match s.png other.png --threshold fixed:1 --json && grep -q '"exact":false' out.txt || fail "all-cut fallback"
  # the early exit does less work than brute force, which does it all
  run 0 match s.png w.png --threshold none --json && grep -q '"completed":5265' out.txt || fail "brute force completes every position"
  # text output names the position
  run 0 match s.png w.png && grep -q "x=37 y=21" out.txt || fail "text output"
  # window larger than the search image: bad input
  run 1 match w.png s.png && stderr_has "larger than"
  ;;

track)
  "$gen" texture a.png --size 128x128 --seed 3
  "$gen" texture b.png --size 128x128 --seed 3 --shift 3,-2
  # default grid: 16 px windows every 16 px, 32 px areas: 6 x 6 fit, 28 edge
  run 0 track a.png b.png --json t.json --overlay o.png --quiet
  chk track-json t.json 3 -2 1.0 --count ok 36 --count edge 28
  chk png-size o.png 896 1024
  grep -q "median of the 36 ok vectors dx=+3.00 dy=-2.00" out.txt || fail "track summary"
  grep -q "every" err.txt && fail "a sparse grid's overlay was thinned: $(cat err.txt)"
  # a grid too dense for the picture (8 px steps at 2x zoom = 16 output px):
  # every 2nd vector of each row and column is drawn, said on stderr; the JSON has all
  "$gen" texture wa.png --size 400x96 --seed 3
  "$gen" texture wb.png --size 400x96 --seed 3 --shift 3,-2
  run 0 track wa.png wb.png --step 8 --json t.json --overlay ow.png --quiet &&
    stderr_has "overlay draws every 2nd vector" && chk png-size ow.png 800 320 &&
    chk track-json t.json 3 -2 1.0 && grep -q '"windows":539,' t.json || fail "dense grid JSON"
  for opts in "--threshold none" "--predict none" "--predict left" "--bounds" "--no-bounds" "--order spread" \
              "--threshold auto-ramp" "--grad" \
              "--window 8 --search 24 --step 8" "--window 12x10 --search 30x20 --step 10x9" \
              "--roi 20,20,80,70"; do
    # shellcheck disable=SC2086
    run 0 track a.png b.png $opts --json t.json && chk track-json t.json 3 -2 1.0 || echo "  (options: $opts)" >&2
  done
  # coarse-to-fine may miss the minimum (the seed's caveat): most windows, not all
  run 0 track a.png b.png --predict none --scan coarse --json t.json && chk track-json t.json 3 -2 0.5
  run 0 track a.png b.png --json - && cp out.txt t2.json && chk track-json t2.json 3 -2 1.0
  # zero motion is drawn as yellow dots, which the legend shows too: at one
  # arrow scale, a still pair's legend band (below the 896 px image) holds more
  # yellow (luma ~204) than a moving pair's, by the dot swatch
  run 0 track a.png a.png --overlay still.png --arrow-scale 4 && run 0 track a.png b.png --overlay moving.png --arrow-scale 4 &&
    ys=$("$check" png-count still.png 200 208 0 950 896 1024) && ym=$("$check" png-count moving.png 200 208 0 950 896 1024) &&
    [ "$ys" -gt $((ym + 10)) ] || fail "no zero-motion dot in the legend ($ys vs $ym yellow pixels)"
  # a picture named other than .png: written as PNG all the same, with a warning
  run 0 track a.png b.png --overlay o.jpg && stderr_has "--overlay 'o.jpg' does not end in .png" &&
    chk png-size o.jpg 896 1024
  run 0 track a.png b.png --overlay O.PNG && grep -q "warning" err.txt && fail "warned about O.PNG"
  # --roi and --step together select the grid: 3 x 2 windows, all inside
  run 0 track a.png b.png --roi 40,40,48,40 --step 16x24 --json t.json &&
    chk track-json t.json 3 -2 1.0 --count ok 6
  # textureless windows: the left 64 columns are flat in both images
  "$gen" texture fa.png --size 128x128 --seed 4 --fill 128,0,0,63,127
  "$gen" texture fb.png --size 128x128 --seed 4 --fill 128,0,0,63,127 --shift -2,1
  # (the default level, the mean, may also exclude a few textured windows)
  run 0 track fa.png fb.png --exclude --json t.json && chk track-json t.json -2 1 0.6 --count edge 28
  grep -c '"excluded"' t.json >/dev/null || fail "no excluded window"
  run 0 track fa.png fb.png --exclude=129:4 --json t.json && chk track-json t.json -2 1 0.6 --count excluded 18
  run 0 track fa.png fb.png --exclude mean:4 --json t.json && chk track-json t.json -2 1 0.6 --count excluded 18
  # fill pixels (GOES style: 12-bit counts, 4095 = fill) in the left 41 columns
  "$gen" texture ga.png --size 128x128 --seed 6 --kind gray16 --max 4000 --fill 4095,0,0,40,127
  "$gen" texture gb.png --size 128x128 --seed 6 --kind gray16 --max 4000 --fill 4095,0,0,40,127 --shift 1,2
  run 0 track ga.png gb.png --mask-value 4095 --json t.json --overlay om.png &&
    chk track-json t.json 1 2 1.0 --count ok 18 --count masked 18 --count edge 28
  run 0 track ga.png gb.png --mask-value 4095 --grad --json t.json &&
    chk track-json t.json 1 2 1.0 --count masked 18
  run 2 track a.png b.png --mask-value 4095        # beyond 8-bit samples
  run 2 track a.png b.png --roi 100,100,64,64      # outside the image
  run 2 track a.png b.png --window 40 --search 32  # area smaller than window
  run 2 track a.png b.png --window 500 && stderr_has "window 500x500, search 1000x1000"  # the default search, resolved
  # a search area equal to the window cannot move: warned (every vector is 0)
  run 0 track a.png b.png --window 16 --search 16 && stderr_has "no room to move: every dx and dy is 0"
  run 0 track a.png b.png --search 32x16 && stderr_has "every dy is 0"
  run 0 track a.png b.png && grep -qE "no room|differ in size" err.txt && fail "warning without cause: $(cat err.txt)"
  # images of different sizes share one coordinate system: accepted with a note
  "$gen" texture bs.png --size 100x90 --seed 3 --shift 3,-2
  run 0 track a.png bs.png --json t.json && stderr_has "images differ in size (FIRST 128 x 128, SECOND 100 x 90)" &&
    chk track-json t.json 3 -2 1.0
  # an area larger than FIRST: every window is EDGE, nothing is searched, and
  # no bounds buffer for it (17 GB for 65535 x 65535 was allocated; found by
  # fuzz_cli). Checked under a 4 GB address-space limit unless ASan (whose
  # shadow memory needs far more) is in the binary.
  limit=unlimited
  nm "$ssda" 2>/dev/null | grep -q __asan_init || limit=4000000
  if (ulimit -v "$limit" && "$ssda" track a.png b.png --search 65535 --json t.json >out.txt 2>err.txt); then
    chk track-json t.json 0 0 0 --no-ok --count edge 64 && grep -q '"bounds":false' t.json ||
      fail "--search 65535: bounds still on"
  else
    fail "--search 65535 failed: $(cat err.txt)"
  fi
  # block-streamed: same vectors within any plate memory, from the minimum
  # (with the left prediction a band of one grid column: 32 x 32 + 16 x 16
  # bytes) up
  for m in 1280 2K 4K 1M; do
    run 0 track a.png b.png --predict left --mem "$m" --json t.json && chk track-json t.json 3 -2 1.0 --count ok 36 &&
      grep -q '"plate_bytes_first"' t.json || fail "--mem $m"
  done
  # below it the run is refused and the message names the size that works
  # (issue 22: it re-read rows without bound; issue 14.4: 47x at 48 B)
  run 2 track a.png b.png --predict left --mem 1279 && grep -q "useful minimum: 1280 bytes" err.txt ||
    fail "--mem 1279: $(cat err.txt)"
  # median prediction (the default) needs the whole grid width (128 x 32 +
  # 128 x 16): it breaks ties and steers the scan from the up-right
  # neighbour, which a strip's right edge lacks
  run 2 track a.png b.png --mem 1K && grep -q "useful minimum: 6144 bytes" err.txt ||
    fail "--mem 1K: $(cat err.txt)"
  run 2 track a.png b.png --threshold auto-ramp --mem 6143 && grep -q "useful minimum: 6144 bytes" err.txt ||
    fail "--threshold auto-ramp --mem 6143: $(cat err.txt)"
  run 0 track a.png b.png --mem 6K --json t.json && chk track-json t.json 3 -2 1.0 --count ok 36
  run 0 track a.png b.png --threshold auto-ramp --mem 6K --json t.json && chk track-json t.json 3 -2 1.0
  run 0 track ga.png gb.png --predict left --mask-value 4095 --mem 3K --json t.json &&
    chk track-json t.json 1 2 1.0 --count ok 18 --count masked 18
  run 0 track a.png b.png --predict left --mem 4K && grep -q "^memory: " out.txt || fail "--mem summary"
  run 2 track a.png b.png --mem 47
  # a plate is never larger than its image: --mem 10G on 128 x 128 images
  # (8-bit: FIRST's plate at most 16384 bytes) allocates what they need (it
  # asked for 10 GB for FIRST's plate),
  # under the same 4 GB limit as above
  if (ulimit -v "$limit" && "$ssda" track a.png b.png --mem 10G --json t.json >out.txt 2>err.txt); then
    chk track-json t.json 3 -2 1.0 --count ok 36 && grep -q '"plate_bytes_first":16384,' t.json ||
      fail "--mem 10G: plates not capped at the images: $(grep -o '"plate_bytes[^,]*' t.json)"
  else
    fail "--mem 10G failed: $(cat err.txt)"
  fi
  ;;

compare)
  "$gen" texture a.png --size 112x112 --seed 7
  "$gen" texture b.png --size 112x112 --seed 7 --shift -3,4
  run 0 compare a.png b.png --json c.json --overlay co.png --quiet && chk compare-json c.json 100
  chk track-json c.json -3 4 1.0
  grep -q "within 1 px: " out.txt || fail "compare summary"
  grep -q "^wrote:   c.json" out.txt && grep -q "^wrote:   co.png" out.txt || fail "compare wrote: lines"
  grep -q '"reference":"ncc"' c.json || fail "compare JSON reference"
  run 0 compare a.png b.png --threshold auto-ramp:0.5 --window 8 --search 24 --step 8 --json c.json &&
    chk compare-json c.json 0
  ;;

grad)
  "$gen" texture g8.png --size 40x30 --seed 8
  "$gen" texture g16.png --size 40x30 --seed 8 --kind gray16
  run 0 grad g8.png o.png && chk grad-same g8.png o.png 2 && chk png-size o.png 40 30 8
  run 0 grad g8.png o16.png --bits 16 && chk grad-same g8.png o16.png 0 && chk png-size o16.png 40 30 16
  run 0 grad g16.png o.png && chk grad-same g16.png o.png 2 && chk png-size o.png 40 30 16
  run 0 grad g16.png o.png --bits 8 && chk grad-same g16.png o.png 10
  run 0 grad g8.png o.png --shift 0 && chk grad-same g8.png o.png 0   # saturates at 255
  stderr_has "saturated"
  run 0 grad g8.png c.png --crop && chk png-size c.png 38 28 8
  # 12-bit counts in a 16-bit PNG (max 3511 here): the default scale comes from
  # the data's maximum (4 x 3511 x 4 fits 16 bits), not from the depth (E' >> 2,
  # 16 times darker, used at most 1/16 of the range: a near-black picture)
  "$gen" texture g12.png --size 40x30 --seed 8 --kind gray16 --max 4095
  run 0 grad g12.png o.png && chk grad-same g12.png o.png -2 && chk png-max o.png 16384 &&
    grep -qF "E' x 4 (input maximum 3511)" out.txt || fail "12-bit grad scaling: $(cat out.txt)"
  run 0 grad g12.png o.png --bits 8 && chk grad-same g12.png o.png 6 && chk png-max o.png 64
  run 0 grad g12.png o.png --shift 2 && chk grad-same g12.png o.png 2   # explicit shift kept
  "$gen" texture tiny.png --size 2x9 --seed 1
  run 1 grad tiny.png x.png && absent x.png
  ;;

pitch)
  # constant 200 Hz after 0.3 s of silence, 16 kHz mono 16-bit
  "$gen" wav v.wav --f0 200 --rate 16000 --secs 1 --silence 0.3
  run 0 pitch v.wav --csv p.csv --plot p.png --quiet &&
    chk pitch-csv p.csv --f0 200 --voiced 0.4:1.2 --silent-before 0.25 --tol 0.01
  grep -q "median 200" out.txt || fail "pitch summary: $(cat out.txt)"
  # frames beyond the plot's f0 range are marked by triangles, named in a legend
  # at the bottom right (nothing is drawn there otherwise)
  "$gen" wav jump.wav --f0 200 --secs 2 --silence 0.3 --jump 500:0.06
  run 0 pitch jump.wav --plot pj.png && n=$("$check" png-count pj.png 0 249 700 515 1100 560) &&
    [ "$n" -gt 100 ] || fail "no legend for the out-of-range triangles ($n)"
  n=$("$check" png-count p.png 0 249 700 515 1100 560) && [ "$n" = 0 ] || fail "out-of-range legend without such frames"
  run 0 pitch v.wav --plot p.jpeg && stderr_has "--plot 'p.jpeg' does not end in .png" && chk png-size p.jpeg 1100 560
  run 0 pitch v.wav --csv - && cp out.txt p2.csv && chk pitch-csv p2.csv --f0 200 --voiced 0.4:1.2
  # a reader that stops early (| head) closes stdout: a quiet end (exit 0, no
  # message, no SIGPIPE death), and the file outputs are complete. 1-sample
  # hops make the CSV (~700 KB) far larger than the pipe's buffer.
  "$ssda" pitch v.wav --hop-ms 0.0625 --plot ph.png --csv - --quiet 2>err.txt | head -1 >head.txt
  st=${PIPESTATUS[0]}
  [ "$st" = 0 ] || fail "pitch --csv - | head -1 exited $st: $(cat err.txt)"
  grep -q "^ssda" err.txt && fail "pitch --csv - | head -1 complained: $(cat err.txt)"   # (LSan may report its suppressions)
  grep -q "^time_s,f0_hz" head.txt || fail "pitch --csv - | head -1: no header"
  chk png-size ph.png 1100 560
  "$gen" texture big1.png --size 640x480 --seed 3
  "$gen" texture big2.png --size 640x480 --seed 3 --shift 1,1
  "$ssda" track big1.png big2.png --step 4 --json - --overlay th.png --quiet 2>err.txt | head -1 >/dev/null
  st=${PIPESTATUS[0]}
  [ "$st" = 0 ] || fail "track --json - | head -1 exited $st: $(cat err.txt)"
  chk png-size th.png 960 848
  run 0 pitch v.wav --full --csv pf.csv && cmp -s <(cut -d, -f1-3 p.csv) <(cut -d, -f1-3 pf.csv) ||
    fail "early exit changed the track"
  run 0 pitch v.wav --hop-ms 5 --csv p.csv && chk pitch-csv p.csv --f0 200 --voiced 0.4:1.2
  # a glide 150 -> 300 Hz, 22.05 kHz stereo float, and a reference file
  "$gen" wav g.wav --glide 150:300 --rate 22050 --secs 1 --silence 0.3 --channels 2 --format float
  run 0 pitch g.wav --csv g.csv && chk pitch-csv g.csv --f0 150:300 --glide-secs 0.3:1.3 --voiced 0.4:1.2 --tol 0.03
  awk 'BEGIN { print "time_s,f0_hz"; for (t = 0; t < 1.3; t += 0.005) printf "%.3f,%.3f\n", t, (t < 0.3 ? 0 : 150 + 150 * (t - 0.3)) }' >ref.csv
  run 0 pitch g.wav --ref ref.csv --plot gp.png && grep -q "GPE 0.00 %" out.txt || fail "reference score: $(cat out.txt)"
  # the header line is optional (the shared reference CSVs have none)
  tail -n +2 ref.csv >ref_nohdr.csv
  run 0 pitch g.wav --ref ref_nohdr.csv && grep -q "GPE 0.00 %" out.txt || fail "headerless reference: $(cat out.txt)"
  # 96 kHz 24-bit: analysed at 48 kHz
  "$gen" wav h.wav --f0 440 --rate 96000 --secs 0.5 --format pcm24
  run 0 pitch h.wav --csv h.csv && chk pitch-csv h.csv --f0 440 --voiced 0.1:0.4
  run 0 pitch v.wav --fmin 100 --fmax 400 --csv p.csv && chk pitch-csv p.csv --f0 200 --voiced 0.4:1.2
  run 2 pitch v.wav --fmax 5000                   # above rate / 4
  "$gen" wav lo.wav --rate 4000 --secs 0.5
  run 1 pitch lo.wav --csv x.csv && stderr_has "8000" && absent x.csv
  "$gen" wav short.wav --rate 16000 --secs 0.01
  run 1 pitch short.wav --csv x.csv --plot x.png && stderr_has "too short" && absent x.csv x.png
  ;;

errors)
  # malformed inputs: exit 1, a message naming the file, no output left behind
  "$gen" texture good.png --size 64x64 --seed 1
  for k in empty text truncated crc huge toomuch; do
    "$gen" bad "$k" "bad_$k.png"
    run 1 grad "bad_$k.png" out.png && stderr_has "bad_$k.png" && absent out.png
    run 1 match "bad_$k.png" good.png --json && stderr_has "bad_$k.png"
    run 1 track good.png "bad_$k.png" --json t.json --overlay o.png && absent t.json o.png
    run 1 compare "bad_$k.png" good.png --json t.json && absent t.json
  done
  run 1 grad bad_huge.png out.png && stderr_has "65535"
  run 1 grad bad_toomuch.png out.png && stderr_has "limit"
  run 1 grad missing.png out.png && stderr_has "missing.png" && absent out.png
  for k in wav-empty wav-text wav-header; do
    "$gen" bad "$k" "bad_$k.wav"
    run 1 pitch "bad_$k.wav" --csv p.csv --plot p.png && stderr_has "bad_$k.wav" && absent p.csv p.png
  done
  run 1 pitch missing.wav --csv p.csv && absent p.csv &&
    stderr_has "cannot open 'missing.wav': No such file or directory"
  grep -q "System error" err.txt && fail "libsndfile's wording: $(cat err.txt)"
  run 1 pitch bad_wav-empty.wav && stderr_has "'bad_wav-empty.wav' is empty, not a sound file"
  run 1 pitch bad_wav-text.wav && stderr_has "'bad_wav-text.wav' is not a sound file libsndfile reads"
  run 1 pitch . && stderr_has "cannot read '.'"
  # an output in a missing folder: exit 1, and the other output is not written either
  "$gen" texture b.png --size 64x64 --seed 1 --shift 1,1
  run 1 track good.png b.png --json t.json --overlay no/such/dir/o.png && absent t.json
  # output modes: a new file gets what fopen would give (0666 minus the umask,
  # not mkstemp's 0600); a replaced file keeps its own mode
  (umask 022 && "$ssda" track good.png b.png --json m.json --overlay m.png >/dev/null) &&
    [ "$(stat -c %a m.json)" = 644 ] && [ "$(stat -c %a m.png)" = 644 ] ||
    fail "new output mode $(stat -c %a m.json m.png)"
  (umask 027 && "$ssda" grad good.png g.png >/dev/null) && [ "$(stat -c %a g.png)" = 640 ] ||
    fail "grad output mode under umask 027: $(stat -c %a g.png)"
  chmod 604 m.json
  (umask 022 && "$ssda" track good.png b.png --json m.json >/dev/null) &&
    [ "$(stat -c %a m.json)" = 604 ] || fail "replaced output mode $(stat -c %a m.json)"
  # a failed run leaves an existing output untouched
  echo old >keep.json
  run 1 track good.png bad_truncated.png --json keep.json
  [ "$(cat keep.json)" = old ] || fail "existing output changed by a failed run"
  ;;

*)
  echo "unknown group $group" >&2; exit 2 ;;
esac
finish
