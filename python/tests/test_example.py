"""examples/python/: the scripts the docs quote run, headless."""

import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("PDS_SOURCE_DIR", pathlib.Path(__file__).parents[2]))


@pytest.mark.parametrize("script", sorted((SOURCE / "examples" / "python").glob("*.py")), ids=lambda p: p.name)
def test_example_runs(tmp_path, script):
    pytest.importorskip("matplotlib")
    out = tmp_path / "out.png"
    env = dict(os.environ, MPLBACKEND="Agg")
    done = subprocess.run([sys.executable, str(script), str(out)], env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_readme_example_runs():
    """The README's three-line example, as printed there."""
    readme = (SOURCE / "README.md").read_text()
    start = readme.index("```python\n", readme.index("## Python")) + len("```python\n")
    code = readme[start : readme.index("```", start)]
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
