// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sparsedyn {

/// A polygon soup or closed surface as read from a mesh file or written by hand: vertex
/// positions and faces given as 0-based vertex indices, counter-clockwise seen from outside
/// (outward normals by the right-hand rule). Nothing is validated here; the loaders in io/
/// produce it and ConvexPolyhedron::FromMesh validates it.
struct PolygonMesh {
  /// Vertex positions in the mesh's frame.
  std::vector<Eigen::Vector3d> vertices;
  /// Each face as its 0-based vertex indices, counter-clockwise seen from outside.
  std::vector<std::vector<std::int32_t>> faces;
};

}  // namespace sparsedyn
