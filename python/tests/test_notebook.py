"""docs/notebooks/work-precision.ipynb executes headless from the bindings and draws its charts,
so that it cannot rot: run as a reader would (nbconvert, Debian's kernel), into a scratch folder,
never into the repository."""

import json
import os
import subprocess
import sys
from pathlib import Path

SOURCE = Path(os.environ.get("SPRINGLAB_SOURCE_DIR", Path(__file__).resolve().parents[2]))
NOTEBOOK = SOURCE / "docs" / "notebooks" / "work-precision.ipynb"


def code_cells(notebook):
    return [c for c in notebook["cells"] if c["cell_type"] == "code"]


def test_the_stored_notebook_has_no_outputs():
    # Outputs are made by running it; stored, they would go stale (and weigh).
    stored = json.loads(NOTEBOOK.read_text())
    assert code_cells(stored) and all(not c.get("outputs") for c in code_cells(stored))


def test_the_notebook_executes_and_draws_its_charts(tmp_path):
    # The kernel draws with Jupyter's inline backend, headless: no MPLBACKEND to override it.
    env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
    env.update(JUPYTER_RUNTIME_DIR=str(tmp_path / "runtime"), IPYTHONDIR=str(tmp_path / "ipython"))
    run = subprocess.run([sys.executable, "-m", "nbconvert", "--execute", "--to", "notebook",
                          "--ExecutePreprocessor.timeout=120", "--output-dir", str(tmp_path), str(NOTEBOOK)],
                         cwd=tmp_path, env=env, capture_output=True, text=True, timeout=240)
    assert run.returncode == 0, run.stderr[-4000:]
    executed = json.loads((tmp_path / NOTEBOOK.name).read_text())
    outputs = [o for c in code_cells(executed) for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    images = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(images) >= 2  # the work-precision diagram and the limiting mode
