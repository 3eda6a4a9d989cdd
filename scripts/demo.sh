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
"$pds" analyze "$out/points.csv" --torus > "$out/analysis.json"

echo "demo: $method, $count points on the unit torus, seed $seed"
echo "  points:   $out/points.csv"
echo "  analysis: $out/analysis.json"
grep -E '"(count|min_distance|relative_radius)"' "$out/analysis.json" | sed 's/^ */    /'
