"""The method table as Python reads it: the rows `springlab list` prints, their families,
limits and tableaux, and the rows made from tableaux."""

import math
import re

import numpy as np
import pytest

import springlab


def test_the_rows_are_those_springlab_list_prints(cli):
    result = cli("list")
    assert result.returncode == 0
    listed = re.findall(r"^method  (\S+) +(.+?): order (\d+), force evaluations per step: (.+), (.+); "
                        r"keeps on a free body: (.+)$", result.stdout, re.M)
    rows = springlab.methods()
    assert [(m.name, m.label, str(m.order), m.evaluations, m.keeps) for m in rows] == [l[:4] + l[5:] for l in listed]
    assert len(rows) >= 12


def test_families_and_undamped_limits_are_the_tables():
    rows = {m.name: m for m in springlab.methods()}
    F = springlab.MethodFamily
    assert rows["rk4"].family == F.RUNGE_KUTTA and rows["rk4"].undamped_limit == pytest.approx(2 * math.sqrt(2))
    assert rows["symplectic-euler"].family == F.PARTITIONED and rows["symplectic-euler"].undamped_limit == 2
    assert rows["euler"].undamped_limit == 0 and rows["euler"].damping_helps
    assert rows["implicit-euler"].implicit and math.isinf(rows["implicit-euler"].undamped_limit)
    assert rows["rk45"].adaptive and math.isnan(rows["rk45"].undamped_limit)
    assert rows["xpbd"].family == F.ITERATIVE and rows["xpbd"].any_step
    assert rows["verlet"].definite_form(0.0) == (1.0, 4.0, 4.0)
    assert rows["rk4"].definite_form() is None


def test_a_runge_kutta_rows_tableau_gives_its_stability_function():
    rk4 = springlab.method("rk4")
    t = rk4.tableau
    assert t.stages == 4 and t.explicit
    assert np.allclose(t.b, [1 / 6, 1 / 3, 1 / 3, 1 / 6]) and np.allclose(t.c, [0, 0.5, 0.5, 1])
    # R(z) = sum z^j / j! up to the order, for an explicit method of order 4 with 4 stages.
    assert np.allclose(t.numerator, [1, 1, 1 / 2, 1 / 6, 1 / 24]) and list(t.denominator) == [1.0]
    z = complex(-0.7, 1.9)
    assert t.stability_function(z) == pytest.approx(np.polyval(t.numerator[::-1], z))
    assert springlab.method("symplectic-euler").tableau is None


def test_a_tableau_named_as_a_method_becomes_a_row():
    heun = springlab.method("heun")
    assert heun.name == "heun" and heun.family == springlab.MethodFamily.RUNGE_KUTTA
    assert "heun" in [m.name for m in springlab.methods()]
    assert heun.source.name and heun.source.b == ["1/2", "1/2"]
    assert np.array_equal(heun.tableau.a, [[0, 0], [1, 0]])
    # Its R(z) is midpoint's: 1 + z + z^2 / 2.
    assert np.allclose(heun.tableau.numerator, [1, 1, 0.5])
    assert springlab.method("rk4").source is None


def test_a_users_tableau_is_listed_apart_from_the_built_in_methods(tmp_path):
    # Heun's third-order tableau written by a user: once used, it is a row of the table, and the
    # messages that list the methods name it apart ("yours: ..."), never among the built-in ones.
    path = tmp_path / "my-heun3.json"
    path.write_text('{"name": "my-heun3", "A": [[0, 0, 0], ["1/3", 0, 0], [0, "2/3", 0]], '
                    '"b": ["1/4", 0, "3/4"], "c": [0, "1/3", "2/3"]}')
    row = springlab.method(str(path))
    assert row.name == "my-heun3" and not row.built_in and springlab.method("vbd").built_in
    assert "my-heun3" in [m.name for m in springlab.methods()]
    assert "my-heun3" not in [m.name for m in springlab.methods(built_in=True)]
    with pytest.raises(springlab.InputError) as error:
        springlab.method("no-such-method")
    said = str(error.value)
    built_in = said.split("methods: ")[1].split(";")[0]
    assert "my-heun3" not in built_in and "vbd" in built_in, said
    assert "yours: my-heun3" in said, said


def test_one_modes_limit_in_closed_form():
    w, c = 10.0, 0.0
    assert springlab.mode_limit("symplectic-euler", c, w * w) == pytest.approx(2 / w)
    assert springlab.mode_limit("rk4", c, w * w) == pytest.approx(2 * math.sqrt(2) / w)
    # Explicit Euler with damping c: stable while h <= c / w^2.
    assert springlab.mode_limit("euler", 2.0, 100.0) == pytest.approx(0.02)
