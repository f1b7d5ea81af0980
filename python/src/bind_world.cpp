// SPDX-License-Identifier: MIT
// World (include/sparsedyn/world.hpp) as the Python class World (PyWorld). Adding a method of
// the C++ World is one .def line below (with With() when it only reads the World).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "errors.hpp"
#include "py_world.hpp"

namespace py = pybind11;

namespace sparsedyn::python {
namespace {

// The packing fraction stats() reports for a World made from Python: the bodies' volumes over
// the box's (0 in open space), as ReportedPacking does for a scene.
double PackingOf(const WorldSettings& settings, const std::vector<BodyDef>& bodies) {
  if (settings.container.kind == Container::Kind::kOpen) return 0.0;
  double volume = 0;
  for (const BodyDef& b : bodies) {
    volume += b.shape ? b.shape->volume() : 4.0 / 3.0 * std::numbers::pi * std::pow(b.radius, 3);
  }
  return volume / (settings.container.hi - settings.container.lo).prod();
}

// World(settings=None, bodies=(), **settings_fields).
std::unique_ptr<PyWorld> MakeWorld(const py::object& settings_or_none,
                                   const std::vector<BodyDef>& bodies, const py::kwargs& fields) {
  py::object settings = settings_or_none.is_none()
                            ? py::module_::import("sparsedyn").attr("Settings")()
                            : py::module_::import("copy").attr("copy")(settings_or_none);
  SetAttributes(settings, fields);
  const WorldSettings s = settings.cast<WorldSettings>();
  auto world = std::make_unique<PyWorld>(World(s), "", PackingOf(s, bodies), 0);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    try {
      world->AddBody(bodies[k]);
    } catch (const InputError& e) {
      throw InputError("bodies[" + std::to_string(k) + "]: " + e.what());
    }
  }
  return world;
}

// is_static(body) / is_polyhedron(body) / is_god(body): `ask` of a body the World holds, else
// InputError.
template <typename Ask>
auto BodyQuery(const char* call, Ask ask) {
  return [call, ask](PyWorld& w, BodyId id) {
    const std::optional<bool> answer = w.With([&](const World& x) -> std::optional<bool> {
      if (!x.IsValid(id)) return std::nullopt;
      return ask(x, id);
    });
    if (!answer) throw InputError(NotInTheWorld(call, id));
    return *answer;
  };
}

// set_pose(body, position, orientation=None): None keeps the body's orientation now.
void SetPose(PyWorld& w, BodyId id, const Vec3& position, const py::object& orientation) {
  const std::optional<Eigen::Quaterniond> given =
      orientation.is_none() ? std::nullopt
                            : std::optional(QuaternionFrom(orientation.cast<py::sequence>()));
  w.Change([&](World& x) {
    if (given) return x.SetPose(id, position, *given);
    if (!x.IsValid(id)) return x.SetPose(id, position, Eigen::Quaterniond::Identity());  // refused
    return x.SetPose(id, position, x.StateAt(id, x.Time()).orientation);
  });
}

// The change methods: each is World's, checked by it, refused with InputError and the
// library's message (the World unchanged).
void BindChanges(py::class_<PyWorld>& c) {
  c.def(
       "remove_body",
       [](PyWorld& w, BodyId id) { w.Change([&](World& x) { return x.RemoveBody(id); }); },
       py::arg("body"),
       "Removes the body now. Its handle is refused from then on; its row in the arrays is NaN "
       "until a later body takes the slot (under a new generation).")
      .def(
          "set_velocity",
          [](PyWorld& w, BodyId id, const Vec3& v) {
            w.Change([&](World& x) { return x.SetVelocity(id, v); });
          },
          py::arg("body"), py::arg("velocity"),
          "Sets the body's velocity now (m/s), its angular velocity kept.")
      .def(
          "set_angular_velocity",
          [](PyWorld& w, BodyId id, const Vec3& omega) {
            w.Change([&](World& x) { return x.SetAngularVelocity(id, omega); });
          },
          py::arg("body"), py::arg("angular_velocity"),
          "Sets the body's angular velocity now (rad/s, world frame), its velocity kept.")
      .def(
          "apply_impulse",
          [](PyWorld& w, BodyId id, const Vec3& impulse, const Vec3& point) {
            w.Change([&](World& x) { return x.ApplyImpulse(id, impulse, point); });
          },
          py::arg("body"), py::arg("impulse"), py::arg("point"),
          "Applies an impulse (N s, world frame) at a point (world frame, m) now: the velocity "
          "changes by impulse / m and the angular velocity by I^-1 ((point - centre) x impulse).")
      .def("set_pose", &SetPose, py::arg("body"), py::arg("position"),
           py::arg("orientation") = py::none(),
           "Moves the body at once (a teleport) to `position` (m) with `orientation` (w, x, y, "
           "z; None keeps its orientation now). Refused where it would touch another body or "
           "leave the container.")
      .def(
          "set_thrust",
          [](PyWorld& w, BodyId id, const Vec3& thrust, const py::sequence& schedule) {
            const std::vector<ThrustChange> changes = ScheduleFrom(schedule, "schedule");
            w.Change([&](World& x) { return x.SetThrust(id, thrust, changes); });
          },
          py::arg("body"), py::arg("thrust"), py::arg("schedule") = py::list(),
          "Sets the body's own acceleration (m/s^2, added to gravity) from now on, and its "
          "later changes: (time, (x, y, z)) pairs with increasing times, replacing what was "
          "left of the old schedule.")
      .def(
          "set_god_track",
          [](PyWorld& w, BodyId id, const GodDef& god) {
            w.Change([&](World& x) { return x.SetGodTrack(id, god); });
          },
          py::arg("body"), py::arg("god"),
          "Gives a god object a new GodDef (max_acceleration and track, no target before time) "
          "from now on, planned from where it is and how it moves now. set_velocity, "
          "set_angular_velocity, apply_impulse and set_thrust refuse a god object; set_pose "
          "teleports it and it goes on to the targets it had not reached.");
}

// The handles: which bodies the World holds and what they are.
void BindHandles(py::class_<PyWorld>& c) {
  c.def(
       "bodies", [](PyWorld& w) { return w.With([](const World& x) { return x.Bodies(); }); },
       "Every body's handle (BodyId), in slot order.")
      .def(
          "is_valid",
          [](PyWorld& w, BodyId id) {
            return w.With([&](const World& x) { return x.IsValid(id); });
          },
          py::arg("body"), "Whether the World holds `body` (not removed).")
      .def(
          "id_of",
          [](PyWorld& w, std::uint32_t slot) -> std::optional<BodyId> {
            const BodyId id = w.With([&](const World& x) { return x.IdOf(slot); });
            if (!id.valid()) return std::nullopt;
            return id;
          },
          py::arg("slot"), "The handle of the body in `slot`, or None for an empty slot.")
      .def_property_readonly(
          "slot_count",
          [](PyWorld& w) { return w.With([](const World& x) { return x.SlotCount(); }); },
          "The number of slots: rows of the arrays (len(world) plus the empty slots).")
      .def("state", &PyWorld::StateOf, py::arg("body"), py::arg("t") = py::none(),
           "The body's BodyState at time t >= time (default now), from its path.")
      .def("is_static",
           BodyQuery("is_static", [](const World& x, BodyId id) { return x.IsStatic(id); }),
           py::arg("body"), "Whether the body is static (Body.is_static).")
      .def("is_polyhedron",
           BodyQuery("is_polyhedron", [](const World& x, BodyId id) { return x.IsPolyhedron(id); }),
           py::arg("body"),
           "Whether the body is a polyhedron (static, god object or moving), else a sphere.")
      .def("is_god", BodyQuery("is_god", [](const World& x, BodyId id) { return x.IsGod(id); }),
           py::arg("body"), "Whether the body is a god object (Body.god).")
      .def(
          "god_track",
          [](PyWorld& w, BodyId id) {
            bool held = true;
            const std::optional<GodDef> god = w.With([&](const World& x) -> std::optional<GodDef> {
              held = x.IsValid(id);
              return x.GodTrackOf(id);
            });
            if (!held) throw InputError(NotInTheWorld("god_track", id));
            return god;
          },
          py::arg("body"),
          "The part of a god object's track not reached yet (targets after time) and its "
          "max_acceleration, a GodDef; None for a body that is not a god object.");
}

}  // namespace

void BindWorld(py::module_& m) {
  using F = StateField;
  // One field of every body at t >= now (default now), evaluated in C++ in one call.
  auto states = [](F field) {
    return [field](PyWorld& w, std::optional<double> t) { return w.States(field, t); };
  };
  py::class_<PyWorld> world(m, "World",
                            "Owns the bodies and runs the event loop. Nothing is computed "
                            "between events; every state comes from the bodies' analytic paths.");
  world
      .def(py::init(&MakeWorld), py::arg("settings") = py::none(),
           py::arg("bodies") = std::vector<BodyDef>{},
           "World(settings=None, bodies=(), **fields): a Settings and/or its fields by keyword "
           "(container=..., gravity=...), and the Body list added in order.")
      .def(
          "add_body",
          [](PyWorld& w, const py::object& body, const py::kwargs& fields) {
            py::object def = body.is_none() ? py::module_::import("sparsedyn").attr("Body")()
                                            : py::module_::import("copy").attr("copy")(body);
            SetAttributes(def, fields);
            return w.AddBody(def.cast<BodyDef>());
          },
          py::arg("body") = py::none(),
          "add_body(body=None, **fields) -> BodyId: adds a Body at the current time and "
          "returns its handle (its index is its row in the arrays); raises InputError "
          "(nothing added) when the World refuses it.")
      .def("advance_to", &PyWorld::AdvanceTo, py::arg("t"),
           "Processes every event with time <= t (s), then sets the clock to t. Releases the "
           "GIL. Raises SimulationError when the event loop stalls.")
      .def_property_readonly("time", &PyWorld::Time, "The simulated time now, s.")
      .def("__len__", &PyWorld::BodyCount)
      .def_property_readonly("body_count", &PyWorld::BodyCount,
                             "The number of bodies the World holds.")
      .def("positions", states(F::kPosition), py::arg("t") = py::none(),
           "Every body's centre of mass at time t (default: now), an (S, 3) array, m. One row "
           "per slot (S = slot_count; row k is the body whose BodyId.index is k), a row of "
           "NaN for a removed body's empty slot.")
      .def("velocities", states(F::kVelocity), py::arg("t") = py::none(),
           "Every body's velocity at time t (default: now), an (S, 3) array, m/s; rows as "
           "positions().")
      .def("orientations", states(F::kOrientation), py::arg("t") = py::none(),
           "Every body's orientation (body to world) at time t (default: now), an (S, 4) array "
           "of unit quaternions (w, x, y, z); rows as positions().")
      .def("angular_velocities", states(F::kAngularVelocity), py::arg("t") = py::none(),
           "Every body's angular velocity at time t (default: now), an (S, 3) array, rad/s; "
           "rows as positions().")
      .def(
          "stats",
          [](PyWorld& w) { return py::module_::import("json").attr("loads")(w.SummaryJson()); },
          "The summary of `sparsedyn run --json` as a dict (the same keys and values).")
      .def("collisions", &PyWorld::Collisions,
           "The collisions since the last call as a numpy structured array with fields time, "
           "a, b (-1 for a wall), wall (0..5 = -x,+x,-y,+y,-z,+z, or -1), point[3], normal[3] "
           "(unit, from a to b), impulse (N s).")
      .def("kinetic_energy",
           [](PyWorld& w) { return w.With([](const World& x) { return x.KineticEnergy(); }); })
      .def("momentum",
           [](PyWorld& w) { return w.With([](const World& x) { return Vec3(x.Momentum()); }); })
      .def("angular_momentum",
           [](PyWorld& w) {
             return w.With([](const World& x) { return Vec3(x.AngularMomentum()); });
           })
      .def("max_penetration",
           [](PyWorld& w) { return w.With([](const World& x) { return x.MaxPenetration(); }); })
      .def(
          "validate",
          [](PyWorld& w) {
            Check<SimulationError>(w.With([](const World& x) { return x.Validate(); }));
          },
          "Raises SimulationError when bodies overlap beyond the tolerance or leave the "
          "container.")
      .def("state_hash",
           [](PyWorld& w) { return w.With([](const World& x) { return x.StateHash(); }); })
      .def_property_readonly("settings", [](PyWorld& w) {
        return w.With([](const World& x) { return x.Settings(); });
      });
  BindChanges(world);
  BindHandles(world);
}

}  // namespace sparsedyn::python
