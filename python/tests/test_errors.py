"""Bad input raises springlab.InputError (a ValueError) whose message is the line the command
line prints after 'springlab: ' for the same input, exiting with status 2; a run that diverges
raises springlab.DivergenceError with `run`'s line (status 3)."""

import pytest

import springlab
from conftest import cli_message

# (the command line's arguments, the same call in Python)
BAD_RUNS = [
    (["run", "ropez"], lambda: springlab.Simulation("ropez")),
    (["run", "no/such/scene.json"], lambda: springlab.Simulation("no/such/scene.json")),
    (["run", "rope", "--method", "rk5"], lambda: springlab.Simulation("rope", method="rk5")),
    (["run", "rope", "--set", "rope.nodes=-3"], lambda: springlab.Simulation("rope", set={"rope.nodes": -3})),
    (["run", "rope", "--set", "rope.colour=3"], lambda: springlab.Simulation("rope", set="rope.colour=3")),
    (["run", "rope", "--set", "nodes"], lambda: springlab.Simulation("rope", set=["nodes"])),
    (["run", "cloth", "--set", "cloth.width=big"], lambda: springlab.Simulation("cloth", set={"cloth.width": "big"})),
    (["run", "rope", "--dt=-1"], lambda: springlab.Simulation("rope", dt=-1)),
    (["run", "rope", "--substeps", "2.5"], lambda: springlab.Simulation("rope", substeps=2.5)),
    (["run", "rope", "--kd=-2"], lambda: springlab.Simulation("rope", kd=-2)),
    (["run", "rope", "--rho", "1"], lambda: springlab.Simulation("rope", rho=1)),
]

BAD_SWEEPS = [
    (["--methods", "euler,rk5"], dict(methods=["euler", "rk5"])),
    (["--points", "1"], dict(points=1)),
    (["--dt-range", "0.01:0.001"], dict(dt_range=(0.01, 0.001))),
    (["--duration", "0.001"], dict(duration=0.001)),
]


@pytest.mark.parametrize("args,call", BAD_RUNS, ids=[" ".join(a[1:]) for a, _ in BAD_RUNS])
def test_bad_input_raises_the_command_lines_message(cli, args, call):
    result = cli(*args)
    assert result.returncode == 2, result.stderr
    with pytest.raises(springlab.InputError) as caught:
        call()
    assert str(caught.value) == cli_message(result)
    assert isinstance(caught.value, ValueError)


@pytest.mark.parametrize("flags,options", BAD_SWEEPS, ids=[" ".join(f) for f, _ in BAD_SWEEPS])
def test_a_bad_sweep_raises_compares_message(cli, tmp_path, flags, options):
    result = cli("compare", "spring", "--out", tmp_path, "--no-charts", *flags)
    assert result.returncode == 2, result.stderr
    with pytest.raises(springlab.InputError) as caught:
        springlab.sweep("spring", **options)
    assert str(caught.value) == cli_message(result)


def test_loading_a_bad_scene_raises_the_same_message_as_running_it(cli):
    with pytest.raises(springlab.InputError) as caught:
        springlab.load_scene("rope", set={"rope.nodes": -3})
    assert str(caught.value) == cli_message(cli("run", "rope", "--set", "rope.nodes=-3"))


def test_an_unknown_method_raises_wherever_a_method_is_named(cli):
    expected = cli_message(cli("run", "rope", "--method", "rk5"))
    analysis = springlab.StabilityAnalysis(springlab.load_scene("spring"))
    for call in (lambda: springlab.method("rk5"), lambda: analysis.limit("rk5"),
                 lambda: springlab.Simulation("spring").set_method("rk5")):
        with pytest.raises(springlab.InputError) as caught:
            call()
        assert str(caught.value) == expected


def test_a_diverging_run_raises_runs_message(cli):
    # The stiff chain at one step a frame: explicit Euler explodes within 0.07 s.
    result = cli("run", "stiff", "--method", "euler", "--duration", "1")
    assert result.returncode == 3, result.stderr
    sim = springlab.Simulation("stiff", method="euler", duration=1)
    with pytest.raises(springlab.DivergenceError) as caught:
        sim.run()
    assert str(caught.value) == cli_message(result)
    # The state kept is the last good one the message names.
    assert sim.diverged and sim.divergence.t == sim.t and sim.divergence.method == "euler"
    assert not sim.step()  # nothing more once diverged


def test_an_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="'metod'"):
        springlab.Simulation("spring", metod="rk4")
    with pytest.raises(TypeError, match="'point'"):
        springlab.sweep("spring", point=3)


@pytest.mark.parametrize("flag,options", [(["--steps", "2.5"], dict(steps=2.5)),
                                          (["--iterations", "0"], dict(iterations=0)),
                                          (["--threads", "-1"], dict(threads=-1))])
def test_a_bad_whole_number_raises_what_the_parser_says(cli, flag, options):
    # The command line refuses these while parsing its flags, and adds a pointer to --help.
    result = cli("run", "rope", *flag)
    assert result.returncode == 2
    with pytest.raises(springlab.InputError) as caught:
        springlab.Simulation("rope", **options)
    assert str(caught.value) + " (see springlab --help)" == cli_message(result)
