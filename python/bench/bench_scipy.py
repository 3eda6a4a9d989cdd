"""pds from Python against SciPy, in one run (figures in docs/benchmarks.md).

    PYTHONPATH=build/python PDS_BENCH_CPP=build/python/bench/pds_cpp_time \
        /usr/bin/python3 python/bench/bench_scipy.py [--quick]

Measures, best of several repetitions (wall clock, time.perf_counter):
  1. PoissonDisk(...).fill_space(): scipy.stats.qmc (one run: it takes
     seconds) against pds.qmc (median of 21), 2D and 3D, with the default
     method (SciPy's own loop, run by pds's bridson with scipy=1) and the
     maximal ones;
  2. a whole call of pds.generate for 100 points (its overhead bounds);
  3. pds.generate for about 10^6 points against the C++ library's own time
     for the same request (pds_cpp_time, built with the module).
Nothing here is a test: the tests check properties, this prints times.
"""

import os
import platform
import subprocess
import sys
import time

import numpy as np
import scipy
from scipy.stats import qmc as scipy_qmc

import pds
from pds import qmc as pds_qmc


def timed(f, repeat):
    """(best, median) seconds of f() and its last result; each result is
    dropped before the next call, as the C++ side frees its points."""
    times = []
    result = None
    for _ in range(repeat):
        result = None
        start = time.perf_counter()
        result = f()
        times.append(time.perf_counter() - start)
    times.sort()
    return times[0], times[len(times) // 2], result


def best(f, repeat):
    t, _, result = timed(f, repeat)
    return t, result


def machine():
    cpu = platform.processor() or "?"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{cpu}, {os.cpu_count()} cores; Python {platform.python_version()}, NumPy {np.__version__}, SciPy {scipy.__version__}"


def main():
    quick = "--quick" in sys.argv
    print(f"# {machine()}; load average {os.getloadavg()[0]:.1f} at the start")
    print("| call | points (SciPy / pds) | SciPy, one run | pds, median of 21 (best) | speed-up (medians) |")
    print("|---|---|---|---|---|")
    cases = [(2, 0.005), (3, 0.05)] if not quick else [(2, 0.02), (3, 0.1)]
    for d, r in cases:
        t_scipy, s = best(lambda: scipy_qmc.PoissonDisk(d, radius=r, seed=1).fill_space(), 1)
        for method in ("bridson", "wei", "ebeida") if d == 3 else ("bridson", "dunbar-humphreys"):
            extra = "" if method == "bridson" else f", method='{method}'"
            b_pds, m_pds, p = timed(lambda: pds_qmc.PoissonDisk(d, radius=r, seed=1, method=method).fill_space(), 21)
            print(
                f"| `PoissonDisk(d={d}, radius={r}{extra}).fill_space()` | {len(s)} / {len(p)} | {t_scipy:.2f} s | "
                f"{m_pds * 1e3:.1f} ms ({b_pds * 1e3:.1f} ms) | {t_scipy / m_pds:,.0f}x |"
            )
    print()
    t_small, _ = best(lambda: pds.generate("random", count=100), 2000)
    t_small_r, _ = best(lambda: pds.generate("bridson", count=100), 2000)
    print(f"pds.generate('random', count=100): {t_small * 1e6:.1f} us a call, the whole call (best of 2000)")
    print(f"pds.generate('bridson', count=100): {t_small_r * 1e6:.1f} us a call (best of 2000)")
    t_q, _ = best(lambda: pds_qmc.PoissonDisk(2, radius=0.1, seed=1).random(100), 2000)
    print(f"pds.qmc.PoissonDisk(2, radius=0.1).random(100) (a new engine each call): {t_q * 1e6:.1f} us")
    cpp = os.environ.get("PDS_BENCH_CPP")
    for method, sizing in (("random", {"count": 1_000_000}), ("jittered", {"count": 1_000_000}), ("bridson", {"radius": 0.0008})):
        repeat = 5 if method == "bridson" else 21
        t_py, m_py, pts = timed(lambda: pds.generate(method, seed=1, **sizing), repeat)
        line = f"pds.generate('{method}', {sizing}): {len(pts)} points, median {m_py * 1e3:.1f} ms (best {t_py * 1e3:.1f})"
        if cpp:
            key, value = next(iter(sizing.items()))
            out = subprocess.run([cpp, method, key, str(value), str(repeat)], check=True, capture_output=True, text=True)
            t_cpp, m_cpp = (float(v) for v in out.stdout.split()[:2])
            line += (
                f"; C++ library alone median {m_cpp * 1e3:.1f} ms (best {t_cpp * 1e3:.1f}) "
                f"(Python/C++ medians {m_py / m_cpp:.3f})"
            )
        print(line)

if __name__ == "__main__":
    main()
