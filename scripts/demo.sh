#!/usr/bin/env bash
# The showcase job of `make demo`: the project's best default pattern, written
# to a file, with its analysis. Usage: demo.sh PATH_TO_PDS OUT_DIR
set -euo pipefail
pds=$1
out=$2
mkdir -p "$out"

method=jittered
count=4096
seed=1

"$pds" generate "$method" --count "$count" --seed "$seed" --torus -o "$out/points.csv"
"$pds" analyze "$out/points.csv" --torus --plot "$out/points.png" > "$out/analysis.json"
# The spectrum averaged over 10 realisations (consecutive seeds), as an image
# and as radial power and anisotropy, and the pair correlation function.
"$pds" analyze --method "$method" --count "$count" --seed "$seed" --sets 10 --torus \
  --spectrum "$out/spectrum.png" --radial "$out/radial.png" --pcf "$out/pcf.png" > /dev/null

echo "demo: $method, $count points on the unit torus, seed $seed"
echo "  points:   $out/points.csv"
echo "  analysis: $out/analysis.json"
echo "  pictures: $out/points.png $out/spectrum.png $out/radial.png $out/pcf.png"
grep -E '"(count|min_distance|relative_radius)"' "$out/analysis.json" | sed 's/^ */    /'
