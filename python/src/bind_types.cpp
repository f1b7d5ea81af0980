// SPDX-License-Identifier: MIT
// The plain data of include/sparsedyn/world.hpp: Container, Settings (WorldSettings), Body
// (BodyDef), GodDef and GodTarget, BodyId, BodyState, the enums and Polyhedron. A new field is one
// def_readwrite line here.
#include <pybind11/eigen.h>
#include <pybind11/operators.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"
#include "errors.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/io/mesh_io.hpp"
#include "sparsedyn/world.hpp"

namespace py = pybind11;

namespace sparsedyn::python {
namespace {

const char* KindName(Container::Kind kind) {
  switch (kind) {
    case Container::Kind::kOpen:
      return "open";
    case Container::Kind::kWalledBox:
      return "walled_box";
    case Container::Kind::kPeriodicBox:
      break;
  }
  return "periodic_box";
}

PyPolyhedron Share(Result<ConvexPolyhedron> built) {
  return {std::make_shared<const ConvexPolyhedron>(ValueOrRaise(std::move(built)))};
}

void BindEnums(py::module_& m) {
  py::enum_<Broadphase>(m, "Broadphase", "Which elements an actor is compared with.")
      .value("allpairs", Broadphase::kAllPairs, "every other element (the thesis)")
      .value("grid", Broadphase::kGrid, "uniform cells with cell-crossing events (default)");
  py::enum_<RotationModel>(m, "RotationModel", "How a polyhedron turns between events.")
      .value("spherical_top", RotationModel::kSphericalTop)
      .value("full_tensor", RotationModel::kFullTensor);
}

void BindContainer(py::module_& m) {
  py::class_<Container>(m, "Container", "The space the bodies live in.")
      .def_static("open", &Container::Open, "Open space, no walls.")
      .def_static("walled_box", &Container::WalledBox, py::arg("lo"), py::arg("hi"),
                  "A box with six static walls from corner lo to corner hi, m.")
      .def_static("periodic_box", &Container::PeriodicBox, py::arg("lo"), py::arg("hi"),
                  "A box with periodic boundaries (minimum image).")
      .def_property_readonly("kind", [](const Container& c) { return KindName(c.kind); })
      .def_readonly("lo", &Container::lo)
      .def_readonly("hi", &Container::hi)
      .def("__repr__", [](const Container& c) {
        return py::str("Container.{}({}, {})").format(KindName(c.kind), Vec3(c.lo), Vec3(c.hi));
      });
}

void BindSettings(py::module_& m) {
  py::class_<WorldSettings>(m, "Settings", "World-wide settings (WorldSettings), SI units.")
      .def(py::init([](const py::kwargs& kwargs) {
             auto settings = py::cast(WorldSettings{});
             SetAttributes(settings, kwargs);
             return settings.cast<WorldSettings>();
           }),
           "Settings(**fields): any field below by keyword, the rest at their defaults.")
      .def("__copy__", [](const WorldSettings& s) { return s; })
      .def_readwrite("container", &WorldSettings::container)
      .def_readwrite("broadphase", &WorldSettings::broadphase)
      .def_readwrite("gravity", &WorldSettings::gravity, "m/s^2, on every body")
      .def_readwrite("contact_tolerance", &WorldSettings::contact_tolerance)
      .def_readwrite("rotation_model", &WorldSettings::rotation_model)
      .def_readwrite("elastic_below_speed", &WorldSettings::elastic_below_speed, "m/s")
      .def_readwrite("grid_cells_per_body", &WorldSettings::grid_cells_per_body)
      .def_readwrite("stall_event_limit", &WorldSettings::stall_event_limit)
      .def_readwrite("profile_phases", &WorldSettings::profile_phases)
      .def_readwrite("start_time", &WorldSettings::start_time,
                     "s: the clock when the World is made (a World that runs on from the state "
                     "of another at that time)");
}

void BindBody(py::module_& m) {
  py::class_<BodyDef>(m, "Body", "A body to add (BodyDef): a sphere, or a Polyhedron shape.")
      .def(py::init([](const py::kwargs& kwargs) {
             auto body = py::cast(BodyDef{});
             SetAttributes(body, kwargs);
             return body.cast<BodyDef>();
           }),
           "Body(**fields): any field below by keyword, the rest at their defaults.")
      .def("__copy__", [](const BodyDef& b) { return b; })
      .def_readwrite("radius", &BodyDef::radius, "m; a sphere's radius")
      .def_property(
          "shape",
          [](const BodyDef& b) -> py::object {
            return b.shape ? py::cast(PyPolyhedron{b.shape}) : py::none();
          },
          [](BodyDef& b, const py::object& shape) {
            b.shape = shape.is_none() ? nullptr : shape.cast<PyPolyhedron>().polyhedron;
          },
          "a Polyhedron, or None for a sphere; placed by its centroid")
      .def_readwrite("position", &BodyDef::position, "centre of mass, m")
      .def_property(
          "orientation", [](const BodyDef& b) { return QuaternionTuple(b.orientation); },
          [](BodyDef& b, const py::sequence& q) { b.orientation = QuaternionFrom(q); },
          "body to world, unit quaternion (w, x, y, z)")
      .def_readwrite("velocity", &BodyDef::velocity, "m/s")
      .def_readwrite("angular_velocity", &BodyDef::angular_velocity, "rad/s, world frame")
      .def_readwrite("thrust", &BodyDef::thrust, "own acceleration added to gravity, m/s^2")
      .def_readwrite("mass", &BodyDef::mass, "kg")
      .def_readwrite("restitution", &BodyDef::restitution, "in [0, 1]")
      .def_readwrite("friction", &BodyDef::friction, "Coulomb coefficient >= 0")
      .def_property(
          "envelope",
          [](const BodyDef& b) {
            return py::make_tuple(b.envelope.e0, b.envelope.e1, b.envelope.e2);
          },
          [](BodyDef& b, const std::array<double, 3>& e) {
            b.envelope = {e[0], e[1], e[2]};
          },
          "(e0, e1, e2): growth of the bounding sphere, App. F")
      .def_property(
          "thrust_schedule", [](const BodyDef& b) { return ScheduleList(b.thrust_schedule); },
          [](BodyDef& b, const py::sequence& changes) {
            b.thrust_schedule = ScheduleFrom(changes, "thrust_schedule");
          },
          "later changes of thrust: (time, (x, y, z)) pairs, times increasing and not before "
          "the World's clock")
      .def_readwrite("is_static", &BodyDef::is_static,
                     "fixed where it is placed, infinite mass, no events of its own (zero "
                     "velocity, spin, thrust and envelope); not in periodic boxes")
      .def_readwrite("god", &BodyDef::god,
                     "a GodDef, or None: a god object driven along its track with bounded "
                     "acceleration, of infinite mass to other bodies; no thrust, spin or "
                     "envelope; not in periodic boxes");
}

void BindGod(py::module_& m) {
  py::class_<GodTarget>(m, "GodTarget",
                        "One target of a god object's track (GodTarget): be at `position` at "
                        "`time`, moving at `velocity` if one is given.")
      .def(py::init([](double time, const Vec3& position, std::optional<Vec3> velocity) {
             return GodTarget{time, position, velocity};
           }),
           py::arg("time"), py::arg("position"), py::arg("velocity") = py::none())
      .def_readwrite("time", &GodTarget::time, "s, absolute")
      .def_readwrite("position", &GodTarget::position, "the centre of mass, m")
      .def_readwrite("velocity", &GodTarget::velocity,
                     "m/s, or None: the plan chooses it (a sweep through the waypoints)")
      .def("__repr__", [](const GodTarget& t) {
        return py::str("GodTarget(time={!r}, position={}, velocity={})")
            .format(t.time, Vec3(t.position),
                    t.velocity ? py::cast(Vec3(*t.velocity)) : py::none());
      });
  py::class_<GodDef>(m, "GodDef",
                     "A god object's drive (GodDef): its track of GodTarget, followed with "
                     "|acceleration| <= max_acceleration.")
      .def(py::init([](double max_acceleration, std::vector<GodTarget> track) {
             return GodDef{max_acceleration, std::move(track)};
           }),
           py::arg("max_acceleration") = 1.0, py::arg("track") = std::vector<GodTarget>{})
      .def_readwrite("max_acceleration", &GodDef::max_acceleration, "A, m/s^2, > 0")
      .def_readwrite("track", &GodDef::track,
                     "a list of GodTarget, times strictly increasing, none before the World's "
                     "clock (a copy: assign a new list to change it)")
      .def("__repr__", [](const GodDef& g) {
        return py::str("GodDef(max_acceleration={!r}, track={!r})")
            .format(g.max_acceleration, py::cast(g.track));
      });
}

void BindBodyId(py::module_& m) {
  py::class_<BodyId>(m, "BodyId",
                     "A body's handle, returned by World.add_body: its slot `index` (its row in "
                     "the World's arrays) and the slot's `generation`. Stale once the body is "
                     "removed: the World then refuses it, also when a later body takes the slot "
                     "(under a new generation).")
      .def(py::init([](std::uint32_t index, std::uint32_t generation) {
             return BodyId{index, generation};
           }),
           py::arg("index"), py::arg("generation") = 0)
      .def_readonly("index", &BodyId::index)
      .def_readonly("generation", &BodyId::generation)
      .def(
          "__index__", [](const BodyId& id) { return id.index; },
          "The slot: a handle indexes the World's arrays (positions()[body]).")
      .def(py::self == py::self)
      .def("__hash__",
           [](const BodyId& id) { return py::hash(py::make_tuple(id.index, id.generation)); })
      .def("__repr__", [](const BodyId& id) {
        return "BodyId(index=" + std::to_string(id.index) +
               ", generation=" + std::to_string(id.generation) + ")";
      });
}

void BindBodyState(py::module_& m) {
  py::class_<BodyState>(m, "BodyState",
                        "A body's state evaluated from its path at some time (World.state).")
      .def_readonly("position", &BodyState::position, "centre of mass, m")
      .def_readonly("velocity", &BodyState::velocity, "m/s")
      .def_readonly("acceleration", &BodyState::acceleration,
                    "m/s^2: gravity plus thrust, unless a wall holds the body")
      .def_property_readonly(
          "orientation", [](const BodyState& s) { return QuaternionTuple(s.orientation); },
          "body to world, unit quaternion (w, x, y, z)")
      .def_readonly("angular_velocity", &BodyState::angular_velocity, "rad/s, world frame")
      .def_readonly("radius", &BodyState::radius,
                    "m: a sphere's radius or a polyhedron's bounding radius")
      .def_readonly("mass", &BodyState::mass, "kg; inf for a static body")
      .def_readonly("version", &BodyState::version, "the number of path changes so far")
      .def("__repr__", [](const BodyState& s) {
        return py::str(
                   "BodyState(position={}, velocity={}, orientation={}, "
                   "angular_velocity={})")
            .format(Vec3(s.position), Vec3(s.velocity), QuaternionTuple(s.orientation),
                    Vec3(s.angular_velocity));
      });
}

void BindPolyhedron(py::module_& m) {
  py::class_<PyPolyhedron>(m, "Polyhedron", "An immutable convex polyhedron (ConvexPolyhedron).")
      .def_static(
          "from_points",
          [](const std::vector<Eigen::Vector3d>& points) {
            return Share(ConvexPolyhedron::FromPoints(points));
          },
          py::arg("points"), "The convex hull of points, an (n, 3) array (Qhull).")
      .def_static(
          "read",
          [](const std::string& path) {
            const PolygonMesh mesh = ValueOrRaise(ReadMesh(path));
            Result<ConvexPolyhedron> built = ConvexPolyhedron::FromMesh(mesh);
            if (!built) throw InputError(path + ": " + built.error().message);
            return Share(std::move(built));
          },
          py::arg("path"), "A mesh file (OFF, OBJ, STL, PLY, Ohio State), checked to be convex.")
      .def_static(
          "random",
          [](int faces, std::uint64_t seed) { return Share(RandomConvexPolyhedron(faces, seed)); },
          py::arg("faces"), py::arg("seed") = 1,
          "A random convex polyhedron with exactly `faces` faces, deterministic for the seed.")
      .def_static(
          "box", [](const Eigen::Vector3d& half_extents) { return Share(MakeBox(half_extents)); },
          py::arg("half_extents"), "The box [-h, h] for half extents h > 0.")
      .def_property_readonly("vertex_count",
                             [](const PyPolyhedron& p) { return p.polyhedron->vertex_count(); })
      .def_property_readonly("face_count",
                             [](const PyPolyhedron& p) { return p.polyhedron->face_count(); })
      .def_property_readonly("volume", [](const PyPolyhedron& p) { return p.polyhedron->volume(); })
      .def_property_readonly("centroid",
                             [](const PyPolyhedron& p) { return p.polyhedron->centroid(); })
      .def_property_readonly("bounding_radius",
                             [](const PyPolyhedron& p) { return p.polyhedron->bounding_radius(); })
      .def_property_readonly(
          "vertices",
          [](const PyPolyhedron& p) {
            const auto vertices = p.polyhedron->vertices();
            Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> out(vertices.size(), 3);
            for (std::size_t v = 0; v < vertices.size(); ++v) {
              out.row(static_cast<Eigen::Index>(v)) = vertices[v].transpose();
            }
            return out;
          },
          "(n, 3) array, in the polyhedron's own frame (not recentred)");
}

}  // namespace

void BindTypes(py::module_& m) {
  BindEnums(m);
  BindContainer(m);
  BindSettings(m);
  BindPolyhedron(m);
  BindGod(m);
  BindBody(m);
  BindBodyId(m);
  BindBodyState(m);
}

}  // namespace sparsedyn::python
