# SPDX-License-Identifier: MIT
"""sparsedyn: event-driven ("sparse dynamics") collision detection and rigid-body simulation.

Exact collision times, no missed collisions, no time step: every body moves on an analytic
path between events, and any state at any time is evaluated from it.

    import sparsedyn
    world = sparsedyn.preset("gas", n=1000, density=0.05, seed=1).build()
    world.advance_to(5.0)                 # releases the GIL
    x = world.positions()                 # (N, 3) float64, from the paths, in one call
    hits = world.collisions()             # structured array: time, a, b, wall, point, normal, impulse
    print(world.stats()["collisions"])    # the keys of `sparsedyn run --json`
    body = world.bodies()[0]              # a BodyId: slot and generation; indexes the arrays
    world.apply_impulse(body, [0, 0, 1], world.state(body).position)   # changes between runs

Errors raise InputError (a ValueError) or SimulationError (a RuntimeError), both subclasses of
sparsedyn.Error, with the library's message (which names the body, file, line, JSON path or
option). The guide is docs/tutorial.md and docs/python.md in the source repository.
"""

from ._sparsedyn import (  # noqa: F401  (the package's API)
    Body,
    BodyId,
    BodyState,
    Broadphase,
    Container,
    Error,
    GodDef,
    GodTarget,
    InputError,
    Polyhedron,
    RotationModel,
    Scene,
    Settings,
    SimulationError,
    World,
    distance,
    load_scene,
    parse_scene,
    preset,
    preset_names,
)

__version__ = "0.1.0"

__all__ = [
    "Body", "BodyId", "BodyState", "Broadphase", "Container", "Error", "GodDef", "GodTarget",
    "InputError", "Polyhedron", "RotationModel", "Scene", "Settings", "SimulationError", "World",
    "distance", "load_scene", "parse_scene", "preset", "preset_names",
]
