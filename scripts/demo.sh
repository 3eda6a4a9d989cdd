#!/usr/bin/env bash
# The showcase job of `make demo`: the project's best default pattern, written
# to a file, with its analysis. Usage: demo.sh PATH_TO_PDS OUT_DIR
#
# The pattern: dart throwing on the unit torus at minimum distance 0.0125, run
# until darts keep missing (near-maximal, about 4200 points, relative radius
# ~0.75: the reference Poisson disk distribution; docs/dart-throwing.md).
set -euo pipefail
pds=$1
out=$2
mkdir -p "$out"

method=dart-throwing
radius=0.0125
seed=1

"$pds" generate "$method" --radius "$radius" --seed "$seed" --torus -o "$out/points.csv"
"$pds" analyze "$out/points.csv" --torus --plot "$out/points.png" > "$out/analysis.json"
# The spectrum averaged over 10 realisations (consecutive seeds), as an image
# and as radial power and anisotropy, and the pair correlation function.
"$pds" analyze --method "$method" --radius "$radius" --seed "$seed" --sets 10 --torus \
  --spectrum "$out/spectrum.png" --radial "$out/radial.png" --pcf "$out/pcf.png" > /dev/null

echo "demo: $method, minimum distance $radius on the unit torus, seed $seed"
echo "  points:   $out/points.csv"
echo "  analysis: $out/analysis.json"
echo "  pictures: $out/points.png $out/spectrum.png $out/radial.png $out/pcf.png"
grep -E '"(count|min_distance|relative_radius)"' "$out/analysis.json" | sed 's/^ */    /'
