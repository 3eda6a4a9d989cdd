"""Shared fixtures: the command line (the reference for bytes) and the markers."""

import os
import shutil

import pytest


def pytest_configure(config):
    config.addinivalue_line("markers", "serial: timing and memory measurements, run alone (CTest: python_serial)")


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("PDS_CLI") or shutil.which("pds")
    if not path:
        pytest.skip("the pds command line is not built (PDS_CLI unset)")
    return path
