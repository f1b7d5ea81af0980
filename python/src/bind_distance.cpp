// SPDX-License-Identifier: MIT
// The closest features of two convex polyhedra (include/sparsedyn/narrow/closest_features.hpp)
// as sparsedyn.distance, with the keys of `sparsedyn distance --json`.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "convert.hpp"
#include "errors.hpp"
#include "sparsedyn/io/distance_summary.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace py = pybind11;

namespace sparsedyn::python {
namespace {

py::object Distance(const PyPolyhedron& a, const PyPolyhedron& b, const py::object& pose_a,
                    const py::object& pose_b) {
  const Pose X_WA = pose_a.is_none() ? Pose{} : PoseFrom(pose_a, "pose_a");
  const Pose X_WB = pose_b.is_none() ? Pose{} : PoseFrom(pose_b, "pose_b");
  ClosestFeatures r;
  {
    py::gil_scoped_release release;
    const TrackedPolyhedron tracked_a(a.polyhedron), tracked_b(b.polyhedron);
    r = FindClosestFeatures(tracked_a, X_WA, tracked_b, X_WB);
  }
  return py::module_::import("json").attr("loads")(DistanceSummaryJson(r));
}

}  // namespace

void BindDistance(py::module_& m) {
  m.def("distance", &Distance, py::arg("a"), py::arg("b"), py::arg("pose_a") = py::none(),
        py::arg("pose_b") = py::none(),
        "Closest features of Polyhedron a and b, each placed by (x, y, z, qw, qx, qy, qz) "
        "(default: identity), in their own frames as read (not recentred), as a dict with the "
        "keys of `sparsedyn distance --json`: distance (negative = penetration depth), "
        "status, point_a, point_b, normal (world frame, from a to b), feature_a, feature_b, "
        "steps.");
}

}  // namespace sparsedyn::python
