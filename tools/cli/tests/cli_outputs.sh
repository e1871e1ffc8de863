#!/usr/bin/env bash
# Output safety of the `ssda` tool (docs/cli.md, "Outputs"; issue 22): all or
# nothing across several outputs, temp files deleted on signals and on a
# file-size limit, standard output checked, special files written through,
# long names, fsync. One CTest entry:
#   cli_outputs.sh outputs SSDA GEN CHECK WORKDIR SHIM
# SHIM is fault_shim.c built as a preload library (rename faults, fsync log).
. "$(dirname "$0")/cli_lib.sh" "$@"
shim=$6
# LD_PRELOAD beside an ASan runtime: ASan must not insist on coming first
preload() {
  ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0 LD_PRELOAD=$shim "$@"
}
same() { [ "$(cat "$1")" = "$2" ] || fail "$1 holds '$(head -c 40 "$1")', expected '$2'"; }

"$gen" texture a.png --size 128x128 --seed 3
"$gen" texture b.png --size 128x128 --seed 3 --shift 3,-2
"$gen" wav v.wav --f0 200 --rate 16000 --secs 1 --silence 0.3

# -- every destination is checked before the first rename --------------------
mkdir ov.png pdir && echo OLD >o.json && echo OLD >p.csv
run 1 track a.png b.png --json o.json --overlay ov.png --quiet &&
  stderr_has "cannot write 'ov.png': Is a directory"
same o.json OLD
run 1 compare a.png b.png --json o.json --overlay ov.png --quiet
same o.json OLD
run 1 pitch v.wav --csv p.csv --plot pdir --quiet && stderr_has "'pdir': Is a directory"
same p.csv OLD
run 1 track a.png b.png --overlay pdir/ --quiet && stderr_has "cannot write 'pdir/': Is a directory"
run 1 grad a.png pdir && stderr_has "cannot write 'pdir': Is a directory"
run 1 track a.png b.png --json o.json --overlay no/such/o.png && stderr_has "'no/such/o.png': No such file"
same o.json OLD
no_temp

# -- a rename that still fails puts back what the others replaced ------------
echo OLD >r.json
preload env SSDA_SHIM_FAIL_RENAME=r.png "$ssda" track a.png b.png --json r.json --overlay r.png \
  --quiet >out.txt 2>err.txt
[ $? = 1 ] && stderr_has "cannot write 'r.png'" || fail "failed rename: exit status"
same r.json OLD
[ -e r.png ] && fail "r.png written although its rename failed"
rm -f r.json
preload env SSDA_SHIM_FAIL_RENAME=r.png "$ssda" track a.png b.png --json r.json --overlay r.png \
  --quiet >out.txt 2>err.txt
[ -e r.json ] && fail "r.json (new) left in place after r.png's rename failed"
no_temp

# -- signals: temp files deleted, the tool dies by the signal -----------------
# The overlay is a FIFO nobody reads: opening it waits, with o.json's temp
# file already written. env --default-signal: a background job of a script
# would otherwise start with SIGINT ignored (and an ignored signal stays so).
mkfifo fifo.png
for sig in INT TERM HUP; do
  echo OLD >s.json
  env --default-signal "$ssda" track a.png b.png --json s.json --overlay fifo.png --quiet \
    >/dev/null 2>err.txt &
  pid=$!
  for _ in $(seq 200); do ls s.json.tmp.* >/dev/null 2>&1 && break; sleep 0.05; done
  ls s.json.tmp.* >/dev/null 2>&1 || fail "SIG$sig: no temp file while waiting for the FIFO"
  kill -s "$sig" "$pid"
  { wait "$pid"; } 2>/dev/null   # (not the shell's "Hangup" line)
  st=$?
  [ "$st" = $((128 + $(kill -l "$sig"))) ] || fail "SIG$sig: exit status $st"
  same s.json OLD
  [ -p fifo.png ] || fail "SIG$sig: the FIFO was replaced"
  no_temp
done

# -- a file-size limit (ulimit -f, KB): EFBIG is a failure (exit 1), not a
#    SIGXFSZ kill, and no temp file is left --------------------------------
"$gen" texture big.png --size 600x600 --seed 2
(ulimit -f 64 && exec "$ssda" grad big.png g.png >out.txt 2>err.txt)
st=$?
[ "$st" = 1 ] && stderr_has "File too large" || fail "grad under ulimit -f: exit $st"
absent g.png
(ulimit -f 64 && exec "$ssda" pitch v.wav --hop-ms 0.0625 --csv big.csv --plot ok.png --quiet \
  >out.txt 2>err.txt)
st=$?
[ "$st" = 1 ] && stderr_has "cannot write 'big.csv': File too large" || fail "pitch under ulimit -f: exit $st"
absent big.csv ok.png

# -- standard output: written and flushed, or exit 1 -------------------------
"$gen" crop a.png w.png 37,21,16,16
for cmd in "match a.png w.png --json" "match a.png w.png" "track a.png b.png --quiet" \
           "compare a.png b.png --quiet" "grad a.png gg.png" "pitch v.wav --quiet" \
           "pitch v.wav --csv - --quiet" "track a.png b.png --json - --quiet" "--help" \
           "track --help" "--version"; do
  # shellcheck disable=SC2086
  "$ssda" $cmd >/dev/full 2>err.txt
  st=$?
  [ "$st" = 1 ] && stderr_has "No space left on device" || fail "ssda $cmd > /dev/full: exit $st"
  grep -q "Success" err.txt && fail "ssda $cmd > /dev/full: $(cat err.txt)"
  # shellcheck disable=SC2086
  "$ssda" $cmd >&- 2>err.txt
  st=$?
  [ "$st" = 1 ] && stderr_has "Bad file descriptor" || fail "ssda $cmd >&-: exit $st"
done
# a closed stdout is not taken by an output file: the JSON stays JSON
"$ssda" track a.png b.png --json c.json --quiet >&- 2>err.txt
[ $? = 1 ] && chk track-json c.json 3 -2 1.0 || fail "track --json FILE with stdout closed"
# a reader that has gone is not a failure (| head)
"$ssda" track a.png b.png --json - --quiet 2>err.txt | head -c 1 >/dev/null
st=${PIPESTATUS[0]}
[ "$st" = 0 ] || fail "track --json - | head -c 1: exit $st $(cat err.txt)"

# -- special files: written through, never replaced ---------------------------
run 0 track a.png b.png --json /dev/stdout --quiet && chk track-json out.txt 3 -2 1.0
grep -q "windows (" out.txt && fail "summary printed into --json /dev/stdout"
"$ssda" track a.png b.png --json /dev/stdout --quiet 2>err.txt | cat >piped.json
chk track-json piped.json 3 -2 1.0
run 0 track a.png b.png --json /dev/stderr --quiet && "$check" track-json err.txt 3 -2 1.0 >/dev/null ||
  fail "--json /dev/stderr"
# a character device: a private /dev/null node where we may make one (root),
# else the system's (then nobody can replace it anyway)
if mknod null c 1 3 2>/dev/null; then nul=null; else nul=/dev/null; fi
run 0 grad a.png "$nul" && [ -c "$nul" ] || fail "grad to a character device replaced it"
run 0 track a.png b.png --json "$nul" --overlay "$nul" --quiet && [ -c "$nul" ] || fail "track to $nul"
# a FIFO: written through to its reader
mkfifo p.fifo
timeout 60 cat p.fifo >got.csv &   # (a tool that never opens it: no hang)
run 0 pitch v.wav --csv p.fifo --quiet
wait
[ -p p.fifo ] || fail "the FIFO was replaced"
chk pitch-csv got.csv --f0 200 --voiced 0.4:1.2
# symbolic links: the target is written (atomically), the link stays
mkdir sub && echo OLD >sub/real.json
ln -s sub/real.json link.json && ln -s ../link.json sub/chain.json && ln -s sub/new.json dangling.json
run 0 track a.png b.png --json link.json --quiet && [ -L link.json ] &&
  chk track-json sub/real.json 3 -2 1.0 || fail "symlink output"
chmod 600 sub/real.json
run 0 track a.png b.png --json sub/chain.json --quiet && [ -L sub/chain.json ] && [ -L link.json ] &&
  [ "$(stat -c %a sub/real.json)" = 600 ] || fail "symlink chain output"
run 0 track a.png b.png --json dangling.json --quiet && [ -L dangling.json ] &&
  chk track-json sub/new.json 3 -2 1.0 || fail "dangling symlink output"
ln -s loop1 loop2 && ln -s loop2 loop1
run 1 grad a.png loop1 && stderr_has "Too many levels of symbolic links"
# anything else (a socket here) is refused, not replaced
if /usr/bin/python3 -c 'import socket,sys; socket.socket(socket.AF_UNIX).bind(sys.argv[1])' sock.png; then
  run 1 grad a.png sock.png && stderr_has "not a regular file" && [ -S sock.png ] ||
    fail "socket output"
fi
no_temp

# -- long names: a valid 251- or 255-character name works ---------------------
n251=$(printf 'n%.0s' $(seq 247)).png
n255=$(printf 'n%.0s' $(seq 250)).json
run 0 grad a.png "$n251" && chk png-size "$n251" 128 128
run 0 grad a.png "$n251" && chk png-size "$n251" 128 128   # replaced
run 0 track a.png b.png --json "$n255" --overlay "$n251" --quiet && chk track-json "$n255" 3 -2 1.0
no_temp

# -- fsync: the file and its directory, before success ------------------------
preload env SSDA_SHIM_FSYNC_LOG=fsync.log "$ssda" track a.png b.png --json f.json --overlay f.png \
  --quiet >out.txt 2>err.txt || fail "track under the fsync log: $(cat err.txt)"
for f in f.json f.png; do
  grep -q "/$f\.tmp\.[0-9a-f]*$" fsync.log || fail "$f not fsynced: $(cat fsync.log 2>&1)"
done
grep -qx "$(pwd -P)" fsync.log || fail "directory not fsynced: $(cat fsync.log 2>&1)"
rm -f fsync.log
preload env SSDA_SHIM_FSYNC_LOG=fsync.log "$ssda" grad a.png sub/g.png >out.txt 2>err.txt
grep -q "/sub/g\.png\.tmp\." fsync.log && grep -qx "$(pwd -P)/sub" fsync.log ||
  fail "grad: not fsynced: $(cat fsync.log 2>&1)"

finish
