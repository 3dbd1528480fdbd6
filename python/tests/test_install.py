"""`cmake --install` and `pip install .` put a package that imports on its own: from a scratch
prefix, with no source tree or build on its path, it loads the shipped scenes it carries and
steps one."""

import os
import subprocess
import sys
from pathlib import Path

import pytest


def run_installed(site, code, cwd):
    """Runs `code` with only the installed package at `site` on the path (no source tree, no
    build, no SPRINGLAB_DATA); returns its printed lines."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SPRINGLAB_DATA")}
    env["PYTHONPATH"] = str(site)
    run = subprocess.run([sys.executable, "-c", code], cwd=cwd, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return run.stdout.split("\n")


def test_the_installed_package_runs_from_its_prefix(tmp_path):
    build = os.environ["SPRINGLAB_BUILD_DIR"]
    if Path(os.environ["SPRINGLAB_PYTHON_INSTALL_DIR"]).is_absolute():
        pytest.skip("SPRINGLAB_PYTHON_INSTALL_DIR is absolute: an install would leave the scratch prefix")
    prefix = tmp_path / "prefix"
    installed = subprocess.run([os.environ.get("SPRINGLAB_CMAKE", "cmake"), "--install", build, "--component", "python",
                                "--prefix", prefix], capture_output=True, text=True)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    site = prefix / os.environ["SPRINGLAB_PYTHON_INSTALL_DIR"]
    assert (site / "springlab" / "data" / "assets" / "scenes" / "rope.json").is_file()

    code = ("import springlab\n"
            "sim = springlab.Simulation('rope', method='rk4', steps=10)\n"
            "sim.run()\n"
            "print(springlab.__file__, springlab.data_dir(), sim.t, sep='\\n')\n")
    module, data, t = run_installed(site, code, tmp_path)[:3]
    assert Path(module).is_relative_to(prefix)
    assert Path(data).is_relative_to(prefix)  # its own scenes, not the source tree's
    assert float(t) > 0


def test_pip_installs_the_package_offline(tmp_path):
    # `python3 -m pip install --no-build-isolation .` as docs/python.md gives it, into a scratch
    # folder, from Debian's pip, setuptools and wheel with no index: this build's CMake folder is
    # built (up to date: a no-op) and packaged, rather than a fresh one (minutes; the README gives
    # the time of that). Nothing is written into the source tree's tracked files.
    source = Path(os.environ["SPRINGLAB_SOURCE_DIR"])
    site = tmp_path / "site"
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SPRINGLAB_DATA")}
    env.update(SPRINGLAB_CMAKE_BUILD_DIR=os.environ["SPRINGLAB_BUILD_DIR"],
               SPRINGLAB_PIP_BUILD_BASE=str(tmp_path / "build"), PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    pip = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation", "--no-deps", "--target",
                          str(site), str(source)], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=280)
    assert pip.returncode == 0, pip.stdout[-3000:] + pip.stderr[-3000:]
    assert (site / "springlab" / "data" / "assets" / "tableaux" / "heun.json").is_file()

    code = ("import springlab, springlab.homework\n"
            "sim = springlab.Simulation('rope', method='verlet', steps=10)\n"
            "sim.run()\n"
            "r = springlab.homework.check(lambda x, v, force, h: (x + h * v, v + h * force(x, v)))\n"
            "print(springlab.__file__, springlab.data_dir(), r.method, sep='\\n')\n")
    module, data, method = run_installed(site, code, tmp_path)[:3]
    assert Path(module).is_relative_to(site) and Path(data).is_relative_to(site)
    assert method == "euler"
