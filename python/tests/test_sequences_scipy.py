"""Unscrambled Sobol and Halton equal SciPy's points exactly, in every dimension.

pds's index i is row i of scipy.stats.qmc.Sobol(d, scramble=False).random(n)
and of qmc.Halton(d, scramble=False).random(n): both start at index 0 (the
origin); `first=k` is SciPy's fast_forward(k). The C++ tests keep SciPy's
values as data (tests/data/scipy_*.txt); this compares with SciPy directly.
"""

import numpy as np
import pytest

qmc = pytest.importorskip("scipy.stats.qmc")

import pds


@pytest.mark.parametrize("d,n", [(1, 256), (2, 1024), (3, 512), (7, 256), (100, 256), (1000, 128), (21201, 16)])
def test_sobol_equals_scipy(d, n):
    theirs = qmc.Sobol(d, scramble=False).random(n)
    ours = pds.generate("sobol", count=n, dim=d)
    assert ours.shape == (n, d)
    assert ours.tobytes() == theirs.tobytes()


def test_sobol_first_is_scipys_fast_forward():
    engine = qmc.Sobol(50, scramble=False)
    engine.fast_forward(1000)
    theirs = engine.random(300)
    assert pds.generate("sobol", count=300, dim=50, first=1000).tobytes() == theirs.tobytes()


@pytest.mark.parametrize("d,n", [(1, 300), (2, 1000), (3, 500), (10, 300), (500, 100), (10000, 8)])
def test_halton_equals_scipy(d, n):
    theirs = qmc.Halton(d, scramble=False).random(n)
    ours = pds.generate("halton", count=n, dim=d)
    assert ours.tobytes() == theirs.tobytes()


def test_halton_first_and_the_correctly_rounded_variant():
    engine = qmc.Halton(20, scramble=False)
    engine.fast_forward(777)
    theirs = engine.random(200)
    assert pds.generate("halton", count=200, dim=20, first=777).tobytes() == theirs.tobytes()
    exact = pds.generate("halton", count=200, dim=20, first=777, rounding=0)
    assert np.max(np.abs(exact - theirs)) <= 4 * 2.0**-53  # SciPy's sums are a few ulps off
    assert exact.tobytes() != theirs.tobytes()


@pytest.mark.parametrize("method", ["sobol", "halton", "hammersley", "latin-hypercube", "random"])
def test_high_dimensions_are_deterministic_and_inside(method):
    lo = -np.arange(300, dtype=float)
    hi = lo + 1.0 + np.arange(300) % 3
    bounds = list(lo) + list(hi)
    kw = {"scramble": 2} if method in ("sobol", "halton", "hammersley") else {}
    a = pds.generate(method, count=200, dim=300, seed=4, bounds=bounds, **kw)
    b = pds.generate(method, count=200, dim=300, seed=4, bounds=bounds, **kw)
    assert a.shape == (200, 300) and a.tobytes() == b.tobytes()
    assert np.all(a >= lo) and np.all(a < hi)
    assert a.tobytes() != pds.generate(method, count=200, dim=300, seed=5, bounds=bounds, **kw).tobytes()


def test_past_the_range_is_a_clear_error():
    with pytest.raises(ValueError, match="1-21201"):
        pds.generate("sobol", count=4, dim=21202)
    with pytest.raises(ValueError, match="GiB"):
        pds.generate("sobol", count=10**8, dim=21201)
