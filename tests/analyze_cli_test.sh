#!/usr/bin/env bash
# End-to-end checks of `pds analyze` (files, stdin, generated sets, outputs)
# and `pds compare`. Usage: analyze_cli_test.sh PATH_TO_PDS
set -uo pipefail
pds=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_exit CODE CMD...: runs CMD, checks its exit status.
expect_exit() {
  local want=$1; shift
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  [[ $got == "$want" ]] || fail "exit $got (want $want): $* -- $(head -c 300 "$tmp/err")"
}
# png_size FILE: width x height from the IHDR chunk.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{printf "%dx%d", $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'; }
has() { grep -q -- "$2" "$1" || fail "$1 lacks $2"; }

"$pds" generate jittered --count 1024 --torus --seed 1 -o "$tmp/a.csv"
"$pds" generate jittered --count 1024 --torus --seed 2 -o "$tmp/b.npy"

# One file: the foundation's fields plus the new measures.
expect_exit 0 "$pds" analyze "$tmp/a.csv" --torus
for key in '"count": 1024' '"min_distance"' '"relative_radius"' '"sets": 1' '"rho_min"' '"rho_mean"' \
  '"l2_star_discrepancy"' '"star_discrepancy": 0\.' '"low_frequency_power"' '"mean_anisotropy_db"' '"pcf"'; do
  has "$tmp/out" "$key"
done

# Beyond the exact star discrepancy's limit (about 10,000 points in 2D): null.
"$pds" generate random --count 20000 -o "$tmp/big.npy"
expect_exit 0 "$pds" analyze "$tmp/big.npy" --frequencies 8
has "$tmp/out" '"star_discrepancy": null'

# Several files are realisations; '-' reads standard input.
expect_exit 0 "$pds" analyze "$tmp/a.csv" "$tmp/b.npy" --torus
has "$tmp/out" '"sets": 2'
has "$tmp/out" '"files"'
"$pds" analyze - --torus <"$tmp/a.csv" >"$tmp/stdin.json" || fail "analyze - failed"
"$pds" analyze "$tmp/a.csv" --torus >"$tmp/file.json"
diff <(grep -v '"file"' "$tmp/stdin.json") <(grep -v '"file"' "$tmp/file.json") >/dev/null ||
  fail "stdin and file give different measures"

# Generated sets and every output.
expect_exit 0 "$pds" analyze --method random --sets 3 --count 500 --torus -K 32 \
  --spectrum "$tmp/s.png" --radial "$tmp/r.csv" --pcf "$tmp/g.csv" --plot "$tmp/p.svg"
has "$tmp/out" '"method": "random"'
has "$tmp/out" '"sets": 3'
[[ $(head -1 "$tmp/r.csv") == "frequency,power,anisotropy_db" ]] || fail "radial CSV header: $(head -1 "$tmp/r.csv")"
[[ $(wc -l <"$tmp/r.csv") == 33 ]] || fail "radial CSV should have 32 annuli"
[[ $(head -1 "$tmp/g.csv") == "r,g" ]] || fail "PCF CSV header: $(head -1 "$tmp/g.csv")"
[[ $(wc -l <"$tmp/g.csv") == 201 ]] || fail "PCF CSV should have 200 rows"
[[ $(png_size "$tmp/s.png") == 520x520 ]] || fail "spectrum PNG size $(png_size "$tmp/s.png")"
head -c 5 "$tmp/p.svg" | grep -q '<?xml' || fail "plot SVG"
expect_exit 0 "$pds" analyze --method jittered --count 256 --torus --radial "$tmp/r.pdf" --pcf "$tmp/g.png" --plot "$tmp/p.png"
[[ $(png_size "$tmp/p.png") == 816x816 ]] || fail "point PNG size $(png_size "$tmp/p.png")"
[[ $(png_size "$tmp/g.png") == 800x600 ]] || fail "PCF PNG size $(png_size "$tmp/g.png")"
head -c 5 "$tmp/r.pdf" | grep -q '%PDF-' || fail "radial PDF"
# Same seed, same bytes.
"$pds" analyze --method random --sets 2 --count 300 --seed 5 --torus --radial "$tmp/r1.csv" >/dev/null
"$pds" analyze --method random --sets 2 --count 300 --seed 5 --torus --radial "$tmp/r2.csv" >/dev/null
cmp -s "$tmp/r1.csv" "$tmp/r2.csv" || fail "radial CSV differs between runs"

# Bad usage: exit 2 with a message.
expect_exit 2 "$pds" analyze
expect_exit 2 "$pds" analyze "$tmp/a.csv" --method random --count 10
expect_exit 2 "$pds" analyze --method nosuch --count 10
expect_exit 2 "$pds" analyze --method random --count 10 --sets 0
expect_exit 2 "$pds" analyze "$tmp/a.csv" --spectrum "$tmp/s.jpg"
expect_exit 2 "$pds" analyze "$tmp/a.csv" --sets 3
expect_exit 2 "$pds" analyze - - <"$tmp/a.csv"
expect_exit 2 "$pds" analyze --method random --dim 3 --count 100 --spectrum "$tmp/s3.png"
expect_exit 2 "$pds" analyze "$tmp/a.csv" --torus --frequencies 5000

# Any width: 1 to 8 columns get every measure but the spectra; more, distances
# and discrepancies only (docs/analysis.md, Dimensions).
awk 'BEGIN { srand(3); print "a,b,c,d,e"; for (i = 0; i < 300; i++) { printf "%.6f", rand(); for (k = 1; k < 5; k++) printf ",%.6f", rand(); print "" } }' >"$tmp/p5.csv"
expect_exit 0 "$pds" analyze "$tmp/p5.csv" --radius 0.05
for key in '"dim": 5' '"relative_radius": 0\.' '"maximal": false' '"centered_discrepancy": 0\.' \
  '"wrap_around_discrepancy"' '"mixture_discrepancy"' '"spectrum_note": "not computed' '"pcf_note"'; do
  has "$tmp/out" "$key"
done
expect_exit 2 "$pds" analyze "$tmp/p5.csv" --pcf "$tmp/pcf.csv"
awk 'BEGIN { srand(4); for (i = 0; i < 200; i++) { printf "%.6f", rand(); for (k = 1; k < 12; k++) printf ",%.6f", rand(); print "" } }' >"$tmp/p12.csv"
expect_exit 0 "$pds" analyze "$tmp/p12.csv" --radius 0.05
for key in '"dim": 12' '"min_distance": 0\.' '"relative_radius": null' '"relative_radius_note": "undefined past 8' \
  '"maximality_note"' '"l2_star_discrepancy": 0\.' '"mixture_discrepancy": [0-9]'; do
  has "$tmp/out" "$key"
done
"$pds" analyze --help >"$tmp/help" 2>&1
has "$tmp/help" "discrepancies in any"

# The comparison sheet: default methods (whatever the registry holds) and a list.
expect_exit 0 "$pds" compare -n 256 -M 2 -K 16 --panel 100 -o "$tmp/c.png"
[[ $(png_size "$tmp/c.png") =~ ^348x ]] || fail "comparison sheet width $(png_size "$tmp/c.png")"
expect_exit 0 "$pds" compare random regular -n 256 -M 2 -K 16 --panel 100 -o "$tmp/c.svg"
[[ $(png_size "$tmp/c.png") != "" ]] || fail "sheet"
expect_exit 2 "$pds" compare nosuch -o "$tmp/c.png"
expect_exit 2 "$pds" compare random -o "$tmp/c.gif"

if ((failures > 0)); then
  echo "$failures failure(s)"
  exit 1
fi
echo "analyze/compare CLI: all checks passed"
