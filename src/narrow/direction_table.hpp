// SPDX-License-Identifier: MIT
// App. J.1.2: a latitude-longitude table that names, for each direction from the polyhedron, the
// feature met first when approaching from far away in that direction (its support vertex).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn::narrow {

class DirectionTable {
 public:
  /// Equal-area bands in z (uniform in z = cos(latitude)) times equal pseudo-angle sectors in
  /// longitude: 512 cells, about 10 degrees across, so a lookup needs no trigonometry.
  static constexpr int kBands = 16;
  static constexpr int kSectors = 32;

  DirectionTable() = default;
  explicit DirectionTable(const ConvexPolyhedron& polyhedron);

  /// The support vertex stored for the cell of direction d (body frame, any length > 0).
  std::int32_t VertexFor(const Eigen::Vector3d& direction) const;

 private:
  static int Cell(const Eigen::Vector3d& unit_direction);
  std::vector<std::int32_t> vertices_;  // kBands * kSectors entries
};

}  // namespace sparsedyn::narrow
