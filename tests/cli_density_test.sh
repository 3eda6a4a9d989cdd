#!/usr/bin/env bash
# End-to-end checks of pds generate's --density, --mask, --polygons and
# --fixed (docs/density.md): outputs honour them, the same seed gives the
# same bytes, bad files and bad combinations exit 2 with one line.
# Usage: cli_density_test.sh PATH_TO_PDS
set -u
pds=$1
source "$(dirname "$0")/cli_lib.sh"
python3 "$(dirname "$0")/../scripts/density_inputs.py" "$tmp/in" || { echo "cannot make the inputs"; exit 1; }
in=$tmp/in

# Density: black at rmin; the gradient is dark in the middle, so the central
# square holds more points than an equal area in a corner.
expect_exit 0 "" -- generate bridson --density "$in/gradient.png" --radius-range 0.01,0.04 --seed 2 -o "$tmp/d.csv"
expect_exit 0 "" -- generate bridson --density "$in/gradient.png" --radius-range 0.01,0.04 --seed 2 -o "$tmp/d2.csv"
cmp -s "$tmp/d.csv" "$tmp/d2.csv" && ok || bad "density: same seed, other bytes"
centre=$(awk -F, 'NR > 1 && $1 > 0.4 && $1 < 0.6 && $2 > 0.4 && $2 < 0.6' "$tmp/d.csv" | wc -l)
corner=$(awk -F, 'NR > 1 && $1 < 0.2 && $2 < 0.2' "$tmp/d.csv" | wc -l)
[[ $centre -gt $((3 * corner)) && $corner -gt 0 ]] && ok || bad "density: centre $centre vs corner $corner"
expect_exit 0 "" -- generate dart-throwing --density "$in/gradient.png" --radius-range 0.01,0.04 --invert -o "$tmp/i.csv"
centre=$(awk -F, 'NR > 1 && $1 > 0.4 && $1 < 0.6 && $2 > 0.4 && $2 < 0.6' "$tmp/i.csv" | wc -l)
corner=$(awk -F, 'NR > 1 && $1 < 0.2 && $2 < 0.2' "$tmp/i.csv" | wc -l)
[[ $corner -gt $((2 * centre)) ]] && ok || bad "--invert: centre $centre vs corner $corner"

# Mask image on other bounds: the "a" of mask.png (a ring of radii 2 and 3.5
# around (4, 5), a bar over x in [7, 9.2]): nothing left of the ring, right
# of the bar or in the ring's hole.
expect_exit 0 "" -- generate bridson --mask "$in/mask.png" --radius 0.05 --bounds 0,0,10,10 -o "$tmp/m.csv"
inband=$(awk -F, 'NR > 1 && ($1 < 0.4 || $1 > 9.3 || (($1 - 4) ^ 2 < 1.9 && ($2 - 5) ^ 2 < 1.9))' "$tmp/m.csv" | wc -l)
total=$(($(wc -l <"$tmp/m.csv") - 1))
[[ $inband -eq 0 && $total -gt 5000 ]] && ok || bad "mask: $inband of $total points where the mask is off"

# Polygons: a square with a square hole.
cat >"$tmp/sq.geojson" <<'JSON'
{"type": "Polygon", "coordinates": [[[0.2, 0.2], [0.8, 0.2], [0.8, 0.8], [0.2, 0.8]], [[0.4, 0.4], [0.6, 0.4], [0.6, 0.6], [0.4, 0.6]]]}
JSON
expect_exit 0 "" -- generate dart-throwing --polygons "$tmp/sq.geojson" --radius 0.02 -o "$tmp/p.csv"
outside=$(awk -F, 'NR > 1 && ($1 < 0.2 || $1 > 0.8 || $2 < 0.2 || $2 > 0.8 || ($1 > 0.4 && $1 < 0.6 && $2 > 0.4 && $2 < 0.6))' "$tmp/p.csv" | wc -l)
[[ $outside -eq 0 && $(wc -l <"$tmp/p.csv") -gt 300 ]] && ok || bad "polygons: $outside points outside"

# Fixed points: the first rows of the output, reported on stderr.
expect_exit 0 "" -- generate bridson --fixed "$in/fixed.csv" --radius 0.05 -o "$tmp/f.csv"
nfixed=$(($(wc -l <"$in/fixed.csv") - 1))
[[ "$(head -$((nfixed + 1)) "$tmp/f.csv" | tail -$nfixed | awk -F, '{printf "%.6f,%.6f\n", $1, $2}')" == "$(tail -$nfixed "$in/fixed.csv" | awk -F, '{printf "%.6f,%.6f\n", $1, $2}')" ]] \
  && ok || bad "fixed points are not the first rows"
grep -q "the first $nfixed of" "$tmp/err" && ok || bad "fixed: no report on stderr: $(cat "$tmp/err")"

# Bad files and bad combinations: exit 2, one line.
echo "not a png" >"$tmp/bad.png"
expect_exit 2 "as PNG" -- generate bridson --density "$tmp/bad.png" --radius-range 0.01,0.02
expect_exit 2 "as PNG" -- generate bridson --mask "$tmp/missing.png" --radius 0.1
expect_exit 2 "--density needs --radius-range" -- generate bridson --density "$in/gradient.png"
expect_exit 2 "min_rho is not taken with a density or a mask" -- generate elimination --density "$in/gradient.png" --radius-range 0.01,0.04 --param min_rho=0.7
expect_exit 2 "--radius-range needs --density" -- generate bridson --radius-range 0.01,0.02
expect_exit 2 "rmin <= rmax" -- generate bridson --density "$in/gradient.png" --radius-range 0.05,0.01
expect_exit 2 "rmin must be positive" -- generate bridson --density "$in/gradient.png" --radius-range 0,0.01
expect_exit 2 "needs --dim 2" -- generate bridson --density "$in/gradient.png" --radius-range 0.01,0.02 --dim 3
expect_exit 2 "not --radius" -- generate bridson --density "$in/gradient.png" --radius-range 0.01,0.02 --radius 0.1
expect_exit 2 "--count is not taken" -- generate bridson --mask "$in/mask.png" --count 100
expect_exit 2 "does not take a density, a mask or fixed points" -- generate sobol --mask "$in/mask.png" --count 10
expect_exit 2 "--invert needs --density" -- generate bridson --radius 0.1 --invert
expect_exit 2 "float32 output is not taken" -- generate bridson --mask "$in/mask.png" --radius 0.1 --dtype float32
expect_exit 2 "surface=1 is not taken" -- generate bridson --mask "$in/mask.png" --radius 0.1 --param surface=1
expect_exit 2 "scipy=1 is not taken" -- generate bridson --mask "$in/mask.png" --radius 0.1 --param scipy=1
expect_exit 2 "all-pairs=1 is not taken" -- generate dart-throwing --mask "$in/mask.png" --radius 0.1 --param all-pairs=1
echo '{"type": "Point", "coordinates": [0, 0]}' >"$tmp/pt.geojson"
expect_exit 2 "is not a Polygon or MultiPolygon" -- generate bridson --polygons "$tmp/pt.geojson" --radius 0.1
echo '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0]' >"$tmp/cut.geojson"
expect_exit 2 "not valid JSON" -- generate bridson --polygons "$tmp/cut.geojson" --radius 0.1
printf 'x,y\n0.5,0.5\n2,0.5\n' >"$tmp/out.csv"
expect_exit 2 "fixed point 2 (2, 0.5) lies outside the domain" -- generate bridson --fixed "$tmp/out.csv" --radius 0.1
printf 'x,y,z\n0.5,0.5,0.5\n' >"$tmp/f3.csv"
expect_exit 2 "fixed points have dimension 3" -- generate bridson --fixed "$tmp/f3.csv" --radius 0.1
printf 'x,y\n0.5,zz\n' >"$tmp/bad.csv"
expect_exit 2 "bad.csv" -- generate bridson --fixed "$tmp/bad.csv" --radius 0.1

# Elimination with a density (count from the field) and with a mask (exact count).
expect_exit 0 "" -- generate elimination --density "$in/gradient.png" --radius-range 0.01,0.04 --seed 2 -o "$tmp/e.csv"
centre=$(awk -F, 'NR > 1 && $1 > 0.4 && $1 < 0.6 && $2 > 0.4 && $2 < 0.6' "$tmp/e.csv" | wc -l)
corner=$(awk -F, 'NR > 1 && $1 < 0.2 && $2 < 0.2' "$tmp/e.csv" | wc -l)
[[ $centre -gt $((3 * corner)) && $corner -gt 0 ]] && ok || bad "elimination density: centre $centre vs corner $corner"
expect_exit 0 "" -- generate elimination --mask "$in/mask.png" --count 2000 --bounds 0,0,10,10 -o "$tmp/em.csv"
inband=$(awk -F, 'NR > 1 && ($1 < 0.4 || $1 > 9.3 || (($1 - 4) ^ 2 < 1.9 && ($2 - 5) ^ 2 < 1.9))' "$tmp/em.csv" | wc -l)
[[ $inband -eq 0 && $(wc -l <"$tmp/em.csv") -eq 2001 ]] && ok || bad "elimination mask: $inband outside"
expect_exit 2 "fixed points are not taken" -- generate elimination --fixed "$tmp/out.csv" --count 10
expect_exit 2 "elimination needs --count" -- generate elimination --mask "$in/mask.png"

# Several classes (Wei 2010): a class column, counts about 16 : 4 : 1, the
# same seed the same bytes, every pair at least its classes' distance apart
# (all pairs, with the given matrix: within 0.03 and 0.05, across 0.04).
expect_exit 0 "" -- generate dart-throwing --classes 0.03,0.06,0.12 --seed 4 -o "$tmp/c.csv"
expect_exit 0 "" -- generate dart-throwing --classes 0.03,0.06,0.12 --seed 4 -o "$tmp/c2.csv"
cmp -s "$tmp/c.csv" "$tmp/c2.csv" && ok || bad "classes: same seed, other bytes"
[[ $(head -1 "$tmp/c.csv") == "x,y,class" ]] && ok || bad "classes header: $(head -1 "$tmp/c.csv")"
read -r n0 n1 n2 < <(awk -F, 'NR > 1 { n[$3]++ } END { print n[0] + 0, n[1] + 0, n[2] + 0 }' "$tmp/c.csv")
[[ $n2 -gt 0 && $((n0 / n2)) -ge 10 && $((n0 / n2)) -le 22 && $((n1 / n2)) -ge 2 && $((n1 / n2)) -le 6 ]] && ok ||
  bad "classes: counts $n0 $n1 $n2"
expect_exit 0 "" -- generate dart-throwing --classes 0.03,0.05 --class-matrix 0.03,0.04,0.04,0.05 --seed 2 -o "$tmp/m.csv"
close=$(awk -F, 'NR > 1 { x[NR] = $1; y[NR] = $2; c[NR] = $3; n = NR }
  END { r[0, 0] = 0.03; r[1, 1] = 0.05; r[0, 1] = r[1, 0] = 0.04
        for (i = 2; i <= n; i++) for (j = 2; j < i; j++) {
          d = (x[i] - x[j]) ^ 2 + (y[i] - y[j]) ^ 2; s = r[c[i], c[j]]
          if (d < s * s * (1 - 1e-12)) bad++ }
        print bad + 0 }' "$tmp/m.csv")
[[ $close -eq 0 ]] && ok || bad "class matrix: $close pairs too close"
expect_exit 0 "" -- generate dart-throwing --classes 0.1,0.2 --dim 3 --torus -o "$tmp/c3.ply"
head -c 200 "$tmp/c3.ply" | grep -q "property int class" && ok || bad "classes: no class property in the PLY"
# pds analyze --class-dots leaves the class column out (2D, the right count) and draws by class.
expect_exit 0 "" -- analyze "$tmp/c.csv" --class-dots 0.002,0.004,0.008 --plot "$tmp/c.png"
grep -q "\"dim\": 2" "$tmp/out" && grep -q "\"count\": $((n0 + n1 + n2))" "$tmp/out" && [[ -s $tmp/c.png ]] && ok ||
  bad "analyze --class-dots: $(head -c 300 "$tmp/out")"
expect_exit 2 "has class 2; 2 radii cover classes 0 to 1" -- analyze "$tmp/c.csv" --class-dots 0.002,0.004
expect_exit 2 "dart-throwing only" -- generate bridson --classes 0.02,0.04
expect_exit 2 "--radius does not apply with --classes" -- generate dart-throwing --classes 0.02 --radius 0.1
expect_exit 2 "not symmetric" -- generate dart-throwing --classes 0.02,0.04 --class-matrix 0.02,0.01,0.015,0.04
expect_exit 2 "class radius must be" -- generate dart-throwing --classes 0.02,-1
expect_exit 2 "--class-matrix needs --classes" -- generate dart-throwing --class-matrix 0.1 --radius 0.1

finish cli_density
