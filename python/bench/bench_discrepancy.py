"""Discrepancies at 10^4 points in 10 dimensions: pds against SciPy, same run.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_discrepancy.py [N] [D]

For each of SciPy's methods (L2-star, CD, WD, MD): pds.discrepancy on every
core, scipy.stats.qmc.discrepancy with workers=1 (its default) and with
workers=-1 (every core), the best of three runs each, and whether the values
agree (pds sums in SciPy's workers=1 order: same double).
"""

import os
import sys
import time

import numpy as np
from scipy.stats import qmc

import pds


def best_of(f, repeats=3):
    best, value = float("inf"), None
    for _ in range(repeats):
        t0 = time.perf_counter()
        value = f()
        best = min(best, time.perf_counter() - t0)
    return best, value


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000
    d = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    x = np.random.default_rng(1).random((n, d))
    print(f"{n} points in {d} dimensions, {os.cpu_count()} CPUs")
    print(f"{'method':<8} {'pds s':>8} {'scipy s':>8} {'scipy -1 s':>10} {'speed-up':>8}  equal")
    for method in ["L2-star", "CD", "WD", "MD"]:
        t_pds, v_pds = best_of(lambda: pds.discrepancy(x, method))
        t_sp, v_sp = best_of(lambda: qmc.discrepancy(x, method=method))
        t_spw, _ = best_of(lambda: qmc.discrepancy(x, method=method, workers=-1))
        print(f"{method:<8} {t_pds:8.3f} {t_sp:8.3f} {t_spw:10.3f} {t_sp / t_pds:7.1f}x  {v_pds == v_sp}")


if __name__ == "__main__":
    main()
