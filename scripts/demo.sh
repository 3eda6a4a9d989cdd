#!/usr/bin/env bash
# The showcase job of `make demo`: the project's best default pattern, written
# to a file, with its analysis. Usage: demo.sh PATH_TO_PDS OUT_DIR
#
# The pattern: maximal Poisson disk sampling on the unit torus at minimum
# distance 0.0125 by Jones's Voronoi method: dart throwing's distribution run
# to the end, so no further point fits anywhere (about 4400 points, relative
# radius ~0.78; docs/jones.md). The analysis checks the distance and the
# maximality at that radius.
set -euo pipefail
pds=$1
out=$2
mkdir -p "$out"

method=jones
radius=0.0125
seed=1

"$pds" generate "$method" --radius "$radius" --seed "$seed" --torus -o "$out/points.csv"
"$pds" analyze "$out/points.csv" --torus --radius "$radius" --plot "$out/points.png" > "$out/analysis.json"
# The spectrum averaged over 10 realisations (consecutive seeds), as an image
# and as radial power and anisotropy, and the pair correlation function.
"$pds" analyze --method "$method" --radius "$radius" --seed "$seed" --sets 10 --torus \
  --spectrum "$out/spectrum.png" --radial "$out/radial.png" --pcf "$out/pcf.png" > /dev/null

echo "demo: $method (maximal Poisson disk), minimum distance $radius on the unit torus, seed $seed"
echo "  points:   $out/points.csv"
echo "  analysis: $out/analysis.json"
echo "  pictures: $out/points.png $out/spectrum.png $out/radial.png $out/pcf.png"
grep -E '"(count|min_distance|relative_radius|min_distance_holds|maximal)"' "$out/analysis.json" | sed 's/^ */    /'
