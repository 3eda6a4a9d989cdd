#!/usr/bin/env bash
# The command line's float32 output, memory budget, progress bar and Ctrl-C.
# Usage: cli_terminal_test.sh PATH_TO_PDS
set -u
pds=$1
source "$(dirname "$0")/cli_lib.sh"

# float32 keeps the radius at an offset where its spacing is 0.0625, and
# refuses a radius it cannot hold.
box=1e6,1e6,1000450,1000450
"$pds" generate bridson --radius 20 --bounds $box --dtype float32 -o "$tmp/f.npy" &&
  "$pds" analyze "$tmp/f.npy" --radius 20 --bounds $box >"$tmp/f.json" &&
  grep -qF '"min_distance_holds": true' "$tmp/f.json" && ok || bad "float32 bridson at 1e6 lost its radius"
expect_exit 2 "float32: radius 10 is too small for float32 coordinates spaced 0.0625" -- \
  generate bridson --radius 10 --bounds $box --dtype float32 -o "$tmp/g.npy"
[[ ! -e "$tmp/g.npy" ]] && ok || bad "a refused float32 request left a file"

# --max-memory: refused before anything runs, with the estimate and the budget.
expect_exit 2 "above the budget of 1 MiB (--max-memory)" -- generate random --count 1000000 --max-memory 1M -o "$tmp/m.npy"
[[ ! -e "$tmp/m.npy" ]] && ok || bad "a refused request left a file"
expect_exit 0 "" -- generate random --count 100000 --max-memory 512M -o "$tmp/m.npy"
expect_exit 2 "--max-memory expects a size such as 512M or 2G, got '12X'" -- generate random --count 10 --max-memory 12X
expect_exit 2 "above the budget" -- generate jones --radius 0.001 --torus --max-memory 10M

# Ctrl-C: exit by the signal (130 in the shell), one line, no file left.
timeout --preserve-status -s INT 1 "$pds" generate best-candidate --count 1000000 -o "$tmp/big.npy" 2>"$tmp/err"
rc=$?
[[ $rc -eq 130 ]] && ok || bad "SIGINT gave exit $rc, expected 130"
grep -qF "pds: interrupted" "$tmp/err" && ok || bad "SIGINT said nothing: $(cat "$tmp/err")"
[[ -z $(ls "$tmp" | grep big) ]] && ok || bad "SIGINT left $(ls "$tmp" | grep big)"

# The bar: on a terminal (script(1) gives one), not elsewhere, not with --quiet.
run="$pds generate best-candidate --count 30000 -o $tmp/bc.npy"
if command -v script >/dev/null; then
  script -qec "$run" /dev/null >"$tmp/tty" && grep -qE "best-candidate \[#*\.*\] [0-9]+/30000 [0-9]+%" "$tmp/tty" &&
    ok || bad "no progress bar on a terminal: $(tr '\r' '\n' <"$tmp/tty" | tail -3)"
  script -qec "$run --quiet" /dev/null >"$tmp/tty" && [[ ! -s "$tmp/tty" ]] && ok || bad "--quiet still drew: $(cat "$tmp/tty")"
fi
$run 2>"$tmp/err" && [[ ! -s "$tmp/err" ]] && ok || bad "progress drawn to a non-terminal: $(cat "$tmp/err")"

expect_exit 0 "" -- render --size 16x16 --spp 1 --quiet -o "$tmp/r.png"

finish cli_terminal
