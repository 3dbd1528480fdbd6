"""Homework 8 in Python: a step of one's own, fn(x, v, force, h) -> (x, v), named as the row of
springlab's table it is and measured at its order (springlab.homework.check), never named when
it is none; run by springlab.Simulation beside the rows, bit for bit the row it is; and whatever
it does wrong (raises, returns nonsense, keeps force() past its step) said plainly."""

import numpy as np
import pytest

import springlab
import springlab.homework


def semi_implicit(x, v, force, h):
    v = v + h * force(x, v)
    return x + h * v, v


def explicit(x, v, force, h):
    return x + h * v, v + h * force(x, v)


def velocity_verlet(x, v, force, h):
    a = force(x, v)
    x1 = x + h * v + 0.5 * h * h * a
    return x1, v + 0.5 * h * (a + force(x1, v))


def rk4(x, v, force, h):
    k1x, k1v = v, force(x, v)
    k2x, k2v = v + 0.5 * h * k1v, force(x + 0.5 * h * k1x, v + 0.5 * h * k1v)
    k3x, k3v = v + 0.5 * h * k2v, force(x + 0.5 * h * k2x, v + 0.5 * h * k2v)
    k4x, k4v = v + h * k3v, force(x + h * k3x, v + h * k3v)
    return x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x), v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)


def order_of(report):
    line = next(text for kind, text in report.lines if text.startswith("order "))
    return float(line.split()[1])


@pytest.mark.parametrize("fn, row, order", [(semi_implicit, "symplectic-euler", 1), (explicit, "euler", 1),
                                            (velocity_verlet, "verlet", 2), (rk4, "rk4", 4)])
def test_each_textbook_step_is_named_and_measured_at_its_order(fn, row, order):
    report = springlab.homework.check(fn)
    assert report.method == row, report.text
    assert report.failed == 0 and report.passed >= 4, report.text
    assert order_of(report) == pytest.approx(order, abs=0.15), report.text


def test_the_energy_is_told_as_the_row_predicts():
    grows = springlab.homework.check(explicit).text
    assert "energy grows: x1.000976562 a step" in grows  # 1 + (w h)^2, w = 8 rad/s, h = 1/256 s
    assert "energy holds" in springlab.homework.check(semi_implicit).text


def test_a_step_of_no_textbook_is_never_named():
    def quarter_gravity(x, v, force, h):  # x + h v + h^2 a / 4: no row's
        a = force(x, v)
        return x + h * v + 0.25 * h * h * a, v + h * a

    report = springlab.homework.check(quarter_gravity)
    assert report.method is None
    assert "quarter_gravity is none of springlab's explicit fixed-step rows" in report.text
    assert report.failed > 0


def test_a_pin_moved_is_named():
    def gravity_everywhere(x, v, force, h):  # adds gravity itself, pins included
        v = v + h * (force(x, v) + np.array([0.0, -8.0, 0.0]))
        return x + h * v, v

    report = springlab.homework.check(gravity_everywhere)
    assert ("fail", next(t for k, t in report.lines if "pinned particle moves" in t)) in report.lines


def test_what_goes_wrong_in_the_function_is_said():
    def raises(x, v, force, h):
        raise ZeroDivisionError("not written yet")

    def half(x, v, force, h):
        return x + h * v

    assert ("fail", "raises raised ZeroDivisionError: not written yet on its call 1 (h = 1/1024 s)") in \
        springlab.homework.check(raises).lines
    assert "half must return (x, v), a pair of arrays of shape (16, 3)" in springlab.homework.check(half).text
    with pytest.raises(TypeError, match="fn must be a function"):
        springlab.homework.check(42)


@pytest.mark.parametrize("scene", ["rope", "cloth"])
def test_a_simulation_steps_it_bit_for_bit_as_the_row_it_is(scene):
    own = springlab.Simulation(scene, method=semi_implicit, steps=120, substeps=2)
    row = springlab.Simulation(scene, method="symplectic-euler", steps=120, substeps=2)
    assert own.method == "semi_implicit"
    own.run()
    row.run()
    assert np.array_equal(own.positions, row.positions) and np.array_equal(own.velocities, row.velocities)
    assert own.counters.force_evals == row.counters.force_evals  # its force() calls, counted as the row's


def test_a_simulation_lets_the_functions_own_errors_through_and_names_it_when_it_diverges():
    def raises(x, v, force, h):
        raise KeyError("mass")

    with pytest.raises(KeyError, match="mass"):
        springlab.Simulation("spring", method=raises, steps=5).run()
    with pytest.raises(springlab.DivergenceError, match="Method explicit, h = 0.5 s. A step of your own has no stated limit"):
        springlab.Simulation("spring", method=explicit, dt=0.5, substeps=1, duration=100).run()
    with pytest.raises(springlab.InputError, match="explicit is a step of your own: springlab states no limit"):
        springlab.Simulation("spring", method=explicit).stability_limit()


def test_force_works_only_within_its_step():
    kept = []

    def keeps(x, v, force, h):
        kept.append(force)
        return semi_implicit(x, v, force, h)

    sim = springlab.Simulation("spring", method=keeps, steps=2)
    sim.run()
    with pytest.raises(RuntimeError, match="only within the step it was given to"):
        kept[0](sim.positions, sim.velocities)


def test_a_step_in_float32_is_judged_to_floats_rounding():
    def in_float(x, v, force, h):
        x, v = x.astype(np.float32), v.astype(np.float32)
        with np.errstate(over="ignore", invalid="ignore"):  # (past the stability limit, float overflows)
            v = v + np.float32(h) * force(x, v).astype(np.float32)
            return x + np.float32(h) * v, v

    report = springlab.homework.check(in_float)
    assert report.method == "symplectic-euler", report.text
    assert "float's rounding (the step returns float32 arrays" in report.text, report.text
    assert report.failed == 0, report.text


def test_a_drag_is_fitted_and_its_sign_held_to():
    def damped(x, v, force, h):  # a = f / m - 0.1 v: a drag rate of 0.1 /s
        v = v + h * (force(x, v) - 0.1 * v)
        return x + h * v, v

    def pushed(x, v, force, h):
        v = v + h * (force(x, v) + 0.1 * v)
        return x + h * v, v

    report = springlab.homework.check(damped)
    assert report.method == "symplectic-euler" and report.failed == 0, report.text
    assert "a global drag on the velocity, a = f / m - c v, c = 0.1 1/s" in report.text, report.text
    wrong = springlab.homework.check(pushed)
    assert wrong.failed_keys == ["damping-sign"], wrong.text


def test_the_report_speaks_the_language_chosen():
    assert "zh-CN" in springlab.languages()
    before = springlab.language()
    try:
        assert springlab.set_language("zh_CN.UTF-8") == "zh-CN"
        text = springlab.homework.check(semi_implicit).text
        assert "半隐式欧拉" in text and "项检查通过" in text, text
    finally:
        springlab.set_language(before)
    assert "checks passed" in springlab.homework.check(semi_implicit).text
