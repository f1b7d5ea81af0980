# SPDX-License-Identifier: MIT
"""Changes during a run from Python: handles, removing, kicking, setting velocities, poses and
thrusts. Each follows the C++ World's semantics (tests/world/changes_test.cpp): a kick by the
closed form, a refused change leaving the World as it was, and running on after changes giving
the collisions of a World built afresh at that time from the same state."""

import math

import numpy as np
import pytest

import sparsedyn

BOX = sparsedyn.Container.walled_box([0, 0, 0], [10, 10, 10])

# Both runs simulate the same state exactly; they differ only in where round-off falls (the
# segment starts), as in tests/world/changes_test.cpp.
SAME_TIME = 1e-9


def two_spheres():
    world = sparsedyn.World(container=BOX)
    a = world.add_body(radius=0.5, position=[2, 5, 5], velocity=[1, 0, 0], mass=2.0)
    b = world.add_body(radius=0.5, position=[8, 5, 5], velocity=[-1, 0, 0])
    return world, a, b


def test_add_body_returns_a_handle_that_indexes_the_arrays():
    world, a, b = two_spheres()
    assert isinstance(a, sparsedyn.BodyId)
    assert (a.index, a.generation, b.index) == (0, 0, 1)
    assert a == sparsedyn.BodyId(0) and a != b and len({a, b, sparsedyn.BodyId(0, 0)}) == 2
    assert repr(b) == "BodyId(index=1, generation=0)"
    assert world.bodies() == [a, b]
    assert world.id_of(1) == b and world.id_of(2) is None
    assert world.is_valid(a) and not world.is_valid(sparsedyn.BodyId(0, 1))
    assert world.slot_count == len(world) == 2
    np.testing.assert_array_equal(world.positions()[b], [8, 5, 5])  # a handle is a row index
    s = world.state(a, t=1.0)
    np.testing.assert_array_equal(s.position, [3, 5, 5])
    np.testing.assert_array_equal(s.velocity, [1, 0, 0])
    assert s.mass == 2.0 and s.radius == 0.5 and s.orientation == (1, 0, 0, 0)


def test_a_kick_changes_velocity_by_j_over_m_and_spin_by_the_inverse_inertia():
    # A sphere (r = 0.5, m = 4) at rest: dv = J / m, dw = (p - c) x J / (2/5 m r^2).
    world = sparsedyn.World(container=BOX)
    ball = world.add_body(radius=0.5, mass=4.0, position=[5, 5, 5])
    world.advance_to(0.5)
    impulse, point = np.array([0.3, -1.0, 0.7]), np.array([5.5, 5.1, 4.9])
    world.apply_impulse(ball, impulse, point)
    s = world.state(ball)
    np.testing.assert_allclose(s.velocity, impulse / 4.0, rtol=1e-15)
    expected_w = np.cross(point - [5, 5, 5], impulse) / (0.4 * 4.0 * 0.25)
    np.testing.assert_allclose(s.angular_velocity, expected_w, rtol=1e-14)
    assert s.version == 1  # one path change

    # A box with its own inertia tensor: I = m / 3 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2).
    world = sparsedyn.World(container=BOX, rotation_model=sparsedyn.RotationModel.full_tensor)
    box = world.add_body(shape=sparsedyn.Polyhedron.box([1, 0.5, 0.25]), position=[5, 5, 5],
                         mass=2.0)
    point = np.array([5.9, 5.4, 4.8])
    world.apply_impulse(box, impulse, point)
    inertia = 2.0 / 3.0 * np.array([0.25 + 0.0625, 1.0 + 0.0625, 1.0 + 0.25])
    s = world.state(box)
    np.testing.assert_allclose(s.velocity, impulse / 2.0, rtol=1e-15)
    np.testing.assert_allclose(s.angular_velocity,
                               np.cross(point - [5, 5, 5], impulse) / inertia, rtol=1e-13)


def test_set_velocity_and_angular_velocity_start_new_paths_now():
    world = sparsedyn.World(container=BOX)
    cube = world.add_body(shape=sparsedyn.Polyhedron.box([0.5, 0.5, 0.5]), position=[5, 5, 5],
                          velocity=[0.5, 0, 0], angular_velocity=[0, 0, 1])
    world.advance_to(1.0)
    world.set_velocity(cube, [0, 1, 0])
    np.testing.assert_allclose(world.positions(t=2.0)[cube], [5.5, 6, 5], rtol=0, atol=1e-14)
    np.testing.assert_array_equal(world.angular_velocities()[cube], [0, 0, 1])  # kept
    world.set_angular_velocity(cube, [0, 0, -2])
    np.testing.assert_array_equal(world.velocities()[cube], [0, 1, 0])  # kept
    q_now = world.state(cube).orientation  # turned by 1 rad about z
    np.testing.assert_allclose(q_now, [math.cos(0.5), 0, 0, math.sin(0.5)], atol=1e-14)
    # 0.25 s later it has turned back by 0.5 rad: 0.5 rad about z in all.
    np.testing.assert_allclose(world.orientations(t=1.25)[cube],
                               [math.cos(0.25), 0, 0, math.sin(0.25)], atol=1e-14)


def test_a_teleport_then_state_at_follows_the_new_place():
    world, a, b = two_spheres()
    # With a polyhedron in the World every body's rotation is kept (a gas of frictionless
    # spheres keeps none: their orientation stays the identity).
    world.add_body(shape=sparsedyn.Polyhedron.box([0.5, 0.5, 0.5]), position=[5, 8, 8])
    world.advance_to(1.0)
    q = (math.cos(0.3), math.sin(0.3), 0.0, 0.0)
    world.set_pose(a, [5, 2, 7], q)
    s = world.state(a)
    np.testing.assert_array_equal(s.position, [5, 2, 7])
    np.testing.assert_allclose(s.orientation, q, atol=1e-15)
    np.testing.assert_allclose(world.state(a, t=1.5).position, [5.5, 2, 7], atol=1e-14)
    world.set_pose(b, [3, 8, 3])  # orientation kept
    assert world.state(b).orientation == (1, 0, 0, 0)
    # The teleported bodies no longer meet at t = 2.5: b (at x = 3, -1 m/s) hits the -x wall
    # 2.5 s later, a (at x = 5, +1 m/s) the +x wall 4.5 s later.
    world.advance_to(6.0)
    hits = world.collisions()
    assert list(hits["a"]) == [b.index, a.index] and list(hits["b"]) == [-1, -1]
    assert list(hits["wall"]) == [0, 1]
    np.testing.assert_allclose(hits["time"], [1 + 2.5, 1 + 4.5], atol=1e-9)


def test_set_thrust_and_its_schedule_give_the_piecewise_parabola():
    world = sparsedyn.World(container=BOX)
    rocket = world.add_body(radius=0.2, position=[5, 5, 1])
    world.advance_to(1.0)
    world.set_thrust(rocket, [0, 0, 2], schedule=[(2.0, (0, 0, 0))])
    # Up at 2 m/s^2 for a second (1 m, 2 m/s), then coasting.
    np.testing.assert_allclose(world.positions(t=1.5)[rocket], [5, 5, 1.25], atol=1e-14)
    world.advance_to(2.5)
    np.testing.assert_allclose(world.state(rocket).position, [5, 5, 3], atol=1e-14)
    np.testing.assert_allclose(world.state(rocket).acceleration, [0, 0, 0], atol=0)
    body = sparsedyn.Body(thrust_schedule=[(1, [0, 0, 1])])
    assert body.thrust_schedule == [(1.0, (0.0, 0.0, 1.0))]


def test_a_removed_body_is_refused_and_its_row_is_nan():
    world, a, b = two_spheres()
    world.advance_to(1.0)
    world.remove_body(a)
    assert not world.is_valid(a) and len(world) == 1 and world.slot_count == 2
    assert world.bodies() == [b] and world.id_of(0) is None
    x = world.positions()
    assert x.shape == (2, 3)
    assert np.isnan(x[a]).all() and not np.isnan(x[b]).any()
    assert np.isnan(world.orientations()[a]).all()
    refusals = {
        "remove_body": lambda: world.remove_body(a),
        "set_velocity": lambda: world.set_velocity(a, [1, 0, 0]),
        "set_angular_velocity": lambda: world.set_angular_velocity(a, [1, 0, 0]),
        "apply_impulse": lambda: world.apply_impulse(a, [1, 0, 0], [2, 5, 5]),
        "set_pose": lambda: world.set_pose(a, [5, 5, 5]),
        "set_thrust": lambda: world.set_thrust(a, [0, 0, 1]),
        "state": lambda: world.state(a),
        "is_static": lambda: world.is_static(a),
    }
    for name, call in refusals.items():
        with pytest.raises(sparsedyn.InputError,
                           match=r"body 0 \(generation 0\) is not in the World") as caught:
            call()
        assert isinstance(caught.value, ValueError), name
    # A later body takes the slot under a new generation; the old handle stays refused.
    c = world.add_body(radius=0.5, position=[5, 2, 2])
    assert (c.index, c.generation) == (0, 1) and c != a
    assert not world.is_valid(a) and world.bodies() == [c, b]
    np.testing.assert_array_equal(world.positions()[c], [5, 2, 2])
    with pytest.raises(sparsedyn.InputError, match="not in the World"):
        world.set_velocity(a, [0, 0, 0])


def test_every_refused_change_leaves_the_world_unchanged():
    world = sparsedyn.World(container=BOX)
    a = world.add_body(radius=0.5, position=[2, 5, 5], velocity=[1, 0.05, 0])
    b = world.add_body(radius=0.5, position=[8, 5, 5], velocity=[-1, 0, 0.05])
    floor = world.add_body(shape=sparsedyn.Polyhedron.box([5, 5, 0.25]), position=[5, 5, 0.25],
                           is_static=True)
    world.advance_to(1.0)
    world.collisions()
    nan, inf = float("nan"), float("inf")
    refused = [
        ("NaN velocity", "velocity must be finite", lambda: world.set_velocity(a, [nan, 0, 0])),
        ("infinite spin", "angular_velocity must be finite",
         lambda: world.set_angular_velocity(a, [0, inf, 0])),
        ("NaN impulse", "impulse must be finite",
         lambda: world.apply_impulse(a, [0, nan, 0], [3, 5, 5])),
        ("infinite point", "point must be finite",
         lambda: world.apply_impulse(a, [1, 0, 0], [inf, 0, 0])),
        ("teleport onto a", "overlaps body 0", lambda: world.set_pose(b, [3.2, 5.2, 5])),
        ("teleport out of the box", "position", lambda: world.set_pose(a, [9.8, 5, 5])),
        ("teleport into the floor", "static body", lambda: world.set_pose(a, [5, 5, 0.6])),
        ("non-unit orientation", "orientation",
         lambda: world.set_pose(a, [5, 5, 5], (2, 0, 0, 0))),
        ("a schedule before now", "before the World's clock",
         lambda: world.set_thrust(a, [0, 0, 1], schedule=[(0.5, (0, 0, 0))])),
        ("a schedule out of order", "later than",
         lambda: world.set_thrust(a, [0, 0, 1], schedule=[(3, (0, 0, 0)), (2, (0, 0, 1))])),
        ("a static body's velocity", "is static", lambda: world.set_velocity(floor, [1, 0, 0])),
        ("a handle never added", "never added", lambda: world.set_velocity(
            sparsedyn.BodyId(7), [1, 0, 0])),
    ]
    hash_before, x_before = world.state_hash(), world.positions(t=3.0)
    for what, message, change in refused:
        with pytest.raises(sparsedyn.InputError, match=message):
            change()
        assert world.state_hash() == hash_before, what
        np.testing.assert_array_equal(world.positions(t=3.0), x_before, err_msg=what)
    assert len(world) == 3 and world.time == 1.0
    # The run then goes on as if nothing had been asked: a and b meet near t = 2.5.
    world.advance_to(4.0)
    assert any(h["b"] >= 0 for h in world.collisions())


def test_bodies_by_kind_in_stats():
    world = sparsedyn.World(container=BOX)
    world.add_body(shape=sparsedyn.Polyhedron.box([5, 5, 0.25]), position=[5, 5, 0.25],
                   is_static=True)
    cube = world.add_body(shape=sparsedyn.Polyhedron.box([0.5, 0.5, 0.5]), position=[2, 2, 5])
    ball = world.add_body(radius=0.5, position=[8, 8, 5])
    world.add_body(radius=0.5, position=[8, 2, 5])
    assert world.stats()["bodies_by_kind"] == {"spheres": 2, "polyhedra": 1, "static": 1,
                                               "god": 0}
    assert world.is_polyhedron(cube) and not world.is_static(cube)
    assert world.is_static(world.id_of(0)) and world.is_polyhedron(world.id_of(0))
    assert not world.is_polyhedron(ball)
    world.remove_body(ball)
    s = world.stats()
    assert s["bodies"] == 3
    assert s["bodies_by_kind"] == {"spheres": 1, "polyhedra": 1, "static": 1, "god": 0}


# --- running on after changes: a fresh World's future -------------------------------------


def mixed_gas(seed, n=64, side=12.0):
    """Spheres of a few sizes and masses, and every 8th body a spinning cube, on a lattice in a
    walled box with random velocities."""
    rng = np.random.default_rng(seed)
    cube = sparsedyn.Polyhedron.box([0.35, 0.35, 0.35])
    per_axis = math.ceil(n ** (1 / 3))
    spacing = side / per_axis
    bodies = []
    for i in range(n):
        cell = np.array([i % per_axis, i // per_axis % per_axis, i // per_axis ** 2])
        body = sparsedyn.Body(radius=0.3 + 0.25 * rng.random(), mass=0.5 + rng.random(),
                              position=(cell + 0.5) * spacing, velocity=rng.normal(size=3))
        if i % 8 == 0:
            body.shape = cube
            body.angular_velocity = rng.normal(size=3)
        bodies.append(body)
    container = sparsedyn.Container.walled_box([0, 0, 0], [side] * 3)
    return container, bodies


def free_spot(world, radius, side):
    """A point of the box whose sphere of `radius` is at least 0.1 m from every body's
    (bounding) sphere, searched on a grid."""
    x, r = world.positions(), np.array([world.state(b).radius for b in world.bodies()])
    x = x[[b.index for b in world.bodies()]]
    for p in np.ndindex(12, 12, 12):
        point = (np.array(p) + 0.5) * side / 12
        if ((point - radius >= 0).all() and (point + radius <= side).all() and
                (np.linalg.norm(x - point, axis=1) > r + radius + 0.1).all()):
            return point
    raise AssertionError("no free spot")


def fresh_world(world, container, defs):
    """A World made at `world`'s clock from its state: each body's state now with the rest of
    its definition (defs by slot), added in slot order."""
    fresh = sparsedyn.World(container=container, start_time=world.time)
    for body in world.bodies():
        s = world.state(body)
        fresh.add_body(defs[body.index], position=s.position, velocity=s.velocity,
                       orientation=s.orientation, angular_velocity=s.angular_velocity)
    return fresh


def contacts(world, until, slot_of):
    """The collisions up to `until` as (time, lower slot, other slot or -1 - wall)."""
    world.advance_to(until)
    out = []
    for hit in world.collisions():
        a = slot_of[hit["a"]]
        if hit["b"] < 0:
            out.append((hit["time"], a, -1 - hit["wall"]))
        else:
            b = slot_of[hit["b"]]
            out.append((hit["time"], min(a, b), max(a, b)))
    return out


@pytest.mark.parametrize("seed", [1, 2])
def test_running_on_after_changes_gives_a_fresh_worlds_collisions(seed):
    side = 12.0
    container, defs = mixed_gas(seed, side=side)
    world = sparsedyn.World(container=container, bodies=defs)
    world.advance_to(1.3)
    world.collisions()
    bodies = world.bodies()
    for kicked in (bodies[8], bodies[9]):  # a cube and a sphere, off their centres
        world.apply_impulse(kicked, [1, 1, 0], world.state(kicked).position + [0, 0, 0.1])
    world.set_velocity(bodies[20], [2, -1, 0.5])
    world.set_angular_velocity(bodies[24], [0, 3, 0])
    world.remove_body(bodies[30])
    world.set_pose(bodies[40], free_spot(world, world.state(bodies[40]).radius, side),
                   (0.6, 0.8, 0, 0))  # a cube, turned
    new = sparsedyn.Body(radius=0.4, velocity=[0, 0, -1.5])
    new.position = free_spot(world, new.radius, side)
    added = world.add_body(new)
    assert added.index == 30  # the removed body's slot, under a new generation
    defs[30] = new
    world.set_thrust(bodies[50], [0, 0, 0.5], schedule=[(2.0, (0.3, 0, 0))])
    defs[50].thrust = [0, 0, 0.5]
    defs[50].thrust_schedule = [(2.0, (0.3, 0, 0))]

    fresh = fresh_world(world, container, defs)
    changed_hits = contacts(world, 4.0, list(range(world.slot_count)))
    fresh_hits = contacts(fresh, 4.0, [b.index for b in world.bodies()])
    assert len(changed_hits) >= 30, "too few collisions to compare"
    compared = min(len(changed_hits), 60)
    assert len(fresh_hits) >= compared
    for k in range(compared):
        (t_a, *pair_a), (t_b, *pair_b) = changed_hits[k], fresh_hits[k]
        assert pair_a == pair_b, f"collision {k}"
        assert t_a == pytest.approx(t_b, abs=SAME_TIME * max(1.0, abs(t_a))), f"collision {k}"


# --- bodies of any kind added while running, god objects -----------------------------------


def test_add_body_mid_run_takes_any_shape_and_starts_now():
    world, a, b = two_spheres()
    world.advance_to(1.0)
    cube = world.add_body(shape=sparsedyn.Polyhedron.box([0.5, 0.5, 0.5]), position=[5, 2, 5],
                          velocity=[0, 0.5, 0], angular_velocity=[0, 0, 1])
    slab = world.add_body(shape=sparsedyn.Polyhedron.box([1, 1, 0.25]), position=[5, 8, 0.25],
                          is_static=True)
    pillar = world.add_body(radius=0.3, position=[1, 1, 1], is_static=True)
    hand = world.add_body(radius=0.4, position=[5, 5, 8],
                          god=sparsedyn.GodDef(5.0, [sparsedyn.GodTarget(2.0, [5, 6, 8])]))
    assert [x.index for x in (cube, slab, pillar, hand)] == [2, 3, 4, 5]
    assert world.slot_count == len(world) == 6
    kinds = [(world.is_static(x), world.is_god(x), world.is_polyhedron(x))
             for x in (a, cube, slab, pillar, hand)]
    assert kinds == [(False, False, False), (False, False, True), (True, False, True),
                     (True, False, False), (False, True, False)]
    # The cube's path starts now: 0.5 s later it is 0.25 m on and has turned by 0.5 rad.
    np.testing.assert_allclose(world.state(cube, t=1.5).position, [5, 2.25, 5], atol=1e-14)
    np.testing.assert_allclose(world.state(cube, t=1.5).orientation,
                               [math.cos(0.25), 0, 0, math.sin(0.25)], atol=1e-14)
    assert world.state(slab).mass == math.inf and world.state(pillar).mass == math.inf
    assert world.stats()["bodies_by_kind"] == {"spheres": 2, "polyhedra": 1, "static": 2,
                                               "god": 1}
    # A body refused while running leaves the World as it was.
    before = world.state_hash()
    with pytest.raises(sparsedyn.InputError, match="overlaps"):
        world.add_body(radius=0.5, position=[5, 2.2, 5])
    with pytest.raises(sparsedyn.InputError, match="god object cannot be static"):
        world.add_body(radius=0.2, position=[8, 8, 8], is_static=True, god=sparsedyn.GodDef())
    assert world.state_hash() == before and len(world) == 6


def god_world():
    """A god sphere at rest at (2, 5, 5), |a| <= 10, to reach (4, 5, 5) at rest at t = 2."""
    world = sparsedyn.World(container=BOX)
    hand = world.add_body(radius=0.5, position=[2, 5, 5],
                          god=sparsedyn.GodDef(10.0, [sparsedyn.GodTarget(2.0, [4, 5, 5])]))
    return world, hand


def test_a_god_object_follows_the_gentlest_rest_to_rest_move():
    # Rest to rest over d = 2 m in tau = 2 s: a = 4 d / tau^2 = 2 m/s^2 for the first half, -2
    # for the second (docs/dynamics.md, "God objects").
    world, hand = god_world()
    assert world.is_god(hand) and not world.is_static(hand) and not world.is_polyhedron(hand)
    body = sparsedyn.Body(god=sparsedyn.GodDef(3.0, [sparsedyn.GodTarget(1.0, [1, 2, 3],
                                                                         velocity=[0, 0, 1])]))
    assert body.god.max_acceleration == 3.0 and body.god.track[0].time == 1.0
    np.testing.assert_array_equal(body.god.track[0].velocity, [0, 0, 1])
    assert sparsedyn.Body().god is None and sparsedyn.GodTarget(1.0, [0, 0, 0]).velocity is None
    np.testing.assert_allclose(world.state(hand, t=0.5).position, [2.25, 5, 5], atol=1e-14)
    np.testing.assert_allclose(world.state(hand, t=0.5).acceleration, [2, 0, 0], atol=1e-14)
    s = world.state(hand, t=1.0)
    np.testing.assert_allclose(s.position, [3, 5, 5], atol=1e-14)
    np.testing.assert_allclose(s.velocity, [2, 0, 0], atol=1e-14)
    world.advance_to(1.0)
    remaining = world.god_track(hand)
    assert remaining.max_acceleration == 10.0
    assert [(t.time, tuple(t.position)) for t in remaining.track] == [(2.0, (4, 5, 5))]
    world.advance_to(2.5)
    s = world.state(hand)
    np.testing.assert_allclose(s.position, [4, 5, 5], atol=1e-12)  # a move ends at its target
    np.testing.assert_allclose(s.velocity, [0, 0, 0], atol=1e-12)
    assert world.god_track(hand).track == []
    assert world.stats()["bodies_by_kind"] == {"spheres": 0, "polyhedra": 0, "static": 0,
                                               "god": 1}


def test_set_god_track_replans_from_the_state_now():
    world, hand = god_world()
    ball = world.add_body(radius=0.5, position=[8, 8, 8])
    world.advance_to(2.5)
    assert world.god_track(ball) is None  # not a god object
    # From rest at (4, 5, 5): 2 m along y in 1 s, a = 4 d / tau^2 = 8 <= 10.
    world.set_god_track(hand, sparsedyn.GodDef(10.0, [sparsedyn.GodTarget(3.5, [4, 7, 5])]))
    s = world.state(hand, t=3.0)
    np.testing.assert_allclose(s.position, [4, 6, 5], atol=1e-12)
    np.testing.assert_allclose(s.velocity, [0, 4, 0], atol=1e-12)
    world.advance_to(3.5)
    np.testing.assert_allclose(world.state(hand).position, [4, 7, 5], atol=1e-12)
    # A teleport: it goes on to the targets it had not reached from its new place.
    world.set_god_track(hand, sparsedyn.GodDef(10.0, [sparsedyn.GodTarget(5.0, [2, 7, 5])]))
    world.set_pose(hand, [6, 7, 5])
    world.advance_to(5.0)
    np.testing.assert_allclose(world.state(hand).position, [2, 7, 5], atol=1e-12)


def test_god_objects_refuse_pushes_and_bad_tracks():
    world, hand = god_world()
    ball = world.add_body(radius=0.5, position=[8, 8, 8])
    world.advance_to(1.0)
    good = sparsedyn.GodDef(10.0, [sparsedyn.GodTarget(3.0, [4, 4, 4])])
    refused = [
        ("set_velocity", "SetVelocity: body 0 \\(generation 0\\) is a god object",
         lambda: world.set_velocity(hand, [1, 0, 0])),
        ("set_angular_velocity", "is a god object",
         lambda: world.set_angular_velocity(hand, [1, 0, 0])),
        ("apply_impulse", "is a god object",
         lambda: world.apply_impulse(hand, [1, 0, 0], [2, 5, 5])),
        ("set_thrust", "is a god object", lambda: world.set_thrust(hand, [0, 0, 1])),
        ("not a god", "SetGodTrack: body 1 \\(generation 0\\) is not a god object",
         lambda: world.set_god_track(ball, good)),
        ("before the clock", "track\\[0\\].time 0.5 is before the World's clock",
         lambda: world.set_god_track(hand, sparsedyn.GodDef(10.0, [
             sparsedyn.GodTarget(0.5, [4, 4, 4])]))),
        ("out of order", "track\\[1\\].time must be after track\\[0\\].time",
         lambda: world.set_god_track(hand, sparsedyn.GodDef(10.0, [
             sparsedyn.GodTarget(3.0, [4, 4, 4]), sparsedyn.GodTarget(2.0, [4, 4, 4])]))),
        ("no acceleration", "max_acceleration must be finite and > 0",
         lambda: world.set_god_track(hand, sparsedyn.GodDef(0.0, []))),
        ("NaN target", "track\\[0\\].position must be finite",
         lambda: world.set_god_track(hand, sparsedyn.GodDef(10.0, [
             sparsedyn.GodTarget(3.0, [float("nan"), 4, 4])]))),
        ("a handle never added", "SetGodTrack: body 9 \\(generation 0\\) is not in the World",
         lambda: world.set_god_track(sparsedyn.BodyId(9), good)),
    ]
    before = world.state_hash()
    for what, message, change in refused:
        with pytest.raises(sparsedyn.InputError, match=message):
            change()
        assert world.state_hash() == before, what
    world.remove_body(hand)
    for query in (world.is_god, world.is_static, world.is_polyhedron, world.god_track):
        with pytest.raises(sparsedyn.InputError,
                           match="body 0 \\(generation 0\\) is not in the World"):
            query(hand)


def test_a_scenes_god_object_is_one_in_python(tmp_path):
    scene = sparsedyn.parse_scene(
        '{"container": {"kind": "walled", "lo": [0, 0, 0], "hi": [10, 10, 10]}, "bodies": ['
        '{"shape": {"generator": "cube"}, "position": [2, 5, 5], "god": {"max_acceleration": 4,'
        ' "track": [{"time": 1, "position": [3, 5, 5], "velocity": [1, 0, 0]}]}},'
        '{"shape": {"sphere": {"radius": 0.5}}, "position": [8, 8, 8]}]}', "gods", str(tmp_path))
    world = scene.build()
    hand = world.id_of(0)
    assert world.is_god(hand) and world.is_polyhedron(hand)
    track = world.god_track(hand)
    assert track.max_acceleration == 4.0
    np.testing.assert_array_equal(track.track[0].velocity, [1, 0, 0])
    world.advance_to(1.0)
    s = world.state(hand)
    np.testing.assert_allclose(s.position, [3, 5, 5], atol=1e-12)
    np.testing.assert_allclose(s.velocity, [1, 0, 0], atol=1e-12)
    assert world.stats()["bodies_by_kind"] == {"spheres": 1, "polyhedra": 0, "static": 0,
                                               "god": 1}
