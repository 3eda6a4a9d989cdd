"""pds.analyze gives the dict of `pds analyze`'s JSON."""

import json
import subprocess

import numpy as np
import pytest

import pds


def cli_analyze(cli, tmp_path, sets, *args):
    files = []
    for i, s in enumerate(sets):
        path = tmp_path / f"set{i}.npy"
        np.save(path, s)
        files.append(str(path))
    out = subprocess.run([cli, "analyze", *files, *args], check=True, capture_output=True, text=True).stdout
    report = json.loads(out)
    report.pop("file")
    report.pop("files", None)
    return report


@pytest.mark.parametrize(
    "method,dim,torus,radius,bounds",
    [
        ("jones", 2, True, 0.03, None),
        ("bridson", 2, False, 0.05, [1, 2, 2.5, 3]),
        ("ebeida", 3, True, 0.15, None),
        ("random", 2, False, None, None),
    ],
)
def test_same_fields_as_the_cli(cli, tmp_path, method, dim, torus, radius, bounds):
    sizing = {"radius": radius} if radius else {"count": 400}
    pts = pds.generate(method, dim=dim, torus=torus, bounds=bounds, seed=4, **sizing)
    ours = pds.analyze(pts, torus=torus, radius=radius, bounds=bounds)
    args = ["--torus"] if torus else []
    if radius:
        args += ["--radius", repr(radius)]
    if bounds:
        args += ["--bounds", ",".join(map(str, bounds))]
    theirs = cli_analyze(cli, tmp_path, [pts], *args)
    assert ours == theirs
    assert list(ours) == list(theirs)  # same order
    assert ours["count"] == len(pts) and ours["dim"] == dim
    if radius:
        assert ours["min_distance_holds"] and ours["min_distance"] >= radius


def test_several_sets_and_options(cli, tmp_path):
    sets = [pds.generate("dunbar-humphreys", radius=0.04, torus=True, seed=s) for s in range(3)]
    ours = pds.analyze(sets, torus=True, max_frequency=20, pcf_bandwidth=0.005)
    theirs = cli_analyze(cli, tmp_path, sets, "--torus", "--frequencies", "20", "--pcf-bandwidth", "0.005")
    assert ours == theirs and ours["sets"] == 3 and ours["spectrum"]["max_frequency"] == 20


def test_missing_measures_are_none():
    one = pds.analyze(np.array([[0.5, 0.5]]))
    assert one["count"] == 1 and one["min_distance"] is None and one["pcf"] is None


def test_errors():
    with pytest.raises(ValueError):
        pds.analyze(np.array([[1.5, 0.5]]))  # outside the unit square
    with pytest.raises(ValueError, match="radius"):
        pds.analyze(np.array([[0.5, 0.5]]), radius=-1)
