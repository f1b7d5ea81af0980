# SPDX-License-Identifier: MIT
"""Bad input raises Python exceptions that carry the library's messages."""

import pytest

import sparsedyn

BOX = sparsedyn.Container.walled_box([0, 0, 0], [10, 10, 10])


def test_bad_body_names_the_field_and_adds_nothing():
    world = sparsedyn.World(container=BOX)
    with pytest.raises(sparsedyn.InputError, match="radius") as caught:
        world.add_body(radius=-1.0, position=[5, 5, 5])
    assert isinstance(caught.value, ValueError) and isinstance(caught.value, sparsedyn.Error)
    assert len(world) == 0


def test_bodies_list_names_the_body():
    with pytest.raises(sparsedyn.InputError, match=r"bodies\[1\]"):
        sparsedyn.World(container=BOX, bodies=[
            sparsedyn.Body(position=[5, 5, 5]),
            sparsedyn.Body(position=[5.2, 5, 5]),  # overlaps the first
        ])


def test_unknown_body_field_is_an_attribute_error():
    with pytest.raises(AttributeError, match="velocty"):
        sparsedyn.Body(velocty=[1, 0, 0])


def test_scene_errors_name_the_json_path(tmp_path):
    path = tmp_path / "s.json"
    path.write_text('{"bodies": [{"shape": {"sphere": {"radius": 0.5}}, "velocty": [1, 0, 0]}]}')
    with pytest.raises(sparsedyn.InputError, match=r"s\.json.*bodies\[0\]\.velocty"):
        sparsedyn.load_scene(str(path))
    with pytest.raises(sparsedyn.InputError, match="line 1"):
        sparsedyn.parse_scene('{"bodies": [', name="broken")


def test_missing_file_and_bad_preset_raise():
    with pytest.raises(sparsedyn.InputError, match="no_such_file"):
        sparsedyn.load_scene("no_such_file.json")
    with pytest.raises(sparsedyn.InputError, match="nonsense"):
        sparsedyn.preset("nonsense")
    with pytest.raises(sparsedyn.InputError):
        sparsedyn.preset("gas", n=10, density=0.9)


def test_states_before_now_raise():
    world = sparsedyn.preset("gas", n=20, seed=1).build()
    world.advance_to(1.0)
    with pytest.raises(sparsedyn.InputError, match="before the World's time"):
        world.positions(t=0.5)


def test_stalled_run_raises_simulation_error():
    # Inelastic spheres resting on each other under gravity: resting contact between bodies is
    # not supported, and the event loop's progress check ends the run with an error.
    world = sparsedyn.World(container=BOX, gravity=[0, 0, -9.81])
    world.add_body(radius=0.5, position=[5, 5, 0.5], restitution=0.0)
    world.add_body(radius=0.5, position=[5, 5, 1.6], restitution=0.0)
    with pytest.raises(sparsedyn.SimulationError, match="event loop") as caught:
        world.advance_to(10.0)
    assert isinstance(caught.value, RuntimeError)
    assert world.time < 10.0


def test_bad_distance_pose_raises():
    cube = sparsedyn.Polyhedron.box([1, 1, 1])
    with pytest.raises(sparsedyn.InputError, match="pose_b"):
        sparsedyn.distance(cube, cube, pose_b=[3, 0, 0, 2, 0, 0, 0])
    with pytest.raises(sparsedyn.InputError):
        sparsedyn.Polyhedron.from_points([[0, 0, 0], [1, 0, 0], [0, 1, 0]])
