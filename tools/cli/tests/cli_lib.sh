# cli_lib.sh - shared by the CLI test scripts (cli_test.sh, cli_outputs.sh,
# cli_flow.sh, segment_test.sh, register_test.sh, symreg_test.sh, ...):
# sourced as
#   . cli_lib.sh GROUP SSDA GEN CHECK WORKDIR [EXTRA...]
# It empties WORKDIR, enters it and defines the helpers below; the script
# ends with `finish`. GEN (gen_inputs.c) makes inputs with known motion and
# f0, CHECK (check_outputs.c) checks JSON/CSV/PNG outputs against the known
# answers. Every case states its expected exit code; failed runs must leave
# no output.
set -u
group=$1 ssda=$2 gen=$3 check=$4 work=$5
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0

fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# run EXPECTED_EXIT ARGS...: run ssda, keep stdout/stderr in out.txt/err.txt
run() {
  local want=$1; shift
  "$ssda" "$@" >out.txt 2>err.txt
  local got=$?
  if [ "$got" -ne "$want" ]; then
    fail "ssda $* exited $got, expected $want"; sed 's/^/  stderr: /' err.txt >&2
    return 1
  fi
  return 0
}

# chk ARGS...: run the output checker
chk() { "$check" "$@" || { fail "check $*"; return 1; }; }

# no_temp: no temp file of an output is left in the work folder (any depth)
no_temp() {
  local left
  left=$(find . -name '*.tmp.*' 2>/dev/null)
  [ -z "$left" ] || fail "temp files left: $left"
}

# absent FILES...: none of the files, nor any temp file, may exist
absent() {
  local f
  for f in "$@"; do [ -e "$f" ] && fail "output '$f' exists after a failed run"; done
  no_temp
}

# stderr_has TEXT: the last run's stderr mentions TEXT
stderr_has() { grep -qF -- "$1" err.txt || fail "stderr lacks '$1': $(cat err.txt)"; }

finish() {
  if [ "$failures" -ne 0 ]; then
    echo "$failures failure(s) in group $group" >&2
    exit 1
  fi
  echo "group $group: ok"
  exit 0
}
