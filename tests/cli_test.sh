#!/usr/bin/env bash
# End-to-end checks of the pds command line: exit codes, one-line errors,
# reproducible bytes, the analyze JSON. Usage: cli_test.sh PATH_TO_PDS
set -u
pds=$1
source "$(dirname "$0")/cli_lib.sh"

# Help lists every method and the radius convention.
expect_exit 0 "" -- --help
grep -q "jittered" "$tmp/out" && grep -q "minimum distance between any two samples" "$tmp/out" && ok || bad "--help lacks methods"
expect_exit 0 "" -- generate --help
grep -q -- "--count" "$tmp/out" && grep -q "regular" "$tmp/out" && ok || bad "generate --help lacks options or methods"

# Same seed, same bytes; another seed, other points; CSV to stdout by default.
"$pds" generate jittered --count 1024 --seed 5 >"$tmp/a.csv" && "$pds" generate jittered -n 1024 -s 5 -o "$tmp/b.csv" &&
  cmp -s "$tmp/a.csv" "$tmp/b.csv" && ok || bad "same seed gave different bytes"
"$pds" generate jittered --count 1024 --seed 6 >"$tmp/c.csv"
cmp -s "$tmp/a.csv" "$tmp/c.csv" && bad "different seeds gave the same points" || ok
[[ $(head -1 "$tmp/a.csv") == "x,y" && $(wc -l <"$tmp/a.csv") -eq 1025 ]] && ok || bad "CSV header or count wrong"
"$pds" generate random --count 100 --dim 3 -o "$tmp/r.npy" && [[ $(stat -c %s "$tmp/r.npy") -eq $((128 + 100 * 3 * 8)) ]] &&
  ok || bad "3D NPY output has the wrong size"
"$pds" generate random --count 100 --dim 3 -o "$tmp/r32.npy" --dtype float32 &&
  [[ $(stat -c %s "$tmp/r32.npy") -eq $((128 + 100 * 3 * 4)) ]] && ok || bad "float32 NPY output has the wrong size"

# analyze: the JSON object and its fields.
# Every point lies in a stratum of diagonal 0.0442 with a sample in it: maximal at 0.045.
expect_exit 0 "" -- analyze "$tmp/a.csv" --radius 0.045
for key in '"count": 1024' '"dim": 2' '"min_distance":' '"relative_radius":' '"maximal": true'; do
  grep -qF "$key" "$tmp/out" && ok || bad "analyze output lacks $key"
done
"$pds" generate regular --radius 0.125 --torus | "$pds" analyze - --torus --radius 0.2 >"$tmp/reg.json" &&
  grep -qF '"min_distance": 0.125' "$tmp/reg.json" && grep -qF '"count": 64' "$tmp/reg.json" &&
  grep -qF '"maximal": true' "$tmp/reg.json" && ok || bad "regular grid analysis through stdin is wrong"
expect_exit 0 "" -- analyze "$tmp/r.npy"
grep -qF '"dim": 3' "$tmp/out" && ok || bad "NPY analysis lacks dim 3"

# Bad usage and input: exit 2, one line naming the problem.
expect_exit 2 "radius must be positive and finite, got 0" -- generate regular --radius 0
expect_exit 2 "radius must be positive and finite, got nan" -- generate regular --radius nan
expect_exit 2 "radius must be positive and finite, got -1" -- generate regular --radius -1
expect_exit 2 "radius must be positive and finite, got inf" -- generate regular --radius inf
expect_exit 2 "radius 1e-160 is outside [1e-150, 1e150]" -- generate dunbar-humphreys --radius 1e-160 --bounds 0,0,1e-140,1e-140
expect_exit 2 "axis 0 has extent 1e-158, outside [1e-150, 1e150]" -- generate bridson --radius 0.1 --bounds 0,0,1e-158,1
expect_exit 2 "more than 10^6 times thinner than the radius 0.1" -- generate dart-throwing --radius 0.1 --bounds 0,0,1e-100,1
expect_exit 2 "count must be at least 1, got 0" -- generate random --count 0
expect_exit 2 "above the cap" -- generate random --count 200000000
expect_exit 2 "above the cap of 1000" -- generate regular --radius 0.001 --max-points 1000
expect_exit 2 "radius 1e-09 over a domain of volume 1 could produce up to 1.38564e+18 points" -- generate dunbar-humphreys --radius 1e-9 --torus
expect_exit 2 "axis 0 has 1 for radius 0.3" -- generate dunbar-humphreys --radius 0.3 --torus
# Coordinates whose spacing is near a tenth of the radius (2^-6 at 1e14): a clear failure, not a
# hang or a bad set. (At 1e13, a spacing of 2^-9, whether a run finishes a valid set or fails
# depends on where the torus seeds fall.)
expect_exit 1 "the coordinates are too coarse for this radius" -- generate dunbar-humphreys --radius 0.2 --torus \
  --bounds 100000000000000,100000000000000,100000000000002,100000000000002
expect_exit 2 "dimension 9 is not supported (supported: 1-8)" -- generate jittered --count 10 --dim 9
# Strata in any dimension take a count with D near-equal factors, and name the nearest ones.
expect_exit 2 "nearest counts that can: 8 and 16" -- generate jittered --count 10 --dim 4
# ebeida and wei run to 8D through the registry: small sets, spaced by the
# analysis, and ebeida's maximal; 9D is refused.
b8=0,0,0,0,0,0,0,0,1,1,1,1,1,1,1,1
for method in ebeida wei; do
  expect_exit 0 "" -- generate $method --dim 8 --radius 1.1 --bounds $b8 --seed 2 -o "$tmp/${method}8.csv"
  expect_exit 0 "" -- analyze "$tmp/${method}8.csv" --bounds $b8 --radius 1.1
  grep -qF '"min_distance_holds": true' "$tmp/out" && ok || bad "$method 8D: a pair closer than the radius"
  if [[ $method == ebeida ]]; then grep -qF '"maximal": true' "$tmp/out" && ok || bad "ebeida 8D: not maximal"; fi
  expect_exit 2 "dimension 9 is not supported (supported: 1-8)" -- generate $method --dim 9 --radius 1.1
done
expect_exit 2 "dimension 21202 is not supported (supported: 1-21201)" -- generate sobol --count 10 --dim 21202
expect_exit 2 "GiB" -- generate sobol --count 100000000 --dim 21201
expect_exit 2 "axis 0 is empty" -- generate random --count 10 --bounds 1,0,1,1
expect_exit 2 "bounds needs 4 values" -- generate random --count 10 --bounds 0,0,1
expect_exit 2 "non-finite bound" -- generate random --count 10 --bounds 0,0,inf,1
expect_exit 2 "unknown method 'bogus'" -- generate bogus --count 10
expect_exit 2 "random needs --count" -- generate random
expect_exit 2 "--param expects NAME=NUMBER" -- generate random --count 10 --param k
expect_exit 2 "has no parameter 'k'" -- generate random --count 10 --param k=3
expect_exit 2 "unknown point file extension" -- generate random --count 10 -o "$tmp/p.txt"
expect_exit 2 "" -- generate random --count ten
expect_exit 2 "" -- frobnicate
printf 'x,y\n0.1,0.2\n0.3\n' >"$tmp/bad.csv"
expect_exit 2 "bad.csv:3: expected 2 values, found 1" -- analyze "$tmp/bad.csv"
expect_exit 2 "cannot open" -- analyze "$tmp/missing.csv"
printf 'x,y\n0.5,1.5\n' >"$tmp/out_of_box.csv"
expect_exit 2 "lies outside the domain" -- analyze "$tmp/out_of_box.csv"
expect_exit 0 "" -- analyze "$tmp/out_of_box.csv" --bounds 0,0,2,2
expect_exit 2 "radius must be positive and finite" -- analyze "$tmp/a.csv" --radius 0

# Low-discrepancy sequences (docs/low-discrepancy.md): exact values, seed ignored unless
# scrambled, a later range continues the sequence, bad parameters exit 2.
"$pds" generate sobol -n 4 -d 3 >"$tmp/s.csv" && [[ $(sed -n 4p "$tmp/s.csv") == "0.75,0.25,0.25" ]] && ok ||
  bad "sobol's third point is not (3/4, 1/4, 1/4)"
"$pds" generate halton -n 64 -s 1 >"$tmp/h1.csv" && "$pds" generate halton -n 64 -s 2 >"$tmp/h2.csv" &&
  cmp -s "$tmp/h1.csv" "$tmp/h2.csv" && ok || bad "unscrambled halton depends on the seed"
"$pds" generate halton -n 64 -s 1 -P scramble=2 >"$tmp/o1.csv" && "$pds" generate halton -n 64 -s 2 -P scramble=2 >"$tmp/o2.csv" &&
  ! cmp -s "$tmp/o1.csv" "$tmp/o2.csv" && ok || bad "Owen-scrambled halton ignores the seed"
"$pds" generate sobol -n 100 -P scramble=2 -s 3 | tail -n 40 >"$tmp/whole.csv" &&
  "$pds" generate sobol -n 40 -P first=60 -P scramble=2 -s 3 | tail -n 40 >"$tmp/part.csv" &&
  cmp -s "$tmp/whole.csv" "$tmp/part.csv" && ok || bad "sobol --param first does not continue the sequence"
expect_exit 2 "parameter scramble must be an integer in [0, 2]" -- generate sobol -n 10 --param scramble=3
expect_exit 2 "exceed the sequence's 2^32 points" -- generate halton -n 10 --param first=4294967290
expect_exit 2 "exceed the set's size 1024" -- generate hammersley -n 256 --param first=900 --param size=1024
expect_exit 2 "cannot be split into a grid of near-cubic strata" -- generate multi-jittered -n 1021
expect_exit 0 "" -- generate latin-hypercube -n 1000 -d 3

# Failures: exit 1, and nothing half-written.
expect_exit 1 "cannot write" -- generate random --count 10 -o "$tmp/no/such/dir/p.csv"

finish cli
