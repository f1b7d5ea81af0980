// SPDX-License-Identifier: MIT
// Small conversions between Python values and the library's types.
#pragma once

#include <pybind11/pybind11.h>

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/pose.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn::python {

/// A unit quaternion from a sequence (w, x, y, z); its norm is checked where it is used.
Eigen::Quaterniond QuaternionFrom(const pybind11::sequence& wxyz);
/// (w, x, y, z).
pybind11::tuple QuaternionTuple(const Eigen::Quaterniond& q);
/// A pose from (x, y, z, qw, qx, qy, qz), as `sparsedyn distance --pose-a` takes it.
Pose PoseFrom(const pybind11::sequence& pose, const char* name);

/// A thrust schedule from a sequence of (time, (x, y, z)) pairs, s and m/s^2; the World checks
/// the times.
std::vector<ThrustChange> ScheduleFrom(const pybind11::sequence& changes, const char* name);
/// The schedule as a list of (time, (x, y, z)) tuples.
pybind11::list ScheduleList(const std::vector<ThrustChange>& schedule);

/// A convex polyhedron shared by bodies and distance queries (Python class Polyhedron).
struct PyPolyhedron {
  std::shared_ptr<const ConvexPolyhedron> polyhedron;
};

/// Sets every keyword argument as an attribute of `self` (an unknown name raises
/// AttributeError): the keyword constructors of Settings and Body, which stay one line per field.
void SetAttributes(pybind11::handle self, const pybind11::kwargs& values);

}  // namespace sparsedyn::python
