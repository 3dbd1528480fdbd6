"""The stability analysis from Python: each method's limit, whether exact, and the limiting mode
(frequency, damping ratio, shape), against the closed forms of docs/numerics.md and against what
`springlab run` states."""

import math

import numpy as np
import pytest

import springlab


def analysis(scene, **overrides):
    return springlab.StabilityAnalysis(springlab.load_scene(scene, set=overrides or None))


def test_the_springs_limits_are_the_closed_forms():
    a = analysis("spring")  # w = 10 rad/s, no damping
    assert a.dense and a.oscillates and a.w_max == pytest.approx(10.0)
    assert a.limit("symplectic-euler").h == pytest.approx(0.2) and a.limit("symplectic-euler").exact
    assert a.limit("rk4").h == pytest.approx(2 * math.sqrt(2) / 10)
    assert a.limit("euler").h == 0.0  # never stable without damping
    assert math.isinf(a.limit("implicit-euler").h) and a.limit("implicit-euler").mode is None
    assert math.isnan(a.limit("rk45").h)
    mode = a.limit("rk4").mode
    assert mode.w == pytest.approx(10.0) and mode.damping_ratio == 0.0
    # The free particle moves along the spring; the anchor does not move.
    assert np.allclose(np.abs(mode.shape), [[0, 0, 0], [1, 0, 0]], atol=1e-12)


def test_damping_buys_explicit_euler_a_limit():
    # damped-spring: k_d = 2, k_s = 100, so h <= k_d / k_s = 0.02 s.
    limit = analysis("damped-spring").limit("euler")
    assert limit.h == pytest.approx(0.02) and limit.exact
    assert limit.mode.damping_ratio == pytest.approx(2 / (2 * 10))
    assert limit.description.startswith("stable up to h = 0.02")


def test_the_hanging_ropes_limiting_mode():
    a = analysis("rope")
    scene = springlab.load_scene("rope")
    for method in ("symplectic-euler", "verlet", "rk4", "euler"):
        limit = a.limit(method)
        mode = limit.mode
        shape = mode.shape
        assert shape.shape == (16, 3) and not shape.flags.writeable
        assert np.abs(shape[scene.pinned]).max() == 0  # the pin does not move
        assert np.linalg.norm(shape, axis=1).max() == pytest.approx(1.0)  # scaled so
        assert np.abs(shape[:, 2]).max() < 1e-12  # a planar rope moves in its plane
        # The limit is that mode's own, in closed form (one damped mode, springlab.mode_limit).
        assert limit.h == pytest.approx(springlab.mode_limit(method, mode.c, mode.w ** 2), rel=1e-6)
        assert mode.damping_ratio == pytest.approx(mode.c / (2 * mode.w))


def test_the_limit_is_the_one_run_states(cli):
    result = cli("run", "rope", "--method", "rk4", "--steps", "1")
    assert result.returncode == 0, result.stderr
    sim = springlab.Simulation("rope", method="rk4")
    a, limit = sim.stability(), sim.stability_limit()
    g = lambda x: "%.6g" % x  # noqa: E731  (the command line's format)
    line = (f"stability  w_max = {g(a.w_max)} rad/s (Gershgorin bound {g(a.w_bound)}), h w_max = {g(sim.h * a.w_max)}; "
            f"rk4: {limit.description}, set by a mode of {g(limit.mode.w)} rad/s with damping ratio "
            f"{g(limit.mode.damping_ratio)} (at the scene's equilibrium, every eigenvalue, ")
    assert line in result.stdout
    # The simulation's analysis is the loaded scene's.
    assert analysis("rope").limit("rk4").h == limit.h


def test_a_large_scenes_limit_may_be_a_lower_bound():
    # Above dense_dofs free coordinates the damping-limited methods' limits come from the
    # numerical range and are stated as 'at least' (never optimistic).
    scene = springlab.load_scene("rope")
    dense = springlab.StabilityAnalysis(scene)
    sparse = springlab.StabilityAnalysis(scene, dense_dofs=10)
    assert not sparse.dense and len(sparse.eigenvalues) == 0
    exact, bound = dense.limit("euler"), sparse.limit("euler")
    assert exact.exact and bound.h <= exact.h * (1 + 1e-9)
    assert bound.description.startswith("stable at least up to") or bound.exact
