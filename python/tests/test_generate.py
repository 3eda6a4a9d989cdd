"""pds.generate and friends: the same bytes as the command line, properties, errors."""

import subprocess

import numpy as np
import pytest

cKDTree = pytest.importorskip("scipy.spatial").cKDTree

import pds

METHODS = pds.methods()
STRATA_GRIDS = ("regular", "jittered", "multi-jittered")


def cases():
    """Every method in every dimension it supports, sized as it allows, box and torus."""
    for m in METHODS:
        # Dimensions 1-8, then the top of the range (at most Sobol's 21,201: random
        # and latin-hypercube go to 2^20, where memory, not code, changes).
        top = min(m["dims"][-1], 21201)
        for dim in [d for d in m["dims"] if d <= 8] + ([top] if top > 8 else []):
            torus = dim == 3
            if m["takes_count"]:
                # Strata need a count with D near-equal factors: 2^D from 4D.
                count = 2**dim if dim >= 4 and m["name"] in STRATA_GRIDS else 300
                yield pytest.param(m["name"], dim, {"count": count}, torus, id=f"{m['name']}-{dim}d-count")
            if m["takes_radius"]:
                r = {2: 0.06, 3: 0.15}.get(dim, 300 ** (-1 / dim))
                # Past 5D ebeida and wei serve small sets only (seconds for tens of points).
                if m["name"] in ("ebeida", "wei") and dim > 5:
                    r = {6: 0.6, 7: 0.8, 8: 1.1}[dim]
                yield pytest.param(m["name"], dim, {"radius": r}, not torus, id=f"{m['name']}-{dim}d-radius")


def cli_points(cli, tmp_path, method, dim, sizing, torus, seed, bounds=None, params=()):
    out = tmp_path / "points.npy"
    cmd = [cli, "generate", method, "--dim", str(dim), "--seed", str(seed), "-o", str(out)]
    for key, value in sizing.items():
        cmd += [f"--{key}", repr(value)]
    if torus:
        cmd.append("--torus")
    if bounds is not None:
        cmd += ["--bounds", ",".join(map(repr, bounds))]
    for name, value in params:
        cmd += ["--param", f"{name}={value}"]
    subprocess.run(cmd, check=True, capture_output=True)
    return np.load(out)


# Parameters that keep a case short where the defaults run long (the bytes are
# compared whatever they are).
SHORT = {"gbn": {"iterations": 20}}


@pytest.mark.parametrize("method,dim,sizing,torus", cases())
def test_same_bytes_as_cli(cli, tmp_path, method, dim, sizing, torus):
    bounds = [0.5, -1.0, 2.0, 0.25] if dim == 2 and not torus else None
    extra = SHORT.get(method, {})
    ours = pds.generate(method, dim=dim, torus=torus, seed=11, bounds=bounds, **sizing, **extra)
    theirs = cli_points(cli, tmp_path, method, dim, sizing, torus, 11, bounds, params=list(extra.items()))
    assert ours.dtype == np.float64 and ours.shape == theirs.shape and ours.shape[1] == dim
    assert ours.tobytes() == theirs.tobytes()


def test_parameters_reach_the_method(cli, tmp_path):
    ours = pds.generate("bridson", radius=0.05, seed=3, k=5)
    assert ours.tobytes() == cli_points(cli, tmp_path, "bridson", 2, {"radius": 0.05}, False, 3, params=[("k", 5)]).tobytes()
    assert ours.tobytes() != pds.generate("bridson", radius=0.05, seed=3).tobytes()
    # A hyphen in a parameter's name is written as an underscore.
    hyphen = pds.generate("dart-throwing", radius=0.08, seed=3, all_pairs=1)
    assert hyphen.tobytes() == pds.generate("dart-throwing", radius=0.08, seed=3).tobytes()


@pytest.mark.parametrize("method", [m["name"] for m in METHODS if m["min_distance"] and m["takes_radius"]])
@pytest.mark.parametrize("torus", [False, True])
def test_minimum_distance_and_bounds(method, torus):
    r = 0.04
    lo, hi = np.array([-1.0, 2.0]), np.array([0.5, 3.0])
    pts = pds.generate(method, radius=r, bounds=[lo, hi], torus=torus, seed=5)
    assert len(pts) > 100
    assert np.all(pts >= lo) and np.all(pts < hi)
    tree = cKDTree(pts - lo, boxsize=(hi - lo) if torus else None)
    d, _ = tree.query(pts - lo, k=2)
    assert d[:, 1].min() >= r


def test_same_seed_same_bytes_and_threads_do_not_matter():
    a = pds.generate("wei", radius=0.01, seed=9, threads=1)
    b = pds.generate("wei", radius=0.01, seed=9, threads=0)
    assert a.tobytes() == b.tobytes()
    assert a.tobytes() != pds.generate("wei", radius=0.01, seed=10).tobytes()


def test_array_owns_the_library_buffer():
    pts = pds.generate("random", count=1000)
    assert pts.flags.c_contiguous and pts.flags.writeable
    # The array wraps the library's vector (a capsule base), not a copy made by NumPy.
    assert pts.base is not None and type(pts.base).__name__ == "PyCapsule"


def test_tile_is_on_the_unit_torus(cli, tmp_path):
    # best-candidate takes a count: the same request as pds generate --torus.
    t = pds.tile("best-candidate", count=256, seed=2)
    assert t.tobytes() == cli_points(cli, tmp_path, "best-candidate", 2, {"count": 256}, True, 2).tobytes()


def test_methods_match_the_registry(cli):
    listing = subprocess.run([cli, "methods"], check=True, capture_output=True, text=True).stdout
    names = [m["name"] for m in METHODS]
    assert names and all(f"  {n} " in listing for n in names)
    bridson = next(m for m in METHODS if m["name"] == "bridson")
    assert bridson["min_distance"] and bridson["takes_radius"] and 2 in bridson["dims"]
    assert any(p["name"] == "k" and p["default"] == 30 for p in bridson["params"])
    for n in names:
        assert n in pds.generate.__doc__


def cli_error(cli, *args):
    done = subprocess.run([cli, *args], capture_output=True, text=True)
    assert done.returncode == 2
    prefix = "pds: error: "
    assert done.stderr.startswith(prefix)
    return done.stderr[len(prefix):].strip()


@pytest.mark.parametrize(
    "kwargs,args",
    [
        ({"method": "nope", "count": 10}, ["nope", "--count", "10"]),
        ({"method": "wei", "count": 10}, ["wei", "--count", "10"]),
        ({"method": "jones", "radius": 0.1, "dim": 4}, ["jones", "--radius", "0.1", "--dim", "4"]),
        ({"method": "bridson", "radius": -1.0}, ["bridson", "--radius", "-1"]),
        ({"method": "bridson", "radius": 1e-200}, ["bridson", "--radius", "1e-200"]),
        ({"method": "random", "count": 0}, ["random", "--count", "0"]),
        ({"method": "bridson", "radius": 0.1, "k": 0}, ["bridson", "--radius", "0.1", "--param", "k=0"]),
        ({"method": "bridson", "radius": 0.1, "q": 1}, ["bridson", "--radius", "0.1", "--param", "q=1"]),
        ({"method": "dart-throwing", "radius": 1e-5}, ["dart-throwing", "--radius", "1e-5"]),
        ({"method": "random", "count": 10, "bounds": [0, 0, 0, 1]}, ["random", "--count", "10", "--bounds", "0,0,0,1"]),
    ],
)
def test_errors_carry_the_cli_message(cli, kwargs, args):
    kwargs = dict(kwargs)
    method = kwargs.pop("method")
    with pytest.raises(ValueError) as err:
        pds.generate(method, **kwargs)
    assert str(err.value) == cli_error(cli, "generate", *args)


def test_python_side_errors():
    with pytest.raises(ValueError, match="bounds needs 4 values"):
        pds.generate("random", count=10, bounds=[0, 1])
    with pytest.raises(ValueError, match="seed must be in"):
        pds.generate("random", count=10, seed=-1)
    with pytest.raises(TypeError):
        pds.generate("random", count=1.5)
    with pytest.raises(ValueError, match="must be a number"):
        pds.generate("bridson", radius=0.1, k="many")


def test_tile_sizes_counts_as_the_cli(cli, tmp_path):
    out = tmp_path / "tile.npy"
    subprocess.run([cli, "tile", "dunbar-humphreys", "--count", "500", "--seed", "3", "-o", str(out)], check=True, capture_output=True)
    ours = pds.tile("dunbar-humphreys", count=500, seed=3)
    assert ours.tobytes() == np.load(out).tobytes()
    assert 450 < len(ours) < 800  # "about the count or somewhat more" (pds::size_request)
