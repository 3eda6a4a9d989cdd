"""Sobol in 1,000 dimensions x 10^6 points from Python: pds against SciPy, in
one run, with the time to write the same 10^9 doubles as the floor (issue 15;
figures in docs/benchmarks.md). The C++ figure is build/bench/pds_bench
--benchmark_filter=Wide (BM_SobolWide, BM_WriteDoublesWide).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_sobol_wide.py [--points N] [--dim D]

Both libraries make the points in blocks of 10^4 (80 MB each: 10^9 doubles
at once would take 8 GB, twice over in SciPy), each block a new array:
pds.generate(..., first=k) and SciPy's engine.random(10^4), which continue
the same sequence. The floor fills one 80 MB array 100 times (ndarray.fill).
Wall clock, time.perf_counter, one run each. Nothing here is a test.
"""

import argparse
import os
import platform
import time

import numpy as np
import scipy
from scipy.stats import qmc

import pds


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--dim", type=int, default=1000)
    ap.add_argument("--block", type=int, default=10_000)
    args = ap.parse_args()
    n, d, block = args.points, args.dim, args.block
    blocks = n // block
    print(f"Sobol, {d} dimensions x {blocks * block} points ({blocks * block * d:.3g} doubles), blocks of {block}")
    print(f"machine: {platform.machine()}, {os.cpu_count()} CPUs; numpy {np.__version__}, scipy {scipy.__version__}")

    buffer = np.empty((block, d))
    t = time.perf_counter()
    for k in range(blocks):
        buffer.fill(float(k))
    floor = time.perf_counter() - t
    print(f"  write the doubles (ndarray.fill)   {floor:8.3f} s")

    t = time.perf_counter()
    for k in range(blocks):
        pds.generate("sobol", count=block, dim=d, first=k * block)
    ours = time.perf_counter() - t
    print(f"  pds.generate('sobol')              {ours:8.3f} s   {ours / floor:5.2f} x the floor")

    engine = qmc.Sobol(d, scramble=False)
    t = time.perf_counter()
    for k in range(blocks):
        engine.random(block)
    theirs = time.perf_counter() - t
    print(f"  scipy qmc.Sobol(scramble=False)    {theirs:8.3f} s   {theirs / floor:5.2f} x the floor, "
          f"{theirs / ours:5.1f} x pds")

    # The same points: the last block of each.
    last = pds.generate("sobol", count=block, dim=d, first=(blocks - 1) * block)
    engine = qmc.Sobol(d, scramble=False)
    engine.fast_forward((blocks - 1) * block)
    assert last.tobytes() == engine.random(block).tobytes()
    print("  (the last blocks are equal byte for byte)")


if __name__ == "__main__":
    main()
