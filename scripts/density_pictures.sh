#!/usr/bin/env bash
# Makes docs/density.md's pictures: scripts/density_pictures.sh [PATH_TO_PDS]
# (default build/apps/pds/pds). Inputs come from scripts/density_inputs.py,
# points go to out/density/, pictures to docs/images/density-*.png.
set -euo pipefail
pds=${1:-build/apps/pds/pds}
in=out/density
img=docs/images
python3 scripts/density_inputs.py "$in"

# A stippling: dark is dense (black at rmin, white at rmax), dots of half rmin.
$pds generate bridson --density $in/face.png --radius-range 0.0035,0.04 --seed 1 -o $in/face.csv
$pds analyze $in/face.csv --plot $img/density-face.png --dot-radius 0.0018 >/dev/null

# The same field from a gradient, by dart throwing, inverted (light is dense).
$pds generate dart-throwing --density $in/gradient.png --radius-range 0.006,0.03 --invert --seed 1 -o $in/gradient.csv
$pds analyze $in/gradient.csv --plot $img/density-gradient.png --dot-radius 0.0025 >/dev/null

# A mask image ("a": on where dark) with the gradient as the density.
$pds generate bridson --mask $in/mask.png --density $in/gradient.png --radius-range 0.005,0.02 --seed 1 -o $in/mask.csv
$pds analyze $in/mask.csv --plot $img/density-mask.png --dot-radius 0.0022 >/dev/null

# Polygons with a hole (GeoJSON MultiPolygon), uniform radius.
$pds generate bridson --polygons $in/region.geojson --radius 0.015 --seed 1 -o $in/region.csv
$pds analyze $in/region.csv --plot $img/density-polygons.png --dot-radius 0.004 >/dev/null

# Fixed points (a circle and a diagonal 0.025 apart) kept and filled around at 0.05.
$pds generate bridson --fixed $in/fixed.csv --radius 0.05 --seed 1 -o $in/fixed-out.csv
$pds analyze $in/fixed-out.csv --plot $img/density-fixed.png --dot-radius 0.007 >/dev/null
