// SPDX-License-Identifier: MIT
#include "convert.hpp"

#include <cmath>
#include <string>

#include "errors.hpp"

namespace py = pybind11;

namespace sparsedyn::python {

Eigen::Quaterniond QuaternionFrom(const py::sequence& wxyz) {
  if (py::len(wxyz) != 4) throw InputError("a quaternion is (w, x, y, z): 4 numbers");
  return {wxyz[0].cast<double>(), wxyz[1].cast<double>(), wxyz[2].cast<double>(),
          wxyz[3].cast<double>()};
}

py::tuple QuaternionTuple(const Eigen::Quaterniond& q) {
  return py::make_tuple(q.w(), q.x(), q.y(), q.z());
}

Pose PoseFrom(const py::sequence& pose, const char* name) {
  if (py::len(pose) != 7) {
    throw InputError(std::string(name) + ": a pose is (x, y, z, qw, qx, qy, qz): 7 numbers");
  }
  Pose out;
  out.translation = {pose[0].cast<double>(), pose[1].cast<double>(), pose[2].cast<double>()};
  const Eigen::Quaterniond q(pose[3].cast<double>(), pose[4].cast<double>(), pose[5].cast<double>(),
                             pose[6].cast<double>());
  // As `sparsedyn distance`: printed quaternions are unit to ~1e-7; farther off is a mistake.
  constexpr double kUnitQuaternionTolerance = 1e-6;
  if (!std::isfinite(q.norm()) || std::abs(q.norm() - 1.0) > kUnitQuaternionTolerance ||
      !out.translation.allFinite()) {
    throw InputError(std::string(name) +
                     ": needs finite values and a unit quaternion (within 1e-6), got norm " +
                     std::to_string(q.norm()));
  }
  out.rotation = q.normalized();
  return out;
}

std::vector<ThrustChange> ScheduleFrom(const py::sequence& changes, const char* name) {
  std::vector<ThrustChange> schedule;
  for (std::size_t k = 0; k < py::len(changes); ++k) {
    const py::object change = changes[k];
    const std::string at = std::string(name) + "[" + std::to_string(k) + "]";
    if (!py::isinstance<py::sequence>(change) || py::len(change) != 2) {
      throw InputError(at + ": a thrust change is a pair (time, (x, y, z))");
    }
    const py::sequence pair = change.cast<py::sequence>();
    const py::sequence thrust = pair[1].cast<py::sequence>();
    if (py::len(thrust) != 3) throw InputError(at + ": the thrust is (x, y, z): 3 numbers");
    schedule.push_back(
        {pair[0].cast<double>(),
         Vec3(thrust[0].cast<double>(), thrust[1].cast<double>(), thrust[2].cast<double>())});
  }
  return schedule;
}

py::list ScheduleList(const std::vector<ThrustChange>& schedule) {
  py::list out;
  for (const ThrustChange& change : schedule) {
    out.append(py::make_tuple(
        change.time, py::make_tuple(change.thrust[0], change.thrust[1], change.thrust[2])));
  }
  return out;
}

void SetAttributes(py::handle self, const py::kwargs& values) {
  for (const auto& [key, value] : values) py::setattr(self, key, value);
}

}  // namespace sparsedyn::python
