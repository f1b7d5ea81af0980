// SPDX-License-Identifier: MIT
// World (include/sparsedyn/world.hpp) as the Python class World (PyWorld). Adding a method of
// the C++ World is one .def line below (with With() when it only reads the World).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <numbers>

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

}  // namespace

void BindWorld(py::module_& m) {
  using F = StateField;
  // One field of every body at t >= now (default now), evaluated in C++ in one call.
  auto states = [](F field) {
    return [field](PyWorld& w, std::optional<double> t) { return w.States(field, t); };
  };
  py::class_<PyWorld>(m, "World",
                      "Owns the bodies and runs the event loop. Nothing is computed between "
                      "events; every state comes from the bodies' analytic paths.")
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
          "add_body(body=None, **fields) -> index: adds a Body at the current time; raises "
          "InputError (nothing added) when the World refuses it.")
      .def("advance_to", &PyWorld::AdvanceTo, py::arg("t"),
           "Processes every event with time <= t (s), then sets the clock to t. Releases the "
           "GIL. Raises SimulationError when the event loop stalls.")
      .def_property_readonly("time", &PyWorld::Time, "The simulated time now, s.")
      .def("__len__", &PyWorld::BodyCount)
      .def_property_readonly("body_count", &PyWorld::BodyCount)
      .def("positions", states(F::kPosition), py::arg("t") = py::none(),
           "Every body's centre of mass at time t (default: now), an (N, 3) array, m.")
      .def("velocities", states(F::kVelocity), py::arg("t") = py::none(),
           "Every body's velocity at time t (default: now), an (N, 3) array, m/s.")
      .def("orientations", states(F::kOrientation), py::arg("t") = py::none(),
           "Every body's orientation (body to world) at time t (default: now), an (N, 4) array "
           "of unit quaternions (w, x, y, z).")
      .def("angular_velocities", states(F::kAngularVelocity), py::arg("t") = py::none(),
           "Every body's angular velocity at time t (default: now), an (N, 3) array, rad/s.")
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
}

}  // namespace sparsedyn::python
