"""Scenes loaded as the command line loads them: by name or file, with --set overrides."""

import os
from pathlib import Path

import numpy as np
import pytest

import springlab

SOURCE = Path(os.environ.get("SPRINGLAB_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def test_the_shipped_scenes_are_the_files_in_assets():
    assert springlab.scenes() == sorted(p.stem for p in (SOURCE / "assets" / "scenes").glob("*.json"))
    assert "heun" in springlab.tableaux()


def test_a_scene_by_name_is_its_file():
    by_name = springlab.load_scene("rope")
    by_file = springlab.load_scene(str(SOURCE / "assets" / "scenes" / "rope.json"))
    assert by_name.name == by_file.name == "rope"
    assert np.array_equal(by_name.positions, by_file.positions)
    assert by_name.particle_count == 16 and by_name.spring_count == 15
    assert by_name.methods == ["euler", "verlet"]
    assert by_name.substeps == "auto"


def test_overrides_as_strings_lists_and_dicts_are_the_same():
    a = springlab.load_scene("cloth", set=["cloth.width=12", "cloth.height=7"])
    b = springlab.load_scene("cloth", set={"cloth.width": 12, "cloth.height": 7})
    c = springlab.load_scene("rope", set="rope.nodes=64")
    assert a.particle_count == b.particle_count == 12 * 7
    assert np.array_equal(a.positions, b.positions)
    assert a.overrides == ["cloth.width=12", "cloth.height=7"]
    assert c.particle_count == 64
    # A JSON value through a dict: a list for the gravity.
    g = springlab.load_scene("rope", set={"gravity": [0, -1.62, 0]})
    assert list(g.gravity) == [0, -1.62, 0]


def test_the_rope_is_the_same_rope_finer():
    coarse, fine = springlab.load_scene("rope"), springlab.load_scene("rope", set={"rope.nodes": 64})
    assert coarse.masses.sum() == pytest.approx(1.6) and fine.masses.sum() == pytest.approx(1.6)
    assert coarse.rest_lengths.sum() == pytest.approx(4.0) and fine.rest_lengths.sum() == pytest.approx(4.0)
    # One end pinned; each spring joins the next two nodes.
    assert list(np.flatnonzero(fine.pinned)) == [0]
    assert np.array_equal(fine.springs, np.column_stack([np.arange(63), np.arange(1, 64)]))
    assert fine.named == {"rope": (0, 64)}


def test_the_scenes_arrays_are_read_only():
    scene = springlab.load_scene("spring")
    for array in (scene.positions, scene.velocities, scene.masses, scene.rest_lengths):
        assert not array.flags.writeable
    assert scene.positions[1].tolist() == [1.5, 0.0, 0.0]
