# Shared by the command-line test scripts: source it after setting pds=PATH.
# Gives $tmp (removed on exit), ok/bad counters, expect_exit and finish.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0

ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect_exit CODE FRAGMENT -- ARGS...: exit status CODE, and for errors a
# single stderr line containing FRAGMENT. Output is left in $tmp/out.
expect_exit() {
  local code=$1 fragment=$2
  shift 3
  "$pds" "$@" >"$tmp/out" 2>"$tmp/err" </dev/null
  local rc=$?
  if [[ $rc -ne $code ]]; then bad "pds $* exited $rc, expected $code; stderr: $(cat "$tmp/err")"; return; fi
  if [[ $code -ne 0 ]]; then
    if [[ $(wc -l <"$tmp/err") -ne 1 ]]; then bad "pds $*: stderr is not one line: $(cat "$tmp/err")"; return; fi
    if ! grep -qF -- "$fragment" "$tmp/err"; then bad "pds $*: stderr lacks '$fragment': $(cat "$tmp/err")"; return; fi
  fi
  ok
}

# finish NAME: the closing line, and the script's status.
finish() {
  echo "$1: $passed passed, $failed failed"
  [[ $failed -eq 0 ]]
}
