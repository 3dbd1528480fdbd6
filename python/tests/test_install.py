"""`cmake --install` and docs/python.md's `pip install .` route put a package that imports on its own: from a scratch
prefix, with no source tree or build on its path, it loads the shipped scenes it carries and
steps one."""

import json
import os
import shlex
import shutil
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


def documented_route(source):
    """The three commands of docs/python.md's "Installing, in a virtual environment", as written."""
    text = (source / "docs" / "python.md").read_text()
    block = text[text.index("<!-- python/tests/test_install.py runs these"):]
    block = block[block.index("```sh\n") + len("```sh\n"):]
    return block[:block.index("```")].strip().splitlines()


def test_the_documented_route_installs_into_a_virtual_environment(tmp_path):
    # docs/python.md's commands verbatim, the environment's folder in a scratch one: a virtual
    # environment with Debian's packages, pip from the source tree offline (this build's CMake
    # folder built, a no-op, and packaged, rather than a fresh build of minutes), the kernel.
    source = Path(os.environ["SPRINGLAB_SOURCE_DIR"])
    lines = documented_route(source)
    assert len(lines) == 3 and all("~/springlab-env" in line for line in lines), lines
    venv = tmp_path / "springlab-env"
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SPRINGLAB_DATA", "JUPYTER_PATH")}
    env.update(SPRINGLAB_CMAKE_BUILD_DIR=os.environ["SPRINGLAB_BUILD_DIR"], SPRINGLAB_PIP_BUILD_BASE=str(tmp_path / "build"),
               PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", JUPYTER_DATA_DIR=str(tmp_path / "jupyter-user"))
    for line in lines:
        run = subprocess.run(shlex.split(line.replace("~/springlab-env", str(venv))), cwd=source, env=env,
                             capture_output=True, text=True, timeout=280)
        assert run.returncode == 0, line + "\n" + run.stdout[-3000:] + run.stderr[-3000:]
    python = venv / "bin" / "python"
    site = next((venv / "lib").glob("python3*/site-packages"))

    code = ("import springlab, springlab.homework\n"
            "sim = springlab.Simulation('rope', method='verlet', steps=10)\n"
            "sim.run()\n"
            "r = springlab.homework.check(lambda x, v, force, h: (x + h * v, v + h * force(x, v)))\n"
            "print(springlab.__file__, springlab.data_dir(), r.method, sep='\\n')\n")
    run = subprocess.run([python, "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    module, data, method = run.stdout.split("\n")[:3]
    assert Path(module).is_relative_to(site) and Path(data).is_relative_to(site)
    assert method == "euler"

    # The kernel is the environment's Python: a notebook executed by Jupyter imports springlab.
    kernel = json.loads((venv / "share" / "jupyter" / "kernels" / "python3" / "kernel.json").read_text())
    assert Path(kernel["argv"][0]) == python
    notebook = tmp_path / "probe.ipynb"
    notebook.write_text(json.dumps({
        "cells": [{"cell_type": "code", "metadata": {}, "execution_count": None, "outputs": [],
                   "source": ["import springlab\n", "print(springlab.__file__)"]}],
        "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3 (ipykernel)", "language": "python"}},
        "nbformat": 4, "nbformat_minor": 5}))
    run = subprocess.run([python, "-m", "nbconvert", "--execute", "--to", "notebook", "--output", "ran.ipynb", notebook],
                         cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-3000:]
    printed = json.loads((tmp_path / "ran.ipynb").read_text())["cells"][0]["outputs"][0]["text"]
    assert Path("".join(printed).strip()).is_relative_to(site)


def test_a_python_without_numpy_is_told_at_import(tmp_path):
    # Another interpreter first on PATH (a pyenv Python) without numpy: `import springlab` says so,
    # and which Python the module was built for, instead of a ModuleNotFoundError later that
    # seems to be a student's function's.
    run = subprocess.run([sys.executable, "-c", "import sys; sys.modules['numpy'] = None; import springlab"],
                         cwd=tmp_path, capture_output=True, text=True)
    assert run.returncode != 0
    last = run.stderr.strip().split("\n")[-1]
    assert "numpy is missing in this Python" in last and "was built for" in last, last
    assert "pip install --no-build-isolation" in last


def test_a_module_built_for_another_python_is_told_at_import(tmp_path):
    # The module's file for another ABI (as a Python 3.12 would see a 3.11 build): the import names it.
    build = Path(os.environ["SPRINGLAB_BUILD_DIR"]) / "python" / "springlab"
    package = tmp_path / "springlab"
    shutil.copytree(build, package)
    for module in package.glob("_springlab*.so"):
        module.rename(package / "_springlab.cpython-399-x86_64-linux-gnu.so")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(tmp_path)
    run = subprocess.run([sys.executable, "-c", "import springlab"], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert run.returncode != 0
    last = run.stderr.strip().split("\n")[-1]
    assert "the compiled module cannot be loaded" in last and "_springlab.cpython-399-x86_64-linux-gnu.so" in last, last
