#!/usr/bin/env bash
# Makes docs/surface.md's pictures: scripts/surface_pictures.sh [PATH_TO_PDS]
# (default build/apps/pds/pds). The torus comes from scripts/surface_inputs.py,
# samples go to out/surface/, pictures to docs/images/surface-*.png: the
# samples facing the viewer, projected orthographically (surface_inputs.py
# --project) and drawn by pds analyze --plot (Cairo).
set -euo pipefail
pds=${1:-build/apps/pds/pds}
in=out/surface
img=docs/images
python3 scripts/surface_inputs.py "$in"

# Uniform: 6,000 samples on the torus, written as PLY and CSV.
$pds generate elimination --mesh $in/torus.obj --count 6000 --seed 1 -o $in/torus.ply
$pds generate elimination --mesh $in/torus.obj --count 6000 --seed 1 -o $in/torus.csv
python3 scripts/surface_inputs.py --project $in/torus.csv $in/torus-view.csv
$pds analyze $in/torus-view.csv --plot $img/surface-torus.png --dot-radius 0.0035 >/dev/null

# Per-vertex density: 6 times denser on the outer rim than on the inner side.
$pds generate elimination --mesh $in/torus.obj --vertex-density $in/torus-density.csv --count 6000 --seed 1 \
  -o $in/torus-density-out.csv
python3 scripts/surface_inputs.py --project $in/torus-density-out.csv $in/torus-density-view.csv
$pds analyze $in/torus-density-view.csv --plot $img/surface-torus-density.png --dot-radius 0.0035 >/dev/null
