"""pds.generate with density, mask and fixed points (docs/density.md)."""
import numpy as np
import pytest

import pds


def radii_of(points, density, rmin, rmax, bounds=(0, 0, 1, 1)):
    """r(x) as the library computes it: bilinear grey, 1/r^2 linear in darkness."""
    rows, cols = density.shape
    u = np.clip((points[:, 0] - bounds[0]) / (bounds[2] - bounds[0]) * cols - 0.5, 0, cols - 1)
    v = np.clip((bounds[3] - points[:, 1]) / (bounds[3] - bounds[1]) * rows - 0.5, 0, rows - 1)
    i = np.clip(u.astype(int), 0, max(cols - 2, 0))
    j = np.clip(v.astype(int), 0, max(rows - 2, 0))
    i1, j1 = np.minimum(i + 1, cols - 1), np.minimum(j + 1, rows - 1)
    fu, fv = u - i, v - j
    top = density[j, i] * (1 - fu) + density[j, i1] * fu
    bottom = density[j1, i] * (1 - fu) + density[j1, i1] * fu
    grey = top * (1 - fv) + bottom * fv
    return 1 / np.sqrt(1 / rmax**2 + (1 - grey) * (1 / rmin**2 - 1 / rmax**2))


def test_density_pair_rule_and_local_density():
    # Dark on the left, light on the right.
    density = np.tile(np.linspace(0, 1, 64), (16, 1))
    rmin, rmax = 0.01, 0.03
    points = pds.generate("bridson", density=density, radius_range=(rmin, rmax), seed=4)
    r = np.clip(radii_of(points, density, rmin, rmax), rmin, rmax)
    d = np.sqrt(((points[:, None, :] - points[None, :, :]) ** 2).sum(-1))
    np.fill_diagonal(d, np.inf)
    assert (d >= np.maximum(r[:, None], r[None, :]) * (1 - 1e-12)).all()
    left = np.count_nonzero(points[:, 0] < 0.25)
    right = np.count_nonzero(points[:, 0] >= 0.75)
    assert left > 4 * right
    again = pds.generate("bridson", density=density, radius_range=(rmin, rmax), seed=4)
    assert np.array_equal(points, again)


def test_mask_and_fixed_points():
    mask = np.ones((32, 32))
    mask[8:24, 8:24] = 0.0  # dark square in the middle: (0.25, 0.75)^2
    fixed = np.array([[0.5, 0.5], [0.9, 0.1]])
    points = pds.generate("dart-throwing", radius=0.03, mask=mask, fixed=fixed, seed=2)
    assert np.array_equal(points[:2], fixed)
    rest = points[2:]
    assert len(rest) > 100
    assert ((rest > 0.25) & (rest < 0.75)).all()
    d = np.sqrt(((rest[:, None, :] - points[None, :, :]) ** 2).sum(-1))
    d[np.arange(len(rest)), np.arange(len(rest)) + 2] = np.inf
    assert d.min() >= 0.03


def test_bad_input_raises_value_error():
    density = np.zeros((4, 4))
    with pytest.raises(ValueError, match="radius_range"):
        pds.generate("bridson", density=density)
    with pytest.raises(ValueError, match="rmin <= rmax"):
        pds.generate("bridson", density=density, radius_range=(0.2, 0.1))
    with pytest.raises(ValueError, match="grey levels must lie in"):
        pds.generate("bridson", density=density + 2, radius_range=(0.1, 0.2))
    with pytest.raises(ValueError, match="does not take a density"):
        pds.generate("sobol", mask=density, radius=0.1)
    with pytest.raises(ValueError, match="count is not taken"):
        pds.generate("bridson", mask=density, count=10)
    with pytest.raises(ValueError, match="fixed point 1"):
        pds.generate("bridson", radius=0.1, fixed=[[2.0, 0.5]])
    with pytest.raises(ValueError, match="float32 is not taken"):
        pds.generate("bridson", mask=density, radius=0.1, dtype="float32")
    with pytest.raises(ValueError, match="needs dim=2"):
        pds.generate("bridson", radius=0.1, dim=3, mask=density)


def test_elimination_takes_a_density_and_a_mask():
    grey = np.tile(np.linspace(0, 1, 64), (64, 1))  # dark (dense) on the left
    points = pds.generate("elimination", density=grey, radius_range=(0.01, 0.04), seed=1)
    assert len(points) > 300
    assert (points[:, 0] < 0.5).mean() > 0.6
    mask = np.ones((32, 32))
    mask[8:24, 8:24] = 0.0
    inside = pds.generate("elimination", mask=mask, count=300, seed=2)
    assert len(inside) == 300
    assert ((inside > 0.25) & (inside < 0.75)).all()
    with pytest.raises(ValueError, match="fixed points are not taken"):
        pds.generate("elimination", count=10, fixed=[[0.5, 0.5]])
