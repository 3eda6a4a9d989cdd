"""pds.qmc.PoissonDisk behaves as SciPy documents scipy.stats.qmc.PoissonDisk."""

import numpy as np
import pytest

cKDTree = pytest.importorskip("scipy.spatial").cKDTree
scipy_qmc = pytest.importorskip("scipy.stats.qmc")

import pds
from pds import qmc


def min_distance(points):
    if len(points) < 2:
        return np.inf
    d, _ = cKDTree(points).query(points, k=2)
    return d[:, 1].min()


@pytest.mark.parametrize("d,radius", [(2, 0.05), (3, 0.15)])
def test_fill_space_keeps_the_radius_inside_the_unit_cube(d, radius):
    sample = qmc.PoissonDisk(d, radius=radius, seed=1).fill_space()
    assert sample.shape[1] == d and sample.dtype == np.float64
    assert np.all(sample >= 0) and np.all(sample < 1)
    assert min_distance(sample) >= radius
    # Full: as many points as SciPy's own engine puts there (its loop, so its
    # law: over seeds 1-8 the means agree within a few per cent; Bridson's
    # loop packs more, bridson_test.cpp tells the two apart over 40 seeds).
    ours = np.mean([len(qmc.PoissonDisk(d, radius=radius, seed=s).fill_space()) for s in range(1, 9)])
    theirs = np.mean([len(scipy_qmc.PoissonDisk(d, radius=radius, seed=s).fill_space()) for s in range(1, 9)])
    assert abs(ours / theirs - 1) < 0.03


@pytest.mark.parametrize("d,radius", [(2, 0.05), (3, 0.15)])
def test_surface_candidates_give_a_denser_set_as_scipys(d, radius):
    dense = qmc.PoissonDisk(d, radius=radius, hypersphere="surface", seed=1).fill_space()
    sparse = qmc.PoissonDisk(d, radius=radius, hypersphere="volume", seed=1).fill_space()
    assert np.all(dense >= 0) and np.all(dense < 1)
    assert min_distance(dense) >= radius
    # SciPy's own surface sampler fills the cube about as densely.
    theirs = scipy_qmc.PoissonDisk(d, radius=radius, hypersphere="surface", seed=1).fill_space()
    assert 0.85 < len(dense) / len(theirs) < 1.2
    assert len(dense) > 1.15 * len(sparse)
    same = pds.generate("bridson", radius=radius, dim=d, seed=1, surface=1, scipy=1)
    assert same.tobytes() == dense.tobytes()
    with pytest.raises(ValueError, match="surface"):
        qmc.PoissonDisk(2, radius=0.05, hypersphere="surface", method="ebeida")


def test_ebeida_fills_five_dimensions_to_saturation():
    # A maximal set: pds.analyze finds no room for another point at the radius.
    sample = qmc.PoissonDisk(5, radius=0.35, method="ebeida", seed=3).fill_space()
    assert sample.shape[1] == 5 and len(sample) > 50
    assert np.all(sample >= 0) and np.all(sample < 1)
    assert min_distance(sample) >= 0.35
    report = pds.analyze(sample, radius=0.35)
    assert report["maximal"] is True


def test_wei_fills_five_dimensions():
    sample = qmc.PoissonDisk(5, radius=0.35, method="wei", seed=3).fill_space()
    assert sample.shape[1] == 5 and len(sample) > 50
    assert np.all(sample >= 0) and np.all(sample < 1)
    assert min_distance(sample) >= 0.35


def test_random_continues_and_fill_space_completes():
    engine = qmc.PoissonDisk(2, radius=0.03, seed=7)
    first = engine.random(10)
    second = engine.random(25)
    rest = engine.fill_space()
    assert first.shape == (10, 2) and second.shape == (25, 2)
    assert engine.num_generated == 35 + len(rest)
    whole = np.concatenate([first, second, rest])
    assert min_distance(whole) >= 0.03  # one Poisson disk set, handed out in pieces
    assert len(np.unique(whole, axis=0)) == len(whole)
    assert engine.random(5).shape == (0, 2)  # the domain is full
    assert engine.fill_space().shape == (0, 2)
    # The same set as one fill_space call.
    again = qmc.PoissonDisk(2, radius=0.03, seed=7).fill_space()
    assert again.tobytes() == whole.tobytes()


def test_random_may_return_fewer_than_asked():
    engine = qmc.PoissonDisk(2, radius=0.3, seed=0)
    got = engine.random(1000)
    assert 0 < len(got) < 1000 and min_distance(got) >= 0.3


def test_reset_gives_the_same_samples_again():
    engine = qmc.PoissonDisk(2, radius=0.05, seed=np.random.default_rng(4))
    a = engine.random(20)
    b = engine.fill_space()
    assert engine.reset() is engine
    assert engine.num_generated == 0
    assert engine.random(20).tobytes() == a.tobytes()
    assert engine.fill_space().tobytes() == b.tobytes()


def test_seed_forms():
    assert qmc.PoissonDisk(2, radius=0.05, seed=12).fill_space().tobytes() == pds.generate(
        "bridson", radius=0.05, seed=12, scipy=1
    ).tobytes()
    g1, g2 = np.random.default_rng(3), np.random.default_rng(3)
    assert qmc.PoissonDisk(2, seed=g1).fill_space().tobytes() == qmc.PoissonDisk(2, seed=g2).fill_space().tobytes()
    assert qmc.PoissonDisk(2, seed=np.random.RandomState(1)).random(3).shape == (3, 2)
    assert qmc.PoissonDisk(2, seed=np.random.SeedSequence(5)).random(3).shape == (3, 2)
    assert (
        qmc.PoissonDisk(2, rng=np.uint64(5)).fill_space().tobytes()
        == pds.generate("bridson", radius=0.05, seed=5, scipy=1).tobytes()
    )
    # None: fresh entropy each time.
    assert qmc.PoissonDisk(2).fill_space().tobytes() != qmc.PoissonDisk(2).fill_space().tobytes()
    with pytest.raises(ValueError):
        qmc.PoissonDisk(2, seed="abc")
    with pytest.raises(ValueError):
        qmc.PoissonDisk(2, seed=-1)


def test_bounds_and_ncandidates():
    engine = qmc.PoissonDisk(2, radius=0.1, l_bounds=[-2, 10], u_bounds=[1, 12], ncandidates=8, seed=2)
    s = engine.fill_space()
    assert np.all(s >= [-2, 10]) and np.all(s < [1, 12]) and min_distance(s) >= 0.1
    assert s.tobytes() == pds.generate("bridson", radius=0.1, bounds=[-2, 10, 1, 12], seed=2, k=8, scipy=1).tobytes()


def test_other_methods():
    s = qmc.PoissonDisk(2, radius=0.02, method="dunbar-humphreys", seed=1).fill_space()
    assert min_distance(s) >= 0.02


def test_integers():
    engine = qmc.PoissonDisk(2, radius=0.05, seed=1)
    ints = engine.integers(10, n=50)
    assert ints.dtype == np.int64 and ints.shape == (50, 2)
    assert ints.min() >= 0 and ints.max() < 10
    ints = qmc.PoissonDisk(2, radius=0.05, seed=1).integers([1, 2], u_bounds=[3, 4], n=50, endpoint=True)
    assert ints.min(axis=0).tolist() >= [1, 2] and np.all(ints.max(axis=0) <= [3, 4])


def test_constructor_errors_match_scipy():
    for kwargs in ({"hypersphere": "cube"},):
        with pytest.raises(ValueError):
            scipy_qmc.PoissonDisk(2, **kwargs)
        with pytest.raises(ValueError):
            qmc.PoissonDisk(2, **kwargs)
    with pytest.raises(ValueError):
        qmc.PoissonDisk(-1)
    with pytest.raises(ValueError, match="1 to 8 dimensions, got d=9"):
        qmc.PoissonDisk(9)
    for method in ("ebeida", "wei"):
        with pytest.raises(ValueError, match="1 to 8 dimensions, got d=9"):
            qmc.PoissonDisk(9, method=method)
    with pytest.raises(NotImplementedError):
        qmc.PoissonDisk(2, optimization="lloyd")
    with pytest.raises(ValueError, match="radius"):
        qmc.PoissonDisk(2, radius=-0.1).random(3)


def test_the_rest_of_scipy_qmc_passes_through():
    assert qmc.scale is scipy_qmc.scale
    assert qmc.Sobol is scipy_qmc.Sobol
    with pytest.raises(AttributeError):
        qmc.NoSuchThing  # noqa: B018


@pytest.mark.parametrize("d", [1, 4, 6])
def test_poisson_disk_in_other_dimensions(d):
    """Past the plane and space the drop-in keeps its radius and its bounds."""
    radius = {1: 0.01, 4: 0.25, 6: 0.45}[d]
    x = qmc.PoissonDisk(d, radius=radius, seed=3).fill_space()
    assert x.shape[1] == d and len(x) > 20
    assert ((x >= 0) & (x < 1)).all()
    assert pds.min_distance(x)[0] >= radius
