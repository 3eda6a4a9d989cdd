#!/usr/bin/env bash
# pds unbounded and pds chunks (docs/unbounded.md): the chunks of a region are
# the whole region's samples, byte for byte; bad input exits 2 with one line.
# Usage: cli_unbounded_test.sh PATH_TO_PDS
pds=$1
source "$(dirname "$0")/cli_lib.sh"

expect_exit 0 "" -- unbounded -r 1 -s 5 --region -3.5,2,27,19 -o "$tmp/whole.npy"
expect_exit 0 "" -- chunks -r 1 -s 5 --region -3.5,2,27,19 --chunk 6.25 -o "$tmp/chunks"
expect_exit 0 "" -- chunks -r 1 -s 5 --region -3.5,2,27,19 --chunk 40 -o "$tmp/one"
expect_exit 0 "" -- chunks -r 1 -s 5 --region -3.5,2,27,19 --chunk 6.25 -t 1 -o "$tmp/serial"
expect_exit 0 "" -- chunks -r 1 -s 5 --region -3.5,2,27,19 --chunk 6.25 -t 3 -o "$tmp/threads"
expect_exit 0 "" -- unbounded -r 1 -s 6 --region -3.5,2,27,19 -o "$tmp/other.npy"
expect_exit 0 "" -- unbounded -r 1 -s 5 --region 0,0,0,4,4,3 -o "$tmp/cube.csv"
expect_exit 0 "" -- unbounded -r 1 -s 5 --torus -3.5,2,27,19 --region -3.5,2,27,19 -o "$tmp/torus.npy"
expect_exit 0 "" -- chunks -r 1 -s 5 --torus -3.5,2,27,19 --region -3.5,2,27,19 --chunk 9 -o "$tmp/tchunks"

# Reads NPY files with the standard library only; prints "same" when the
# union of the manifest's chunks, sorted lexicographically, has the bytes of
# the whole region's file, and the manifest's counts add up.
check() {
  python3 - "$1" "$2" <<'PY'
import json, struct, sys, os
def load(path):
    data = open(path, 'rb').read()
    assert data[:6] == b'\x93NUMPY'
    n = struct.unpack('<H', data[8:10])[0]
    header = data[10:10 + n].decode()
    body = data[10 + n:]
    assert "'<f8'" in header, header
    values = struct.unpack('<%dd' % (len(body) // 8), body)
    return [tuple(values[i:i + 2]) for i in range(0, len(values), 2)]
whole = load(sys.argv[1])
manifest = json.load(open(os.path.join(sys.argv[2], 'manifest.json')))
union = []
for c in manifest['chunks']:
    pts = load(os.path.join(sys.argv[2], c['file']))
    assert len(pts) == c['count']
    assert all(c['lo'][k] <= p[k] < c['hi'][k] for p in pts for k in range(2)), c['file']
    union += pts
assert manifest['count'] == len(union)
print('same' if sorted(union) == whole and sorted(whole) == whole and len(whole) > 300 else 'different')
PY
}
if [[ $(check "$tmp/whole.npy" "$tmp/chunks") == same ]]; then ok; else bad "chunks differ from the whole region"; fi
if [[ $(check "$tmp/torus.npy" "$tmp/tchunks") == same ]]; then ok; else bad "torus chunks differ from the whole torus"; fi
if [[ $(check "$tmp/torus.npy" "$tmp/chunks") == different ]]; then ok; else bad "the torus gave the plane's set"; fi
if diff -r "$tmp/serial" "$tmp/threads" >/dev/null && diff -r "$tmp/serial" "$tmp/chunks" >/dev/null; then ok; else bad "threads changed the chunk files"; fi
if [[ $(ls "$tmp/chunks" | wc -l) -eq 16 ]]; then ok; else bad "expected 15 chunks and a manifest"; fi
if [[ $(check "$tmp/whole.npy" "$tmp/one") == same ]]; then ok; else bad "one chunk differs from the whole region"; fi
if [[ $(check "$tmp/other.npy" "$tmp/chunks") == different ]]; then ok; else bad "another seed gave the same set"; fi
if [[ $(head -1 "$tmp/cube.csv") == x,y,z && $(wc -l <"$tmp/cube.csv") -gt 20 ]]; then ok; else bad "3D region"; fi

# pds analyze reads a manifest as one set, over the chunks' region: the
# whole region's count, minimum distance and nearest-neighbour mean.
expect_exit 0 "" -- analyze -r 1 "$tmp/chunks/manifest.json"
cp "$tmp/out" "$tmp/a_chunks.json"
expect_exit 0 "" -- analyze -r 1 "$tmp/whole.npy" --bounds -3.5,2,27,19
if python3 - "$tmp/a_chunks.json" "$tmp/out" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
keys = ('count', 'min_distance', 'mean_nn_distance', 'domain')
sys.exit(0 if all(a[k] == b[k] for k in keys) and a['count'] > 300 else 1)
PY
then ok; else bad "analyze of the manifest differs from analyze of the whole region"; fi
cp "$tmp/chunks/manifest.json" "$tmp/chunks/saved.json"
printf '{"format": "pds-chunks", "version": 1, "dim": 2' >"$tmp/chunks/manifest.json"
expect_exit 2 "not valid JSON" -- analyze "$tmp/chunks/manifest.json"
sed 's/"count": 366/"count": 365/' "$tmp/chunks/saved.json" >"$tmp/chunks/manifest.json"
expect_exit 2 "count" -- analyze "$tmp/chunks/manifest.json"
mv "$tmp/chunks/saved.json" "$tmp/chunks/manifest.json"

expect_exit 2 "radius" -- unbounded -r 0 --region 0,0,1,1 -o "$tmp/x.csv"
expect_exit 2 "radius" -- unbounded -r nan --region 0,0,1,1 -o "$tmp/x.csv"
expect_exit 2 "--region needs 4 values" -- unbounded -r 1 --region 0,0,1 -o "$tmp/x.csv"
expect_exit 2 "is empty" -- unbounded -r 1 --region 0,2,1,1 -o "$tmp/x.csv"
expect_exit 2 "above the cap" -- unbounded -r 0.001 --region 0,0,1000,1000 -o "$tmp/x.csv"
expect_exit 2 "2^40 cells" -- unbounded -r 1 --region 1e13,0,1.00000000001e13,1 -o "$tmp/x.csv"
expect_exit 2 "darts_per_cell" -- unbounded -r 1 --darts-per-cell 0 --region 0,0,1,1 -o "$tmp/x.csv"
expect_exit 2 "not inside the torus" -- unbounded -r 1 --torus 0,0,10,10 --region 0,0,11,10 -o "$tmp/x.csv"
expect_exit 2 "5 to 2^40" -- unbounded -r 1 --torus 0,0,3,10 --region 0,0,1,1 -o "$tmp/x.csv"
expect_exit 2 "--torus needs 4" -- unbounded -r 1 --torus 0,0,3 --region 0,0,1,1 -o "$tmp/x.csv"
expect_exit 2 "--chunk" -- chunks -r 1 --region 0,0,10,10 --chunk 0 -o "$tmp/d"
expect_exit 2 "--chunk" -- chunks -r 1 --region 0,0,10,10 --chunk -1 -o "$tmp/d"
expect_exit 2 "10^6 chunks" -- chunks -r 1 --region 0,0,10,10 --chunk 1e-4 -o "$tmp/d"

# pds generate METHOD --unbounded is the same field, for the methods whose
# process it is; the options it cannot take are refused by name.
expect_exit 0 "" -- generate ebeida --unbounded -r 1 -s 5 --region -3.5,2,27,19 -o "$tmp/generated.npy"
if cmp -s "$tmp/generated.npy" "$tmp/whole.npy"; then ok; else bad "generate --unbounded differs from pds unbounded"; fi
expect_exit 0 "" -- generate maximal-darts --unbounded --torus --bounds -3.5,2,27,19 -r 1 -s 5 \
  --region -3.5,2,27,19 -o "$tmp/gtorus.npy"
if cmp -s "$tmp/gtorus.npy" "$tmp/torus.npy"; then ok; else bad "generate --unbounded --torus differs"; fi
expect_exit 0 "" -- generate dart-throwing --unbounded -r 1 -s 5 --region 0,0,0,4,4,3 --dim 3 -o "$tmp/gcube.csv"
if cmp -s "$tmp/gcube.csv" "$tmp/cube.csv"; then ok; else bad "generate dart-throwing --unbounded in 3D differs"; fi
expect_exit 2 "taken by ebeida, maximal-darts and dart-throwing" -- generate bridson --unbounded -r 1 --region 0,0,1,1
expect_exit 2 "--classes does not apply with --unbounded" -- generate dart-throwing --unbounded -r 1 --region 0,0,1,1 --classes 1,2
expect_exit 2 "pds chunks -t" -- generate ebeida --unbounded -r 1 --region 0,0,1,1 -t 2
expect_exit 2 "--bounds (the torus of --unbounded) needs 4" -- generate ebeida --unbounded -r 1 --region 0,0,1,1 --torus --bounds 0,0,0,9,9,9
expect_exit 2 "--region needs --unbounded" -- generate ebeida -r 1 --region 0,0,1,1
expect_exit 2 "needs --region" -- generate ebeida --unbounded -r 1
expect_exit 2 "needs --radius" -- generate ebeida --unbounded --region 0,0,1,1
expect_exit 2 "--count does not apply with --unbounded" -- generate ebeida --unbounded -r 1 -n 5 --region 0,0,1,1
expect_exit 2 "needs --torus" -- generate ebeida --unbounded -r 1 --region 0,0,1,1 --bounds 0,0,1,1
expect_exit 2 "needs --bounds" -- generate ebeida --unbounded -r 1 --region 0,0,1,1 --torus
expect_exit 2 "does not match --region" -- generate ebeida --unbounded -r 1 --region 0,0,1,1 --dim 3
finish cli_unbounded
