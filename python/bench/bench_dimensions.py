"""Poisson disk in 1 to 8 dimensions: speed and relative radius of every
dimension-generic method, and SciPy's qmc.PoissonDisk in the same run
(figures in docs/dimensions.md and docs/benchmarks.md).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_dimensions.py [--n N] [--scipy-n M]

For each method and dimension: the unit cube (--torus: the unit torus) at the radius where N points
would have relative radius 0.75 (pds.generate sizes radius-only methods so
from a count), one run, wall clock of pds.generate; rho from the set's own
minimum distance. SciPy: PoissonDisk(d, radius=r, seed=1).fill_space() at the
radius for M points in the unit box (SciPy has no torus); its rate in samples
a second is what the speed-up compares, as SciPy at 10^5 points in 6D runs
for a long time. Nothing here is a test: the tests check properties.
"""

import argparse
import math
import platform
import time

import numpy as np
from scipy.stats import qmc as scipy_qmc

import pds


def rho(points, torus, dim):
    """Relative radius: half the minimum distance over the densest packing's
    ball radius for this many points (pds.analyze's figure)."""
    report = pds.analyze(points, torus=torus)
    return report["relative_radius"]


def radius_for(n, dim, rho_target=0.75):
    """The radius at which n points in the unit cube have relative radius rho
    (pds.generate's own count-to-radius rule, kCountRelativeRadius)."""
    densities = {1: 1.0, 2: math.pi / math.sqrt(12), 3: math.pi / math.sqrt(18), 4: math.pi**2 / 16,
                 5: math.pi**2 / (15 * math.sqrt(2)), 6: math.pi**3 / (48 * math.sqrt(3)),
                 7: math.pi**3 / 105, 8: math.pi**4 / 384}
    ball = math.pi ** (dim / 2) / math.gamma(dim / 2 + 1)
    r_max = (densities[dim] / (n * ball)) ** (1 / dim)
    return 2 * rho_target * r_max


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=100_000, help="points a pds run aims at")
    ap.add_argument("--scipy-n", type=int, default=5_000, help="points a SciPy run aims at")
    ap.add_argument("--dims", default="1,2,3,4,5,6,7,8")
    ap.add_argument("--methods", default="bridson,dart-throwing,ebeida,wei,best-candidate")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--torus", action="store_true", help="pds on the unit torus (SciPy stays in the box)")
    args = ap.parse_args()
    where = "torus" if args.torus else "box"
    print(f"# {platform.node()} {platform.processor() or platform.machine()}, threads {args.threads}, pds in the {where}")
    print("| method | D | points | seconds | samples/s | rho |")
    print("|---|---|---|---|---|---|")
    rates = {}
    for d in map(int, args.dims.split(",")):
        for m in args.methods.split(","):
            info = next(x for x in pds.methods() if x["name"] == m)
            if d not in info["dims"]:
                continue
            # Dart throwing runs to saturation; past 5D it is for small sets.
            n = args.n if not (m == "dart-throwing" and d >= 5) else min(args.n, 10_000)
            if m == "best-candidate":
                n = min(n, 20_000)
            r = radius_for(n, d)
            start = time.perf_counter()
            x = pds.generate(m, radius=r, dim=d, torus=args.torus, seed=1, threads=args.threads)
            t = time.perf_counter() - start
            rates[(m, d)] = len(x) / t
            print(f"| {m} | {d} | {len(x)} | {t:.3f} | {len(x) / t:,.0f} | {rho(x, args.torus, d):.3f} |", flush=True)
        if d >= 2:
            r = radius_for(args.scipy_n, d)
            start = time.perf_counter()
            x = scipy_qmc.PoissonDisk(d, radius=r, seed=1).fill_space()
            t = time.perf_counter() - start
            rate = len(x) / t
            speedup = rates.get(("bridson", d), 0) / rate
            print(f"| SciPy PoissonDisk (box) | {d} | {len(x)} | {t:.3f} | {rate:,.0f} | {rho(x, False, d):.3f} |"
                  f" bridson/SciPy {speedup:,.0f}x", flush=True)


if __name__ == "__main__":
    main()
