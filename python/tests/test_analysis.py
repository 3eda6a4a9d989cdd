"""Spectra, pair correlation, discrepancy and rendering through Python."""

import numpy as np
import pytest

import pds


def test_periodogram_of_white_noise_is_flat():
    sets = [pds.generate("random", count=512, seed=s) for s in range(8)]
    p = pds.periodogram(sets, torus=True, max_frequency=16)
    assert p.shape == (33, 33)
    assert p[16, 16] == pytest.approx(512)  # k = 0: N
    off = np.delete(p.reshape(-1), 16 * 33 + 16)
    assert off.mean() == pytest.approx(1.0, abs=0.1)


def test_periodogram_is_indexed_y_then_x():
    # A grid stretched along x: 8 columns, 2 rows; its first peak along x is at kx = 8.
    xs, ys = np.meshgrid((np.arange(8) + 0.5) / 8, (np.arange(2) + 0.5) / 2)
    pts = np.column_stack([xs.ravel(), ys.ravel()])
    p = pds.periodogram(pts, torus=True, max_frequency=8)
    assert p[8, 16] == pytest.approx(16) and p[16, 8] == pytest.approx(16)
    assert p[8 + 2, 8] == pytest.approx(16)  # ky = 2
    assert p[8 + 1, 8] == pytest.approx(0, abs=1e-9)  # ky = 1


def test_radial_power_shows_blue_noise():
    sets = [pds.generate("dunbar-humphreys", radius=0.02, torus=True, seed=s) for s in range(4)]
    f, power, aniso = pds.radial_power(sets, torus=True, max_frequency=48)
    assert f.shape == power.shape == aniso.shape and len(f) == 48
    assert power[f < 0.4].mean() < 0.2  # low frequencies suppressed
    assert power.max() > 1.2  # the ring


def test_pair_correlation_is_zero_below_the_radius():
    pts = pds.generate("bridson", radius=0.03, seed=1)
    r, g = pds.pair_correlation(pts, r_max=0.1, bandwidth=0.003, steps=100)
    assert r.shape == g.shape == (100,)
    assert np.all(g[r < 0.03 - 0.003] == 0)
    assert g[(r > 0.03) & (r < 0.045)].max() > 1.2


def test_discrepancy_orders_sequences_before_noise():
    sobol = pds.generate("sobol", count=256)
    noise = pds.generate("random", count=256, seed=1)
    assert pds.discrepancy(sobol) < pds.discrepancy(noise)
    assert pds.discrepancy(sobol, kind="star") < pds.discrepancy(noise, kind="star")
    with pytest.raises(ValueError, match="kind"):
        pds.discrepancy(sobol, kind="l1")


def test_analysis_errors():
    with pytest.raises(ValueError, match="shape"):
        pds.periodogram(np.zeros((4, 5)))
    with pytest.raises(ValueError):
        pds.periodogram(np.full((4, 2), 2.0))  # outside the unit square
    with pytest.raises(ValueError, match="same dimension"):
        pds.periodogram([np.zeros((3, 2)), np.zeros((3, 3))])


@pytest.mark.skipif(not pds._pds.has_render, reason="built without the render component")
def test_render_returns_a_grey_image():
    img = pds.render("zone-plate", "best-candidate", spp=2, size=(64, 48), tile_count=256)
    assert img.shape == (48, 64) and img.dtype == np.float64
    assert 0 <= img.min() and img.max() <= 1 and img.std() > 0.1
    again = pds.render("zone-plate", "best-candidate", spp=2, size=(64, 48), tile_count=256)
    assert img.tobytes() == again.tobytes()
    with pytest.raises(ValueError, match="unknown filter"):
        pds.render(size=(8, 8), filter="sinc")
