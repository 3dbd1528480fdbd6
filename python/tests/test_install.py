"""`cmake --install` puts a package that imports on its own: from a scratch prefix, with no
source tree or build on its path, it loads the shipped scenes it carries and steps one."""

import os
import subprocess
import sys
from pathlib import Path

import pytest


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
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SPRINGLAB_DATA")}
    env["PYTHONPATH"] = str(site)
    run = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    module, data, t = run.stdout.split("\n")[:3]
    assert Path(module).is_relative_to(prefix)
    assert Path(data).is_relative_to(prefix)  # its own scenes, not the source tree's
    assert float(t) > 0
