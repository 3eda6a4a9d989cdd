#!/usr/bin/env bash
# End-to-end checks of pds generate elimination --mesh (docs/surface.md):
# OBJ, PLY and OFF of the same mesh give the same samples, the count is
# exact, samples lie on the sphere, the PLY header names the columns, bad
# meshes and options that do not apply exit 2 with one line.
# Usage: cli_mesh_test.sh PATH_TO_PDS
set -u
pds=$1
source "$(dirname "$0")/cli_lib.sh"

# A latitude-longitude unit sphere (12 rings, 24 segments) in the three formats.
awk -v dir="$tmp" 'BEGIN {
  R = 12; S = 24; pi = atan2(0, -1); n = 0
  vx[n] = 0; vy[n] = 0; vz[n] = 1; n++
  for (i = 1; i < R; i++) for (j = 0; j < S; j++) {
    t = pi * i / R; p = 2 * pi * j / S
    vx[n] = sin(t) * cos(p); vy[n] = sin(t) * sin(p); vz[n] = cos(t); n++
  }
  vx[n] = 0; vy[n] = 0; vz[n] = -1; south = n; n++
  f = 0
  for (j = 0; j < S; j++) {
    a = 1 + j; b = 1 + (j + 1) % S
    fa[f] = 0; fb[f] = a; fc[f] = b; f++
    for (i = 1; i + 1 < R; i++) {
      a = 1 + (i - 1) * S + j; b = 1 + i * S + j; c = 1 + i * S + (j + 1) % S; d = 1 + (i - 1) * S + (j + 1) % S
      fa[f] = a; fb[f] = b; fc[f] = c; f++
      fa[f] = a; fb[f] = c; fc[f] = d; f++
    }
    a = 1 + (R - 2) * S + j; b = 1 + (R - 2) * S + (j + 1) % S
    fa[f] = a; fb[f] = south; fc[f] = b; f++
  }
  obj = dir "/s.obj"; off = dir "/s.off"; ply = dir "/s.ply"
  printf "OFF\n%d %d 0\n", n, f > off
  printf "ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n", n, f > ply
  for (k = 0; k < n; k++) {
    printf "v %.17g %.17g %.17g\n", vx[k], vy[k], vz[k] > obj
    printf "%.17g %.17g %.17g\n", vx[k], vy[k], vz[k] > off
    printf "%.17g %.17g %.17g\n", vx[k], vy[k], vz[k] > ply
  }
  for (k = 0; k < f; k++) {
    printf "f %d %d %d\n", fa[k] + 1, fb[k] + 1, fc[k] + 1 > obj
    printf "3 %d %d %d\n", fa[k], fb[k], fc[k] > off
    printf "3 %d %d %d\n", fa[k], fb[k], fc[k] > ply
  }
}'

for f in obj off ply; do
  expect_exit 0 "" -- generate elimination --mesh "$tmp/s.$f" --count 500 --seed 3 -o "$tmp/$f.csv"
done
cmp -s "$tmp/obj.csv" "$tmp/off.csv" && cmp -s "$tmp/obj.csv" "$tmp/ply.csv" && ok || bad "OBJ, OFF and PLY differ"
[[ $(head -1 "$tmp/obj.csv") == "x,y,z,nx,ny,nz,face" && $(($(wc -l <"$tmp/obj.csv") - 1)) -eq 500 ]] && ok ||
  bad "header or count: $(head -1 "$tmp/obj.csv"), $(wc -l <"$tmp/obj.csv") lines"
# On the inscribed polyhedron: radius within [cos(pi/12) cos(pi/24)..., 1]; the
# normal points outward; the face index names one of the 528 triangles.
off_surface=$(awk -F, 'NR > 1 { r = sqrt($1*$1 + $2*$2 + $3*$3); if (r > 1 + 1e-12 || r < 0.95 || $1*$4 + $2*$5 + $3*$6 < 0.9 || $7 < 0 || $7 >= 528) n++ } END { print n + 0 }' "$tmp/obj.csv")
[[ $off_surface -eq 0 ]] && ok || bad "$off_surface samples off the sphere or with bad normals/faces"
# --radius sizes the count: 4 pi / (2 sqrt 3 (0.1 / 1.38)^2), near 680.
expect_exit 0 "" -- generate elimination --mesh "$tmp/s.obj" --radius 0.1 -o "$tmp/r.csv"
expect_exit 2 "--mesh does not take min_rho" -- generate elimination --mesh "$tmp/s.obj" --count 100 --param min_rho=0.7 -o "$tmp/x.csv"
expect_exit 2 "--mesh does not take levels" -- generate elimination --mesh "$tmp/s.obj" --count 100 --param levels=1 -o "$tmp/x.csv"
n=$(($(wc -l <"$tmp/r.csv") - 1))
[[ $n -gt 600 && $n -lt 720 ]] && ok || bad "--radius 0.1 gave $n samples"
# PLY output: the header names the columns, then 7 values a sample
# (6 doubles and an int: 52 bytes).
expect_exit 0 "" -- generate elimination --mesh "$tmp/s.obj" --count 100 -o "$tmp/o.ply"
header=$(head -c 400 "$tmp/o.ply" | sed -n '1,/end_header/p')
[[ $header == *"element vertex 100"*"property double nz"*"property int face"*end_header* ]] && ok || bad "PLY header: $header"
size=$(($(wc -c <"$tmp/o.ply") - ${#header} - 1))
[[ $size -eq 5200 ]] && ok || bad "PLY body is $size bytes, expected 5200"
# Per-vertex density: the northern cap (z > 0.5) dense.
awk -F' ' '$1 == "v" { print ($4 > 0.5 ? 9 : 1) }' "$tmp/s.obj" | { echo density; cat; } >"$tmp/density.csv"
expect_exit 0 "" -- generate elimination --mesh "$tmp/s.obj" --vertex-density "$tmp/density.csv" --count 600 -o "$tmp/d.csv"
north=$(awk -F, 'NR > 1 && $3 > 0.6' "$tmp/d.csv" | wc -l)
south=$(awk -F, 'NR > 1 && $3 < -0.6' "$tmp/d.csv" | wc -l)
[[ $north -gt $((4 * south)) ]] && ok || bad "vertex density: north $north, south $south"

# Bad meshes and options.
printf 'v 0 0 0\nv 1 0 0\nf 1 2 5\n' >"$tmp/bad.obj"
expect_exit 2 "bad.obj: not a readable OBJ mesh" -- generate elimination --mesh "$tmp/bad.obj" --count 10 -o "$tmp/x.csv"
printf 'garbage' >"$tmp/bad.ply"
expect_exit 2 "bad.ply: not a PLY file (the first line is not 'ply')" -- generate elimination --mesh "$tmp/bad.ply" --count 10 -o "$tmp/x.csv"
printf 'OFF\n3 1 0\n0 0 0\n' >"$tmp/bad.off"
expect_exit 2 "bad.off: the OFF file ends after 1 of its 3 vertices" -- generate elimination --mesh "$tmp/bad.off" --count 10 -o "$tmp/x.csv"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n' >"$tmp/flat.obj"
expect_exit 2 "has area 0" -- generate elimination --mesh "$tmp/flat.obj" --count 10 -o "$tmp/x.csv"
expect_exit 2 "cannot open" -- generate elimination --mesh "$tmp/none.obj" --count 10 -o "$tmp/x.csv"
expect_exit 2 "unknown mesh file extension" -- generate elimination --mesh "$tmp/s.stl" --count 10 -o "$tmp/x.csv"
expect_exit 2 "elimination only" -- generate bridson --mesh "$tmp/s.obj" --count 10 -o "$tmp/x.csv"
expect_exit 2 "exactly one of --count and --radius" -- generate elimination --mesh "$tmp/s.obj" -o "$tmp/x.csv"
expect_exit 2 "--bounds does not apply" -- generate elimination --mesh "$tmp/s.obj" --count 5 --bounds 0,0,1,1 -o "$tmp/x.csv"
expect_exit 2 "has no parameter 'k'" -- generate elimination --mesh "$tmp/s.obj" --count 5 --param k=3 -o "$tmp/x.csv"
expect_exit 2 "needs one column, got 7" -- generate elimination --mesh "$tmp/s.obj" --vertex-density "$tmp/r.csv" --count 5 -o "$tmp/x.csv"
head -5 "$tmp/density.csv" >"$tmp/short.csv"
expect_exit 2 "4 vertex densities for 266 vertices" -- generate elimination --mesh "$tmp/s.obj" --vertex-density "$tmp/short.csv" --count 5 -o "$tmp/x.csv"
expect_exit 2 "--vertex-density needs --mesh" -- generate bridson --vertex-density "$tmp/density.csv" --radius 0.1 -o "$tmp/x.csv"

finish cli_mesh
