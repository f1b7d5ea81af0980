# SPDX-License-Identifier: MIT
"""World from Python: arrays of the right shape, dtype and value, against closed forms."""

import threading
import time

import numpy as np
import pytest

import sparsedyn

BOX = sparsedyn.Container.walled_box([0, 0, 0], [10, 10, 10])


def two_spheres():
    """Two spheres approaching head on along x: they touch at t = (6 - 1) / 2 = 2.5 s."""
    return sparsedyn.World(container=BOX, bodies=[
        sparsedyn.Body(radius=0.5, position=[2, 5, 5], velocity=[1, 0, 0]),
        sparsedyn.Body(radius=0.5, position=[8, 5, 5], velocity=[-1, 0, 0]),
    ])


def test_arrays_have_shapes_and_dtypes():
    world = sparsedyn.preset("gas", n=50, seed=1).build()
    assert len(world) == world.body_count == 50
    for array, columns in ((world.positions(), 3), (world.velocities(), 3),
                           (world.orientations(), 4), (world.angular_velocities(), 3)):
        assert array.shape == (50, columns)
        assert array.dtype == np.float64
        assert array.flags.c_contiguous


def test_positions_follow_the_paths_in_free_flight():
    world = two_spheres()
    np.testing.assert_array_equal(world.positions(), [[2, 5, 5], [8, 5, 5]])
    # Evaluated ahead of the clock from the analytic path, before any event is processed.
    np.testing.assert_allclose(world.positions(t=1.5), [[3.5, 5, 5], [6.5, 5, 5]], rtol=0,
                               atol=1e-15)
    world.advance_to(1.5)
    assert world.time == 1.5
    np.testing.assert_allclose(world.positions(), [[3.5, 5, 5], [6.5, 5, 5]], rtol=0, atol=1e-15)


def test_head_on_elastic_collision_swaps_velocities_at_the_contact_time():
    world = two_spheres()
    world.advance_to(4.0)
    hits = world.collisions()
    assert hits.dtype.names == ("time", "a", "b", "wall", "point", "normal", "impulse")
    assert len(hits) == 1
    assert hits["time"][0] == pytest.approx(2.5, abs=1e-9)
    assert (hits["a"][0], hits["b"][0], hits["wall"][0]) in ((0, 1, -1), (1, 0, -1))
    np.testing.assert_allclose(hits["point"][0], [5, 5, 5], atol=1e-8)
    np.testing.assert_allclose(np.abs(hits["normal"][0]), [1, 0, 0], atol=1e-12)
    assert hits["impulse"][0] == pytest.approx(2.0)  # m * relative speed for equal masses
    np.testing.assert_allclose(world.velocities(), [[-1, 0, 0], [1, 0, 0]], atol=1e-12)
    assert len(world.collisions()) == 0  # emptied by the call before


def test_gravity_gives_the_parabola():
    world = sparsedyn.World(sparsedyn.Settings(container=BOX, gravity=[0, 0, -9.81]))
    ball = world.add_body(radius=0.25, position=[5, 5, 8], velocity=[0.5, 0, 1])
    assert (ball.index, ball.generation) == (0, 0)
    t = 0.6
    expected = [5 + 0.5 * t, 5, 8 + t - 0.5 * 9.81 * t * t]
    np.testing.assert_allclose(world.positions(t=t)[0], expected, rtol=1e-14)
    np.testing.assert_allclose(world.velocities(t=t)[0], [0.5, 0, 1 - 9.81 * t], rtol=1e-14)


def test_rotating_polyhedron_orientation_is_the_exponential_of_its_spin():
    cube = sparsedyn.Polyhedron.box([0.5, 0.5, 0.5])
    world = sparsedyn.World(container=BOX)
    world.add_body(shape=cube, position=[5, 5, 5], angular_velocity=[0, 0, 1.0])
    q = world.orientations(t=0.8)[0]  # turned by 0.8 rad about z
    np.testing.assert_allclose(q, [np.cos(0.4), 0, 0, np.sin(0.4)], atol=1e-14)
    assert cube.face_count == 6 and cube.volume == pytest.approx(1.0)


def test_stats_keys_and_conservation():
    world = sparsedyn.preset("gas", n=200, seed=4).build()
    world.advance_to(2.0)
    s = world.stats()
    for key in ("bodies", "simulated_time", "wall_seconds", "events", "events_by_kind",
                "stale_events", "meetings", "collisions", "kinetic_energy_initial",
                "kinetic_energy_final", "momentum_initial", "momentum_final", "max_penetration"):
        assert key in s, key
    assert s["bodies"] == 200 and s["simulated_time"] == 2.0 and s["preset"] == "gas"
    assert s["kinetic_energy_final"] == pytest.approx(s["kinetic_energy_initial"], rel=1e-12)
    assert s["collisions"] == s["body_collisions"] + s["wall_collisions"] > 0
    assert s["wall_seconds"] > 0
    world.validate()


def test_advance_to_releases_the_gil():
    world = sparsedyn.preset("gas", n=20000, seed=1).build()
    ticks = 0
    done = threading.Event()

    def run():
        world.advance_to(20.0)  # about 160k collisions: a tenth of a second or more
        done.set()

    worker = threading.Thread(target=run)
    worker.start()
    start = time.perf_counter()
    while not done.is_set():
        ticks += 1  # runs only while the worker's C++ loop does not hold the GIL
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - start
    assert world.time == 20.0
    assert elapsed > 0.05, "the run was too short to tell"
    assert ticks >= 10
