"""pds.read_chunks: a chunked set written by `pds chunks` read back as one
array, equal to the region sampled whole; malformed manifests raise
ValueError."""

import json
import os
import shutil
import subprocess

import numpy as np
import pytest

import pds

PDS = os.environ.get("PDS_CLI")


@pytest.fixture
def chunk_dir(tmp_path):
    if not PDS or not os.path.exists(PDS):
        pytest.skip("the pds command line is not built (PDS_CLI)")
    args = ["-r", "1", "-s", "5", "--region", "-3.5,2,27,19"]
    subprocess.run([PDS, "chunks", *args, "--chunk", "6.25", "-o", str(tmp_path / "c")], check=True,
                   stdout=subprocess.DEVNULL)
    subprocess.run([PDS, "unbounded", *args, "-o", str(tmp_path / "whole.npy")], check=True, stdout=subprocess.DEVNULL)
    return tmp_path


def test_reads_the_region(chunk_dir):
    points = pds.read_chunks(chunk_dir / "c" / "manifest.json")
    whole = np.load(chunk_dir / "whole.npy")
    assert points.shape == whole.shape and points.shape[0] > 300
    assert points.tobytes() == whole.tobytes()  # the canonical order: the same bytes
    points, bounds, torus = pds.read_chunks(str(chunk_dir / "c" / "manifest.json"), with_region=True)
    assert bounds == [-3.5, 2.0, 27.0, 19.0] and torus is False
    assert pds.min_distance(points, bounds=bounds)[0] >= 1.0


def test_refuses_malformed_manifests(chunk_dir):
    path = chunk_dir / "c" / "manifest.json"
    manifest = json.loads(path.read_text())
    path.write_text("{")
    with pytest.raises(ValueError, match="not valid JSON"):
        pds.read_chunks(path)
    manifest["chunks"][0]["file"] = "../whole.npy"
    path.write_text(json.dumps(manifest))
    with pytest.raises(ValueError, match="plain file name"):
        pds.read_chunks(path)
    manifest["chunks"][0]["file"] = "chunk_0_0.npy"
    manifest["chunks"][0]["count"] += 1
    manifest["count"] += 1
    path.write_text(json.dumps(manifest))
    with pytest.raises(ValueError, match="the manifest says"):
        pds.read_chunks(path)
    shutil.rmtree(chunk_dir / "c")
    with pytest.raises(ValueError, match="cannot open"):
        pds.read_chunks(path)
