#!/usr/bin/env bash
# pds-mpi (docs/unbounded.md): `mpirun -np P pds-mpi chunks ...` writes the
# files of `pds chunks ...`, byte for byte, for P = 1, 2, 3 (more processes
# than this machine's cores: --oversubscribe); bad input exits 2 once; a
# process that cannot write fails the run (exit 1, no manifest), never hangs.
# Usage: cli_mpi_test.sh PATH_TO_PDS PATH_TO_PDS_MPI MPIEXEC
pds=$1 pds_mpi=$2 mpiexec=$3
source "$(dirname "$0")/cli_lib.sh"
# Open MPI as root (CI) and on a machine with fewer cores than processes.
mpi() { timeout 120 "$mpiexec" --allow-run-as-root --oversubscribe -np "$@"; }
export OMPI_MCA_rmaps_base_oversubscribe=1

args=(-r 1 -s 5 --region -3.5,2,27,19 --chunk 6.25)
expect_exit 0 "" -- chunks "${args[@]}" -o "$tmp/one"
args3=(-r 1 -s 2 --torus 0,0,0,4,4,4 --region 0,0,0,4,4,4 --chunk 2)
expect_exit 0 "" -- chunks "${args3[@]}" -o "$tmp/one3"
targs=(-r 1 -s 5 --torus 0,0,20,14 --region 0,0,20,14 --chunk 5)
expect_exit 0 "" -- chunks "${targs[@]}" -o "$tmp/onet"
for p in 1 2 3; do
  if mpi "$p" "$pds_mpi" chunks "${args[@]}" -t 1 -o "$tmp/p$p" >"$tmp/out" 2>"$tmp/err" &&
    diff -r "$tmp/one" "$tmp/p$p" >/dev/null; then ok; else bad "P = $p differs from pds chunks: $(cat "$tmp/err")"; fi
done
if mpi 2 "$pds_mpi" chunks "${args3[@]}" -o "$tmp/p3d" >/dev/null 2>"$tmp/err" && diff -r "$tmp/one3" "$tmp/p3d" >/dev/null
then ok; else bad "3D torus, P = 2 differs: $(cat "$tmp/err")"; fi
if mpi 3 "$pds_mpi" chunks "${targs[@]}" -o "$tmp/pt" >/dev/null 2>"$tmp/err" && diff -r "$tmp/onet" "$tmp/pt" >/dev/null
then ok; else bad "torus, P = 3 differs: $(cat "$tmp/err")"; fi

# Bad input: exit 2, the error said once (by process 0).
mpi 3 "$pds_mpi" chunks -r 1 --region 0,0,10,10 --chunk 0 -o "$tmp/bad" >/dev/null 2>"$tmp/err"
rc=$?
if [[ $rc -eq 2 && $(grep -c "pds-mpi: error: --chunk" "$tmp/err") -eq 1 && ! -e "$tmp/bad/manifest.json" ]]; then ok
else bad "bad --chunk: exit $rc, stderr: $(cat "$tmp/err")"; fi
# A chunk that cannot be written (a directory in its place) on process 1.
mkdir -p "$tmp/blocked/chunk_1_0.npy"
mpi 2 "$pds_mpi" chunks -r 1 --region 0,0,10,10 --chunk 5 -o "$tmp/blocked" >/dev/null 2>"$tmp/err"
rc=$?
if [[ $rc -eq 1 && ! -e "$tmp/blocked/manifest.json" ]] && grep -q "chunk_1_0.npy" "$tmp/err"; then ok
else bad "a failed chunk: exit $rc, stderr: $(cat "$tmp/err")"; fi
finish cli_mpi
