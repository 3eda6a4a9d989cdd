#!/usr/bin/env bash
# End-to-end checks of pds tile, pds render and pds render-sheet: files,
# reproducible bytes, JSON metrics, exit codes. Usage: cli_render_test.sh PATH_TO_PDS
set -u
pds=$1
source "$(dirname "$0")/cli_lib.sh"
is_png() { [[ $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]; }

# tile: a torus pattern; its analysis on the torus agrees with the summary.
expect_exit 0 "" -- tile jittered --count 256 --seed 3 -o "$tmp/t.npy"
grep -qF '"count": 256' "$tmp/out" && grep -qF '"torus_min_distance":' "$tmp/out" && ok || bad "tile summary wrong"
d1=$(grep -F '"torus_min_distance"' "$tmp/out" | tr -dc '0-9.e-')
"$pds" analyze "$tmp/t.npy" --torus >"$tmp/a.json" && d2=$(grep -F '"min_distance"' "$tmp/a.json" | tr -dc '0-9.e-') &&
  [[ "$d1" == "$d2" ]] && ok || bad "tile min distance $d1 differs from analyze --torus ${d2:-}"
"$pds" tile jittered --count 256 --seed 3 -o "$tmp/t2.npy" >/dev/null && cmp -s "$tmp/t.npy" "$tmp/t2.npy" && ok ||
  bad "tile: same seed, different bytes"
expect_exit 2 "unknown method" -- tile nope --count 10 -o "$tmp/x.npy"

# tile + render --tile: a tile written by pds tile draws the same image as the
# sampler that generates that tile itself (same method, count and seed), from
# .npy and from .csv; radius-only methods are sized alike in both.
for method in best-candidate ebeida; do
  for ext in npy csv; do
    "$pds" tile $method --count 300 --seed 4 -o "$tmp/tile.$ext" >/dev/null &&
      "$pds" render --scene zone-plate --tile "$tmp/tile.$ext" --spp 2 --size 40x32 --seed 4 -o "$tmp/from_tile.png" &&
      "$pds" render --scene zone-plate --sampler $method --tile-count 300 --spp 2 --size 40x32 --seed 4 -o "$tmp/direct.png" &&
      cmp -s "$tmp/from_tile.png" "$tmp/direct.png" && ok || bad "render --tile ($method, .$ext) differs from --sampler $method"
  done
done
expect_exit 0 "" -- render --tile "$tmp/tile.csv" --spp 2 --size 16x16 --metrics --reference-spp 4 -o "$tmp/x.png"
grep -qF '"tile_file":' "$tmp/out" && grep -qF '"tile_points":' "$tmp/out" && ok || bad "render --tile metrics"
expect_exit 2 "--sampler does not apply" -- render --tile "$tmp/tile.csv" --sampler bridson --size 8x8 -o "$tmp/x.png"
"$pds" generate random --count 10 --bounds 0,0,2,1 -o "$tmp/wide.csv"
expect_exit 2 "unit torus" -- render --tile "$tmp/wide.csv" --size 8x8 -o "$tmp/x.png"

# render: a PNG, the same bytes for the same seed on any thread count.
expect_exit 0 "" -- render --scene checkerboard --sampler jittered --spp 4 --size 64x48 -o "$tmp/a.png" --threads 1
is_png "$tmp/a.png" && ok || bad "render did not write a PNG"
"$pds" render --scene checkerboard --sampler jittered --spp 4 --size 64x48 -o "$tmp/b.png" --threads 2 &&
  cmp -s "$tmp/a.png" "$tmp/b.png" && ok || bad "render: thread count changed the image"
expect_exit 0 "" -- render --scene zone-plate --sampler tiled:jittered --spp 3 --size 64x64 --tile-count 256 \
  -o "$tmp/z.png" --error "$tmp/e.png" --spectrum "$tmp/s.png" --samples-spectrum "$tmp/ss.png" --reference-spp 16
for key in '"rmse":' '"psnr_db":' '"error_low_frequency_share":' '"tile_period_px":' '"samples_power_on_tile_lattice":'; do
  grep -qF "$key" "$tmp/out" && ok || bad "render metrics lack $key"
done
for f in z e s ss; do is_png "$tmp/$f.png" && ok || bad "render did not write $f.png"; done

# render-sheet: one PNG and one JSON row per panel.
expect_exit 0 "" -- render-sheet --scene checkerboard --samplers jittered,random --spp 1,2 --size 32x32 \
  --reference-spp 4 -o "$tmp/sheet.png"
is_png "$tmp/sheet.png" && [[ $(grep -c '"rmse"' "$tmp/out") -eq 4 ]] && ok || bad "render-sheet output wrong"

# Bad input: exit 2, one line naming the problem.
expect_exit 2 "--size expects WIDTHxHEIGHT" -- render --size 64 -o "$tmp/x.png"
expect_exit 2 "--size must be between" -- render --size 0x10 -o "$tmp/x.png"
expect_exit 2 "--size must be between" -- render --size 4097x10 -o "$tmp/x.png"
expect_exit 2 "tile count must be in" -- render --sampler best-candidate --tile-count 100000000 --size 8x8 -o "$tmp/x.png"
expect_exit 2 "spp (samples per pixel) must be in [1, 1048576], got 0" -- render --spp 0 --size 8x8 -o "$tmp/x.png"
expect_exit 2 "unknown scene 'teapot'" -- render --scene teapot --size 8x8 -o "$tmp/x.png"
expect_exit 2 "unknown filter 'sinc'" -- render --filter sinc --size 8x8 -o "$tmp/x.png"
expect_exit 2 "unknown method 'nope'" -- render --sampler nope --size 8x8 -o "$tmp/x.png"
expect_exit 2 "--reference-spp must be in" -- render --size 8x8 -o "$tmp/x.png" --metrics --reference-spp 0
expect_exit 2 "more than 2^32 reference samples" -- render --size 4096x4096 -o "$tmp/x.png" --metrics --reference-spp 512
expect_exit 2 "sampler jittered takes no method parameters" -- render --size 8x8 -P k=3 -o "$tmp/x.png"
expect_exit 2 "has no parameter 'k'" -- render --sampler tiled:jittered --size 8x8 -P k=3 -o "$tmp/x.png"
expect_exit 1 "cannot write" -- render --size 8x8 -o "$tmp/no/such/dir.png"

finish cli_render
