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

# The face again, by weighted sample elimination (the field sizes the count).
$pds generate elimination --density $in/face.png --radius-range 0.0035,0.04 --seed 1 -o $in/face-elim.csv
$pds analyze $in/face-elim.csv --plot $img/density-face-elimination.png --dot-radius 0.0018 >/dev/null

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

# Several classes (Wei 2010): radii 0.012, 0.024, 0.048 on the unit torus, the default cross-class
# rule. The placement, dots sized by class; then the spectra of each class alone and of the union,
# each averaged over 4 seeds (the class column split off with awk, or left out by --class-dots).
$pds generate dart-throwing --classes 0.012,0.024,0.048 --torus --seed 1 -o $in/classes.csv
$pds analyze $in/classes.csv --class-dots 0.0025,0.005,0.01 --plot $img/density-classes.png >/dev/null
for seed in 1 2 3 4; do
  $pds generate dart-throwing --classes 0.012,0.024,0.048 --torus --seed $seed -o $in/classes-$seed.csv
  for c in 0 1 2; do
    awk -F, -v c=$c 'NR == 1 { print "x,y" } NR > 1 && $3 == c { print $1 "," $2 }' $in/classes-$seed.csv \
      >$in/class$c-$seed.csv
  done
done
# Frequencies up to K = 128, 64, 32 for classes 0, 1, 2 (each about twice the class's sqrt(N)), so
# that each picture shows its class's dark disc at about the same size.
k=(128 64 32)
for c in 0 1 2; do
  $pds analyze --torus $in/class$c-{1,2,3,4}.csv -K ${k[$c]} --spectrum $img/density-class$c-spectrum.png >/dev/null
done
$pds analyze --torus $in/classes-{1,2,3,4}.csv --class-dots 1,1,1 --spectrum $img/density-classes-spectrum.png \
  --radial $img/density-classes-radial.png >/dev/null
