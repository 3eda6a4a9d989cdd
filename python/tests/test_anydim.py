"""Analysis in every dimension: SciPy's discrepancies to the last bits, minimum
distance against all pairs, the report's fields in 1 to 8 dimensions and past."""

import numpy as np
import pytest

import pds

qmc = pytest.importorskip("scipy.stats.qmc")

METHODS = ["L2-star", "CD", "WD", "MD"]


@pytest.mark.parametrize("n,d", [(1, 1), (50, 1), (200, 2), (300, 5), (150, 10), (80, 40)])
@pytest.mark.parametrize("method", METHODS)
def test_discrepancy_equals_scipy(n, d, method):
    x = np.random.default_rng(n * 100 + d).random((n, d))
    ours, theirs = pds.discrepancy(x, method), qmc.discrepancy(x, method=method)
    assert ours == pytest.approx(theirs, rel=1e-12, abs=0)


def test_discrepancy_on_a_box_is_scipys_on_the_scaled_points():
    lo, hi = np.array([-1.0, 2.0, 0.0]), np.array([1.0, 5.0, 0.25])
    x = lo + (hi - lo) * np.random.default_rng(3).random((100, 3))
    u = qmc.scale(x, lo, hi, reverse=True)
    for method in METHODS:
        ours = pds.discrepancy(x, method, bounds=np.concatenate([lo, hi]))
        assert ours == pytest.approx(qmc.discrepancy(u, method=method), rel=1e-12, abs=0)


def test_discrepancy_names_and_errors():
    x = np.random.default_rng(1).random((20, 4))
    assert pds.discrepancy(x) == pds.discrepancy(x, "L2-star") == pds.discrepancy(x, kind="l2-star")
    with pytest.raises(ValueError, match="L2-star, CD, WD, MD"):
        pds.discrepancy(x, "centered")
    with pytest.raises(ValueError, match="unit cube"):
        pds.discrepancy(x + 1.0, "CD")


@pytest.mark.parametrize("d", [1, 4, 8, 11])
@pytest.mark.parametrize("torus", [False, True])
def test_min_distance_against_all_pairs(d, torus):
    x = np.random.default_rng(d).random((300, d))
    diff = np.abs(x[:, None, :] - x[None, :, :])
    if torus:
        diff = np.minimum(diff, 1.0 - diff)
    dist = np.sqrt((diff**2).sum(-1))
    np.fill_diagonal(dist, np.inf)
    distance, i, j = pds.min_distance(x, torus=torus)
    assert distance == pytest.approx(dist.min(), rel=1e-14)
    assert i < j and dist[i, j] == pytest.approx(distance, rel=1e-14)


def test_analyze_in_five_and_in_twelve_dimensions():
    x5 = np.random.default_rng(5).random((400, 5))
    r = pds.analyze(x5, radius=0.05)
    assert r["dim"] == 5 and r["relative_radius"] > 0 and "maximal" in r
    assert r["centered_discrepancy"] == pytest.approx(qmc.discrepancy(x5, method="CD"), rel=1e-12)
    assert r["spectrum"] is None and "2D and 3D" in r["spectrum_note"]
    x12 = np.random.default_rng(12).random((300, 12))
    r = pds.analyze(x12, radius=0.05)
    assert r["relative_radius"] is None and "8 dimensions" in r["relative_radius_note"]
    assert "maximal" not in r and "maximality_note" in r
    assert r["min_distance"] == pytest.approx(pds.min_distance(x12)[0])
    assert r["mixture_discrepancy"] == pytest.approx(qmc.discrepancy(x12, method="MD"), rel=1e-12)
