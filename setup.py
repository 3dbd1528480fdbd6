"""`pip install .` for the springlab Python module: CMake builds python/ (the core and the
bindings, the way scripts/build.sh does, without the app), and setuptools packages what it built
with the shipped scenes and tableaux, as `cmake --install --component python` lays them out.

    python3 -m pip install --no-build-isolation .

SPRINGLAB_CMAKE_BUILD_DIR names a build folder already configured with SPRINGLAB_PYTHON=ON (the
tests' own build): it is built (a no-op when up to date) and packaged instead of a fresh one.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent
VERSION = re.search(r"project\(springlab VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


class CMakeBuild(build_ext):
    """The extension `springlab._springlab`, built by CMake's target springlab_python."""

    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        given = os.environ.get("SPRINGLAB_CMAKE_BUILD_DIR")
        build = Path(given) if given else Path(self.build_temp).resolve() / "cmake"
        cmake = shutil.which("cmake")
        if not cmake:
            sys.exit("springlab: cmake is not on PATH (apt-get install cmake; scripts/setup.sh installs it)")
        if not given:
            configure = [cmake, "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                         "-DSPRINGLAB_PYTHON=ON", "-DSPRINGLAB_BUILD_APP=OFF", "-DSPRINGLAB_BUILD_TESTS=OFF",
                         "-DSPRINGLAB_BUILD_BENCH=OFF", f"-DPython_EXECUTABLE={sys.executable}"]
            if shutil.which("ninja"):
                configure += ["-G", "Ninja"]
            subprocess.run(configure, check=True)
        subprocess.run([cmake, "--build", str(build), "--target", "springlab_python", "--parallel", str(os.cpu_count() or 2)],
                       check=True)
        built = sorted((build / "python" / "springlab").glob("_springlab*.so"))
        if not built:
            sys.exit(f"springlab: CMake built no module in {build / 'python' / 'springlab'}")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], target)
        shutil.copy2(built[0].with_name("_build.py"), target.with_name("_build.py"))  # the interpreter it is for


class WithData(build_py):
    """The package with the shipped scenes, tableaux and translations in springlab/data/assets, where
    springlab/__init__.py looks for them."""

    def run(self):
        super().run()
        for kind, pattern in (("scenes", "*.json"), ("tableaux", "*.json"), ("locale", "*.po")):
            into = Path(self.build_lib) / "springlab" / "data" / "assets" / kind
            into.mkdir(parents=True, exist_ok=True)
            for data in (ROOT / "assets" / kind).glob(pattern):
                shutil.copy2(data, into / data.name)


# setuptools' own build folder and its metadata: build/pip, beside the files of CMake's build/
# (scripts/build.sh's) and out of the source tree's tracked folders.
BUILD_BASE = Path(os.environ.get("SPRINGLAB_PIP_BUILD_BASE", ROOT / "build" / "pip"))
BUILD_BASE.mkdir(parents=True, exist_ok=True)

setup(
    version=VERSION,
    packages=["springlab"],
    package_dir={"springlab": "python/springlab"},
    ext_modules=[Extension("springlab._springlab", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "build_py": WithData},
    options={"build": {"build_base": str(BUILD_BASE)}, "egg_info": {"egg_base": str(BUILD_BASE)}},
    zip_safe=False,
)
