"""Installs the Python package vibra (python/vibra) with its C++ module
vibra._vibra, built by CMake from this source tree:

    python3 -m venv --system-site-packages .venv
    .venv/bin/pip install --no-build-isolation .

numpy and pybind11 come from the system (Debian's python3-numpy and
pybind11-dev), so nothing is fetched. CMake builds in build-python/, beside
and never inside vibra's own build/, through ccache when it is installed (at
the same depth as build/, so the libraries' objects are shared with it).
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
CMAKE_BUILD = ROOT / "build-python"
CMAKE_BUILD.mkdir(exist_ok=True)  # egg_info writes its metadata there


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        env = dict(os.environ)
        env.setdefault("CCACHE_BASEDIR", str(ROOT))
        configure = ["cmake", "-S", str(ROOT), "-B", str(CMAKE_BUILD), "-G", "Ninja",
                     "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF", f"-DPython_EXECUTABLE={sys.executable}"]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        subprocess.run(configure, check=True, env=env)
        subprocess.run(["cmake", "--build", str(CMAKE_BUILD), "--target", "_vibra"], check=True, env=env)
        built = next((CMAKE_BUILD / "python" / "vibra").glob("_vibra*" + Path(self.get_ext_filename("x")).suffix))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    name="vibra",
    version="0.1.0",
    description="Vibration ODEs of Linge & Langtangen chapter 1: solvers, scenes and analyses from Python",
    python_requires=">=3.9",
    packages=["vibra"],
    package_dir={"": "python"},
    ext_modules=[Extension("vibra._vibra", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own work also stays out of the source tree and build/.
    options={"build": {"build_base": str(CMAKE_BUILD / "setuptools")},
             "egg_info": {"egg_base": str(CMAKE_BUILD)}},
)
