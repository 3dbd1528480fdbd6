"""The accuracy sweep from Python: `springlab compare`'s runs as numpy arrays, the same numbers
as its results.csv, and the orders of docs/numerics.md."""

import csv
import json

import numpy as np
import pytest

import springlab

# Explicit Euler's error must stay below a tenth of the motion to count for its order: steps up
# to 5 ms over 1 s.
OPTIONS = dict(methods=["euler", "verlet", "rk4"], points=4, dt_range=(5e-4, 5e-3), duration=1.0,
               stability_budget=0, drift_duration=0, threads=1)
FLAGS = ["--methods", "euler,verlet,rk4", "--points", 4, "--dt-range", "0.0005:0.005", "--duration", 1,
         "--stability-budget", 0, "--drift-duration", 0, "--threads", 1]


@pytest.fixture(scope="module")
def result():
    return springlab.sweep("spring", **OPTIONS)


def test_the_runs_are_arrays_a_row_a_run(result):
    runs = result.runs
    n = len(runs["method"])
    assert n == 3 * 4 and all(len(column) == n for column in runs.values())
    assert list(dict.fromkeys(runs["method"])) == ["euler", "verlet", "rk4"]
    assert result.reference == "exact solution" and result.w_max == pytest.approx(10.0)
    rk4 = runs["method"] == "rk4"
    assert np.all(np.diff(runs["h"][rk4]) < 0)  # coarse to fine
    assert np.all(runs["work"][rk4] == runs["force_evals"][rk4])  # no solver iterations
    assert np.all(runs["force_evals"][rk4] == np.round(4 * 1.0 / runs["h"][rk4]))
    assert not runs["diverged"].any()


def test_the_fitted_orders_are_the_methods_orders(result):
    summary = result.summary
    order = dict(zip(summary["method"], summary["order"]))
    assert order["euler"] == pytest.approx(1, abs=0.15)
    assert order["verlet"] == pytest.approx(2, abs=0.1)
    assert order["rk4"] == pytest.approx(4, abs=0.1)
    assert list(summary["order_table"]) == [1, 2, 4]


def test_the_runs_are_compares_results(cli, tmp_path, result):
    out = cli("compare", "spring", "--out", tmp_path, "--no-charts", *FLAGS)
    assert out.returncode == 0, out.stderr
    with open(tmp_path / "results.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    runs = result.runs
    assert [r["method"] for r in rows] == list(runs["method"])
    assert [int(r["force_evals"]) for r in rows] == list(runs["force_evals"])
    # results.csv writes 10 significant digits.
    assert np.allclose([float(r["step"]) for r in rows], runs["h"], rtol=1e-9, atol=0)
    assert np.allclose([float(r["error"]) for r in rows], runs["error"], rtol=1e-9, atol=0)


def test_a_sweep_from_a_loaded_scene_keeps_its_overrides(tmp_path):
    # The same sweep from the scene with its override, and from a file that is that scene: the
    # same numbers, to the bit (one thread); from the rope as shipped (16 nodes), others.
    options = dict(methods="rk4,symplectic-euler", points=2, dt_range=(5e-4, 1e-3), duration=0.05,
                   stability_budget=0, drift_duration=0, threads=1)
    overridden = springlab.sweep(springlab.load_scene("rope", set={"rope.nodes": 6}), **options)
    rope = json.loads(open(f"{springlab.data_dir()}/assets/scenes/rope.json").read())
    rope["generators"][0]["nodes"] = 6
    (tmp_path / "rope6.json").write_text(json.dumps(rope))
    six = springlab.sweep(springlab.load_scene(str(tmp_path / "rope6.json")), **options)
    shipped = springlab.sweep(springlab.load_scene("rope"), **options)
    assert overridden.reference.startswith("rk4 at h = ")
    assert set(overridden.runs["method"]) == {"rk4", "symplectic-euler"}
    assert np.all(overridden.runs["error"] > 0) and np.all(np.isfinite(overridden.runs["error"]))
    assert np.array_equal(overridden.runs["error"], six.runs["error"])
    assert not np.array_equal(overridden.runs["error"], shipped.runs["error"])