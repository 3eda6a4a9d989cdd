#!/usr/bin/env python3
"""Writes tests/data/scipy_{sobol,halton}.txt: unscrambled Sobol and Halton
points from SciPy (scipy.stats.qmc, run once; Debian's python3-scipy 1.10.1),
which src/pds/samplers/{sobol,halton}_test.cpp compare pds's points with.

Each block: a line `METHOD d n checksum`, a line `columns c0 c1 ...`, then n
lines with those columns of the n x d array (float.hex, exact). Small d keep
every column; for large d a few columns are kept and the checksum covers the
whole array: the sum over k of bits(x_k) * (k + 1) mod 2^64, x_k the array's
doubles in row-major order and bits() their IEEE-754 bit patterns.

  /usr/bin/python3 scripts/scipy_qmc_reference.py [OUTDIR]
"""
import sys

import numpy as np
import scipy
from scipy.stats import qmc

N = 64


def checksum(x):
    bits = np.ascontiguousarray(x, dtype=np.float64).view(np.uint64).ravel()
    weights = np.arange(1, bits.size + 1, dtype=np.uint64)
    with np.errstate(over="ignore"):
        return int((bits * weights).sum(dtype=np.uint64))


def columns(d):
    if d <= 10:
        return list(range(d))
    return sorted({0, 1, 2, d // 2, d - 2, d - 1})


def block(name, d, x):
    cols = columns(d)
    lines = [f"{name} {d} {len(x)} {checksum(x)}", "columns " + " ".join(map(str, cols))]
    lines += [" ".join(float(v).hex() for v in row[cols]) for row in x]
    return "\n".join(lines) + "\n"


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "tests/data"
    header = f"# scipy {scipy.__version__}: qmc.{{}}(d, scramble=False).random({N}); scripts/scipy_qmc_reference.py\n"
    with open(f"{outdir}/scipy_sobol.txt", "w") as f:
        f.write(header.format("Sobol"))
        for d in (1, 2, 3, 10, 100, 1000, 21201):
            f.write(block("sobol", d, qmc.Sobol(d, scramble=False).random(N)))
    with open(f"{outdir}/scipy_halton.txt", "w") as f:
        f.write(header.format("Halton"))
        for d in (1, 2, 3, 10, 100, 1000, 10000):
            f.write(block("halton", d, qmc.Halton(d, scramble=False).random(N)))


if __name__ == "__main__":
    main()
