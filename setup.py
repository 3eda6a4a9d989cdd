"""The build step of `pip install --no-build-isolation .` (pyproject.toml).

The module is a CMake target (python/CMakeLists.txt): this configures the
project for the running interpreter with only the library and the module,
builds the target, and copies what `cmake --install --component python` lays
out (the module and the pds shared libraries beside it) into the wheel.
"""

import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        temp = pathlib.Path(self.build_temp).resolve()
        build, stage = temp / "cmake", temp / "stage"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython_EXECUTABLE={sys.executable}", "-DPDS_BUILD_PYTHON=ON", "-DPDS_BUILD_APPS=OFF",
            "-DPDS_BUILD_TESTS=OFF", "-DPDS_BUILD_BENCH=OFF", "-DPDS_PYTHON_INSTALL_DIR=.",
        ]  # fmt: skip
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        subprocess.run(configure, check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target", "pds_python", "-j", jobs], check=True)
        shutil.rmtree(stage, ignore_errors=True)
        subprocess.run(["cmake", "--install", str(build), "--component", "python", "--prefix", str(stage)], check=True)
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve().parent
        target.mkdir(parents=True, exist_ok=True)
        for old in target.glob("libpds_*"):
            old.unlink()
        # The module, and each library under its soname (libpds_x.so.0, a link
        # to the versioned file, which the loader never asks for by name).
        for f in (stage / "pds").iterdir():
            if f.name.startswith("_pds") or (f.name.startswith("libpds_") and f.is_symlink()):
                shutil.copy2(f, target / f.name, follow_symlinks=True)


setup(ext_modules=[Extension("pds._pds", sources=[])], cmdclass={"build_ext": CMakeBuild})
