// SPDX-License-Identifier: MIT
#include "world/shape_table.hpp"

namespace sparsedyn {

Result<BodyShape> ShapeTable::Build(const std::shared_ptr<const ConvexPolyhedron>& shape) const {
  BodyShape s;
  s.given = shape;
  s.polyhedron = shape;
  if (shape->centroid().norm() > 1e-12 * shape->scale()) {
    s.polyhedron = std::make_shared<const ConvexPolyhedron>(shape->Recentered());
  }
  s.tracked = std::make_shared<const TrackedPolyhedron>(s.polyhedron);
  const Eigen::Matrix3d unit = s.polyhedron->inertia() / s.polyhedron->volume();
  s.unit_inertia = model_ == RotationModel::kSphericalTop
                       ? Eigen::Matrix3d((unit.trace() / 3.0) * Eigen::Matrix3d::Identity())
                       : unit;
  s.unit_inv_inertia = s.unit_inertia.inverse();
  if (!s.unit_inv_inertia.allFinite() || s.unit_inertia.determinant() <= 0) {
    return Error{"shape: its inertia tensor is singular (a degenerate polyhedron)"};
  }
  return s;
}

std::uint32_t ShapeTable::Insert(BodyShape shape) {
  const auto index = static_cast<std::uint32_t>(shapes_.size());
  index_.emplace(shape.given.get(), index);
  shapes_.push_back(std::move(shape));
  return index;
}

}  // namespace sparsedyn
