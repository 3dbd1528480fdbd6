"""Python steps a scene to the very bits `springlab run` reaches: the same scene, options and
number of steps give the same positions, velocities, time and energies, compared exactly (the
CSV trace writes each number so that it reads back as the same double)."""

import csv

import numpy as np
import pytest

import springlab

# (scene, the command line's options, the same as Python keywords, steps). Chosen to go through
# each kind of method (Runge-Kutta, partitioned, implicit, adaptive, iterative, a tableau read as
# data), automatic and fixed sub-steps, --set, --ks/--kd and contacts.
CASES = [
    ("rope", ["--method", "rk4"], dict(method="rk4"), 300),
    ("rope", ["--method", "symplectic-euler", "--set", "rope.nodes=24"],
     dict(method="symplectic-euler", set={"rope.nodes": 24}), 400),
    ("rope", ["--method", "verlet", "--ks", "3000"], dict(method="verlet", ks=3000), 300),
    ("rope", ["--method", "euler"], dict(method="euler"), 60),
    ("rope", ["--method", "implicit-euler", "--dt", "0.002"], dict(method="implicit-euler", dt=0.002), 100),
    ("rope", ["--method", "heun"], dict(method="heun"), 200),
    ("damped-spring", ["--method", "midpoint", "--dt", "0.005", "--substeps", "3", "--kd", "1.5"],
     dict(method="midpoint", dt=0.005, substeps=3, kd=1.5), 200),
    ("spring", ["--method", "rk45", "--tol", "1e-7"], dict(method="rk45", tol=1e-7), 100),
    ("cloth", ["--method", "xpbd", "--set", "cloth.width=8", "--set", "cloth.height=8", "--iterations", "3"],
     dict(method="xpbd", set=["cloth.width=8", "cloth.height=8"], iterations=3), 40),
    ("cloth-sphere", ["--method", "symplectic-euler", "--set", "cloth.width=10", "--set", "cloth.height=10"],
     dict(method="symplectic-euler", set={"cloth.width": 10, "cloth.height": 10}), 150),
]


def last_row(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, last = rows[0], rows[-1]
    return dict(zip(header, (float(x) for x in last)))


def state_of(row, n):
    x = np.array([[row[f"{c}{i}"] for c in "xyz"] for i in range(n)])
    v = np.array([[row[f"v{c}{i}"] for c in "xyz"] for i in range(n)])
    return x, v


@pytest.mark.parametrize("scene,flags,options,steps", CASES, ids=[f"{c[0]}-{c[2]['method']}" for c in CASES])
def test_python_reaches_the_command_lines_bits(cli, tmp_path, scene, flags, options, steps):
    trace = tmp_path / "trace.csv"
    result = cli("run", scene, *flags, "--steps", steps, "--csv", trace, "--every", steps)
    assert result.returncode == 0, result.stderr
    row = last_row(trace)

    sim = springlab.Simulation(scene, steps=steps, **options)
    start = sim.positions.copy()
    assert sim.run() == steps
    x, v = state_of(row, sim.particle_count)
    assert not np.array_equal(x, start), "the run should move the scene"
    assert sim.t == row["t"]
    assert np.array_equal(sim.positions, x)
    assert np.array_equal(sim.velocities, v)
    e = sim.energy()
    assert (e.kinetic, e.potential, e.total) == (row["kinetic"], row["potential"], row["total"])

    # The comparison tells one step from another: a step more is not the same state.
    sim.step()
    assert not np.array_equal(sim.positions, x)


def test_the_same_scene_from_a_loaded_scene_and_by_name_gives_the_same_bits():
    scene = springlab.load_scene("rope", set={"rope.nodes": 24})
    by_scene = springlab.Simulation(scene, method="verlet")
    by_name = springlab.Simulation("rope", method="verlet", set="rope.nodes=24")
    by_scene.advance(250)
    by_name.advance(250)
    assert by_scene.state_hash() == by_name.state_hash()
