"""A Simulation stepped from Python: its state as numpy views of the simulation's own arrays (no
copy, read-only, keeping the simulation alive), its energies against the state, its physics
against the exact solution, and its controls."""

import gc
import math
import weakref

import numpy as np
import pytest

import springlab


def test_the_state_is_a_read_only_view_of_the_simulations_arrays_not_a_copy():
    sim = springlab.Simulation("rope", method="symplectic-euler")
    x, again = sim.positions, sim.positions
    assert x.shape == (16, 3) and x.dtype == np.float64
    assert np.shares_memory(x, again)  # the same doubles, twice: no copy
    # Each coordinate is one contiguous column, the columns a padded stride apart (state.hpp).
    assert x.strides[0] == 8 and x.strides[1] >= 8 * 16 and x.strides[1] % 64 == 0
    assert not x.flags.writeable
    with pytest.raises(ValueError):
        x[0, 0] = 1.0
    assert not np.shares_memory(sim.positions, sim.velocities)


def test_a_view_keeps_its_simulation_alive():
    sim = springlab.Simulation("rope", method="rk4")
    sim.advance(10)
    alive = weakref.ref(sim)
    x = sim.positions
    expected = x.copy()
    del sim
    gc.collect()
    assert alive() is not None  # held by the view
    assert np.array_equal(x, expected)
    del x
    gc.collect()
    assert alive() is None


def test_reading_the_state_again_after_a_step_gives_the_new_state():
    sim = springlab.Simulation("rope", method="rk4")
    before = sim.positions.copy()
    assert sim.step()
    assert sim.t == pytest.approx(sim.dt) and sim.steps_taken == 1
    assert not np.array_equal(sim.positions, before)
    assert sim.advance(9) == 9 and sim.steps_taken == 10


def test_energies_are_those_of_the_state():
    # `spring`: a unit mass on a spring (k_s = 100, rest length 1) to an anchor at the origin.
    sim = springlab.Simulation("spring", method="rk4", dt=0.01)
    sim.advance(37)
    x, v = sim.positions[1], sim.velocities[1]
    e = sim.energy()
    assert e.kinetic == pytest.approx(0.5 * v @ v, rel=1e-13)
    assert e.spring == pytest.approx(0.5 * 100 * (np.linalg.norm(x) - 1) ** 2, rel=1e-12)
    assert (e.gravity, e.field) == (0.0, 0.0)
    assert e.total == e.kinetic + e.spring + e.gravity + e.field
    assert e.potential == e.spring + e.gravity + e.field


def test_rk4_follows_the_exact_oscillation():
    # x(t) = 1 + 0.5 cos(10 t) (docs/numerics.md). RK4 at h w = 0.1 lags the phase by about
    # (h w)^5 / 120 a step: 8e-6 rad over 100 steps, 4e-6 m at this amplitude.
    sim = springlab.Simulation("spring", method="rk4", dt=0.01, substeps=1, steps=100)
    sim.run()
    assert sim.t == pytest.approx(1.0)
    assert sim.positions[1, 0] == pytest.approx(1 + 0.5 * math.cos(10 * sim.t), abs=5e-6)
    assert sim.counters.force_evals == 4 * 100


def test_the_state_hash_tells_states_apart_and_reset_returns_to_the_start():
    scene = springlab.load_scene("rope")
    a = springlab.Simulation(scene, method="verlet")
    b = springlab.Simulation(scene, method="verlet")
    start = a.state_hash()
    a.advance(100)
    b.advance(100)
    assert a.state_hash() == b.state_hash() != start
    a.reset()
    assert a.state_hash() == start and a.t == 0.0
    assert np.array_equal(a.positions, scene.positions)


def test_settings_change_as_the_app_changes_them():
    sim = springlab.Simulation("spring", method="euler", dt=0.01, substeps=1)
    assert (sim.method, sim.dt, sim.substeps, sim.auto_substeps) == ("euler", 0.01, 1, False)
    sim.set_method("heun")
    sim.set_dt(0.02)
    sim.set_substeps(4)
    assert (sim.method, sim.h) == ("heun", 0.005)
    sim.set_substeps("auto")
    assert sim.auto_substeps
    sim.set_stiffness(400.0)
    assert sim.stability_limit().mode.w == pytest.approx(20.0)
    with pytest.raises(springlab.InputError, match=r"^--dt: must be in \(0, 1\] s, got 2$"):
        sim.set_dt(2.0)
    with pytest.raises(springlab.InputError, match=r"^--substeps: "):
        sim.set_substeps(0)


def test_run_takes_the_steps_run_would():
    # The scene's duration over dt, or duration=, or steps=.
    scene = springlab.load_scene("spring")
    assert springlab.Simulation(scene).planned_steps == round(scene.duration / scene.dt)
    assert springlab.Simulation("spring", duration=0.5, dt=0.01).planned_steps == 50
    sim = springlab.Simulation("spring", steps=7)
    assert sim.run() == 7 and sim.steps_taken == 7


def test_every_shipped_scene_loads_steps_and_is_analysed():
    for name in springlab.scenes():
        sim = springlab.Simulation(name)
        assert sim.advance(5) == 5, name
        assert np.isfinite(sim.positions).all() and np.isfinite(sim.energy().total), name
        # The analysis says something true of each: where the scene oscillates, its highest
        # frequency within Gershgorin's bound, and each row's limit of its kind (stable-at-any-step
        # rows infinite, adaptive ones none, symplectic Euler's and Verlet's within 2 / w_max,
        # which damping only shortens); where it does not, the reason.
        analysis = sim.stability()
        if analysis.oscillates:
            assert 0 < analysis.w_max <= analysis.w_bound * (1 + 1e-9), name
        else:
            assert analysis.no_modes_reason, name
        for row in springlab.methods():
            h = analysis.limit(row.name).h
            if row.any_step:
                assert h == math.inf, (name, row.name, h)
            elif row.adaptive:
                assert math.isnan(h), (name, row.name, h)
            elif row.name in ("symplectic-euler", "verlet") and analysis.oscillates:
                assert 0 < h * analysis.w_max <= 2 * (1 + 1e-9), (name, row.name, h)
    # On the undamped spring, symplectic Euler's limit is 2 / w exactly (w = 10 rad/s).
    assert springlab.Simulation("spring").stability().limit("symplectic-euler").h == pytest.approx(0.2, rel=1e-9)
