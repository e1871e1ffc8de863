#!/usr/bin/env bash
# What a new user trying the tool on unseen data ran into (issue 14, the CLI
# items): report the scan that ran, odd margins, messages that name the
# argument, nothing trackable, the work baseline of pitch, reference formats,
# the silence gate, --voicing above --threshold. Two CTest groups:
#   cli_usability.sh track|pitch SSDA GEN CHECK WORKDIR
. "$(dirname "$0")/cli_lib.sh" "$@"

case $group in
track)
  "$gen" texture a.png --size 128x128 --seed 3
  "$gen" texture b.png --size 128x128 --seed 3 --shift 3,-2
  # item 2: the scan that ran is reported: with a prediction a raster scan runs
  # as a predict scan (the same pixel ops), and an explicit --scan raster is warned
  run 0 track a.png b.png --json t.json --quiet && grep -q '"scan":"predict"' t.json ||
    fail "default track JSON does not say scan predict: $(grep -o '"scan":"[a-z]*"' t.json)"
  ops_default=$(grep -o '"pixel_ops":[0-9]*' t.json)
  run 0 track a.png b.png --scan predict --json t.json --quiet &&
    [ "$(grep -o '"pixel_ops":[0-9]*' t.json)" = "$ops_default" ] || fail "default is not a predict scan"
  grep -q "scan predict" out.txt || true
  run 0 track a.png b.png --scan raster --quiet && stderr_has "--scan raster is run as --scan predict"
  run 0 track a.png b.png --scan raster --predict none --json t.json --quiet &&
    grep -q '"scan":"raster"' t.json && ! grep -q "warning" err.txt || fail "--predict none keeps raster"
  run 0 track a.png b.png --quiet && grep -q "scan predict" out.txt || fail "summary lacks the scan: $(cat out.txt)"
  # item 3: an odd margin gives a one-sided range, and says so
  "$gen" texture c.png --size 128x128 --seed 3 --shift -1,-1
  "$gen" texture d.png --size 128x128 --seed 3 --shift 1,1
  # (two placements per axis: both on the border, every vector at_limit)
  run 0 track a.png c.png --window 16 --search 17 --json t.json --quiet &&
    stderr_has "odd margin: dx ranges over -1..+0, dy over -1..+0" &&
    chk track-json t.json -1 -1 1.0 --searched --count ok 0
  run 0 track a.png d.png --window 16 --search 17 --json t.json --quiet &&   # +1 is out of range
    chk track-json t.json 0 0 1.0 --searched --count ok 0
  run 0 track a.png b.png --window 16 --search 40x39 --quiet && stderr_has "dx ranges over -12..+12, dy over -12..+11"
  run 0 track a.png b.png --window 16 --search 40 --quiet && grep -q "odd margin" err.txt && fail "even margin warned"
  # item 5: messages name the argument
  mkdir dir
  run 1 track dir b.png && stderr_has "cannot read 'dir': Is a directory"
  run 1 compare a.png dir && stderr_has "cannot read 'dir': Is a directory"
  run 1 track a.png b.png --overlay dir/ && stderr_has "cannot write 'dir/': Is a directory"
  run 2 track a.png b.png extra.png && stderr_has "unexpected argument 'extra.png'"
  run 2 compare a.png b.png extra.png && stderr_has "unexpected argument 'extra.png'"
  run 2 grad a.png o.png extra.png && stderr_has "unexpected argument 'extra.png'"
  run 2 pitch x.wav extra.wav && stderr_has "unexpected argument 'extra.wav'"
  run 2 track a.png b.png --exclude foo && stderr_has "unexpected argument 'foo': not a value of --exclude"
  # '--' ends the options: a file named like an option, and an option after it
  cp a.png ./-a.png
  run 0 track --quiet -- -a.png b.png && grep -q "^status: " out.txt || fail "track -- -a.png"
  run 2 track a.png b.png -- --quiet && stderr_has "unexpected argument '--quiet' (after '--' every argument is a file name)"
  # item 6: nothing trackable is said; a one-window overlay is not thinned
  "$gen" texture s1.png --size 20x20 --seed 1
  "$gen" texture s2.png --size 20x20 --seed 1 --shift 1,0
  run 0 track s1.png s2.png && stderr_has "nothing to track: every one of the 1 windows is 'edge'"
  "$gen" texture fa.png --size 64x64 --seed 4 --fill 128,0,0,63,63
  run 0 track fa.png fa.png --exclude && stderr_has "nothing to track: of 16 windows 4 excluded"
  run 0 track a.png b.png && grep -q "nothing to track" err.txt && fail "warned with ok windows"
  "$gen" texture r.png --size 400x12 --seed 2
  run 0 track r.png r.png --window 400x12 --search 400x12 --step 1 --overlay o.png &&
    grep -q "overlay draws every" err.txt && fail "one-window overlay thinned: $(cat err.txt)"
  ;;

pitch)
  "$gen" wav v.wav --f0 200 --rate 16000 --secs 1 --silence 0.5
  # item 7: the work baseline counts the frames analysed (not the silent
  # ones), --full reports 100 %, and the default's share is of --full's work
  run 0 pitch v.wav --full && grep -q "= 100.00 % of the full search" out.txt || fail "--full: $(grep work out.txt)"
  full=$(sed -n 's/^work: *\([0-9]*\) differences.*/\1/p' out.txt)
  run 0 pitch v.wav
  read -r d pct base <<<"$(sed -n 's/^work: *\([0-9]*\) differences = \([0-9.]*\) % of the full search (\([0-9]*\).*/\1 \2 \3/p' out.txt)"
  awk -v f="$full" -v b="$base" -v d="$d" -v p="$pct" 'BEGIN {
        if (b < f * 0.997 || b > f) exit 1;               # baseline = --full work, within its half-period lags
        if (p < 100 * d / f || p > 100 * d / f * 1.004) exit 1 }' ||
    fail "default share $pct % of $base vs --full's $full differences"
  grep -q "silent" out.txt || fail "silent frames not reported"
  # item 8: reference formats
  awk 'BEGIN { for (t = 0; t < 1.5; t += 0.01) printf "%.2f,%s\n", t, (t < 0.52 ? 0 : 200) }' >ref.csv
  awk -F, '{ printf "%s %s\n", $1, $2 }' ref.csv >ref_ws.txt
  awk -F, '{ printf "%s\t%s\t0.9\n", $1, $2 }' ref.csv >ref_tab.txt
  awk -F, '{ print $2 }' ref.csv >ref_f0.txt
  for r in ref.csv ref_ws.txt ref_tab.txt; do
    run 0 pitch v.wav --ref "$r" && grep -q "GPE 0.00 % (of [1-9]" out.txt || fail "--ref $r: $(grep vs out.txt)"
  done
  run 0 pitch v.wav --ref ref_f0.txt --ref-hop 0.01 && grep -q "GPE 0.00 % (of [1-9]" out.txt ||
    fail "--ref-hop: $(grep vs out.txt) $(cat err.txt)"
  run 1 pitch v.wav --ref ref_f0.txt && stderr_has "line 1: one column" && stderr_has "--ref-hop"
  run 1 pitch v.wav --ref ref.csv --ref-hop 0.01 && stderr_has "line 1: 2 columns"
  run 2 pitch v.wav --ref-hop 0.01 && stderr_has "--ref-hop needs --ref"
  awk -F, '{ printf "%s %s\n", $2, $1 }' ref.csv >ref_swapped.txt   # f0 first: not increasing
  run 1 pitch v.wav --ref ref_swapped.txt && stderr_has "line 2: time 0 s is not after"
  { head -50 ref.csv; sed -n 40p ref.csv; tail -n +51 ref.csv; } >ref_unsorted.csv
  run 1 pitch v.wav --ref ref_unsorted.csv && stderr_has "line 51:"
  { head -20 ref.csv; echo "0.21,oops"; } >ref_bad.csv
  run 1 pitch v.wav --ref ref_bad.csv && stderr_has "line 21: not numbers"
  awk -F, '{ printf "%d,%s\n", $1 * 1000, $2 }' ref.csv >ref_ms.csv
  run 0 pitch v.wav --ref ref_ms.csv && stderr_has "look like milliseconds"
  awk -F, '{ printf "%s,0\n", $1 }' ref.csv >ref_unvoiced.csv
  run 0 pitch v.wav --ref ref_unvoiced.csv && stderr_has "no frame is voiced in both"
  # a track with no voiced frame (every frame below the gate): the warning
  # is about the track and its options, not the reference's columns
  run 0 pitch v.wav --ref ref.csv --silence 0dB && stderr_has "no frame of the track is voiced" &&
    stderr_has "a lower --silence" && grep -q "check its columns" err.txt &&
    fail "--silence 0dB blamed the reference: $(cat err.txt)"
  run 0 pitch v.wav --ref ref.csv && grep -q "warning" err.txt && fail "warning on a good reference: $(cat err.txt)"
  # item 9: the silence gate: a quiet clean recording (peak about 30 of 32768)
  # keeps its voiced frames by default; --silence sets the gate
  "$gen" wav q.wav --f0 200 --secs 0.5 --silence 0.1 --gain 0.0015
  run 0 pitch q.wav --csv q.csv && chk pitch-csv q.csv --f0 200 --voiced 0.2:0.55 --min-voiced 0.9
  run 0 pitch q.wav --silence -50dB && grep -q "; 0 voiced" out.txt && grep -q "dBFS; --silence" out.txt ||
    fail "--silence -50dB: $(sed -n 2p out.txt)"
  run 0 pitch q.wav --silence 100 && grep -q "; 0 voiced" out.txt || fail "--silence 100: $(sed -n 2p out.txt)"
  run 0 pitch v.wav --silence 0 --csv s.csv && chk pitch-csv s.csv --f0 200 --voiced 0.6:1.4
  run 2 pitch v.wav --silence 10dB && stderr_has "bad --silence"
  run 2 pitch v.wav --silence loud
  # item 10: --voicing above --threshold would change nothing: refused
  run 2 pitch v.wav --voicing 0.5 && stderr_has "--voicing 0.5 is above the dip threshold 0.3"
  run 2 pitch v.wav --threshold 0.2 --voicing 0.25 && stderr_has "above the dip threshold 0.2"
  run 0 pitch v.wav --threshold 0.4 --voicing 0.3
  run 0 pitch v.wav --voicing 0.3
  ;;

*)
  echo "unknown group $group" >&2; exit 2 ;;
esac
finish
