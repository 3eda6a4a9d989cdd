#!/usr/bin/python3
"""SciPy's scipy.stats.qmc.PoissonDisk (Debian's python3-scipy) on the unit
square or cube (a box: it has no tiling), one thread, its defaults (ncandidates
30, hypersphere "volume"). Times only fill_space().
Usage: scipy_pd.py DIM RADIUS [SEED=0] [OUT.csv]"""
import sys
import time

import numpy as np
from scipy.stats import qmc

dim, r = int(sys.argv[1]), float(sys.argv[2])
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 0
engine = qmc.PoissonDisk(d=dim, radius=r, seed=seed)
c0, w0 = time.thread_time(), time.perf_counter()
pts = engine.fill_space()
c1, w1 = time.thread_time(), time.perf_counter()
n = len(pts)
print(f"RESULT scipy-PoissonDisk dim={dim} samples={n} cpu_s={c1 - c0:.6f} wall_s={w1 - w0:.6f} "
      f"Msamples_per_cpu_s={n / (c1 - c0) * 1e-6:.4f}")
if len(sys.argv) > 4:
    np.savetxt(sys.argv[4], pts, delimiter=",", header="x,y" if dim == 2 else "x,y,z", comments="", fmt="%.17g")
