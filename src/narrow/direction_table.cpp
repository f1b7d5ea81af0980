// SPDX-License-Identifier: MIT
#include "narrow/direction_table.hpp"

#include <algorithm>
#include <cmath>

#include "narrow/angle_tables.hpp"

namespace sparsedyn::narrow {
namespace {

// The point of the unit L1 diamond at pseudo-angle p (inverse of PseudoAngle up to scale).
Eigen::Vector2d DiamondPoint(double p) {
  if (p < 1.0) return {1.0 - p, p};
  if (p < 2.0) return {1.0 - p, 2.0 - p};
  if (p < 3.0) return {p - 3.0, 2.0 - p};
  return {p - 3.0, p - 4.0};
}

}  // namespace

DirectionTable::DirectionTable(const ConvexPolyhedron& polyhedron) {
  vertices_.resize(static_cast<std::size_t>(kBands * kSectors));
  for (int band = 0; band < kBands; ++band) {
    const double z = -1.0 + (2.0 * band + 1.0) / kBands;
    for (int sector = 0; sector < kSectors; ++sector) {
      const Eigen::Vector2d xy =
          DiamondPoint(4.0 * (sector + 0.5) / kSectors).normalized() * std::sqrt(1.0 - z * z);
      const Eigen::Vector3d direction(xy.x(), xy.y(), z);
      vertices_[static_cast<std::size_t>(Cell(direction))] = polyhedron.SupportVertex(direction);
    }
  }
}

int DirectionTable::Cell(const Eigen::Vector3d& unit_direction) {
  const int band =
      std::clamp(static_cast<int>((unit_direction.z() + 1.0) * 0.5 * kBands), 0, kBands - 1);
  const int sector = std::clamp(
      static_cast<int>(PseudoAngle(unit_direction.x(), unit_direction.y()) * 0.25 * kSectors), 0,
      kSectors - 1);
  return band * kSectors + sector;
}

std::int32_t DirectionTable::VertexFor(const Eigen::Vector3d& direction) const {
  const double length = direction.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return vertices_[0];
  return vertices_[static_cast<std::size_t>(Cell(direction / length))];
}

}  // namespace sparsedyn::narrow
