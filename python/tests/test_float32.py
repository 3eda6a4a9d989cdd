"""pds.generate(dtype="float32"): float32 values that keep the radius and the bounds."""

import numpy as np
import pytest

import pds

MIN_DISTANCE = [m["name"] for m in pds.methods() if m["min_distance"] and m["takes_radius"] and 2 in m["dims"]]


def torus_distances(points, period):
    """All pairwise distances in double, on the nearest image, from the float32 values."""
    p = points.astype(np.float64)
    d = np.abs(p[:, None, :] - p[None, :, :])
    d = np.minimum(d, period - d)
    dist = np.sqrt((d * d).sum(axis=2))
    return dist[np.triu_indices(len(p), 1)]


@pytest.mark.parametrize("method", MIN_DISTANCE)
def test_float32_keeps_the_radius_at_an_offset_of_a_million(method):
    # float32 values are 0.0625 apart near 1e6; the smallest radius it takes in 2D is 17.7.
    lo, r = 1e6, 18.5
    hi = lo + 20 * r
    points = pds.generate(method, radius=r, bounds=[[lo, lo], [hi, hi]], torus=True, seed=3, dtype="float32")
    assert points.dtype == np.float32 and len(points) > 100
    assert ((points >= lo) & (points < hi)).all()
    assert torus_distances(points, hi - lo).min() >= r


def test_float32_refuses_a_radius_it_cannot_hold():
    with pytest.raises(ValueError, match="float32: radius 10 is too small"):
        pds.generate("bridson", radius=10, bounds=[[1e6, 1e6], [1e6 + 400, 1e6 + 400]], dtype="float32")
    with pytest.raises(ValueError, match="dtype must be float64 or float32"):
        pds.generate("random", count=10, dtype="int32")
