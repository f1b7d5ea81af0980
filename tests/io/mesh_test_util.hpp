// SPDX-License-Identifier: MIT
#pragma once

// Comparisons for the mesh reader tests.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "sparsedyn/geometry/polygon_mesh.hpp"

namespace sparsedyn::testing {

using Triangle = std::array<std::array<double, 3>, 3>;

/// The surface as a sorted list of oriented triangles of positions (each polygon fanned from
/// its first vertex, each triangle rotated to start at its smallest corner). Two meshes with
/// equal soups describe the same oriented surface, whatever their vertex numbering; this is
/// what survives a trip through STL.
inline std::vector<Triangle> TriangleSoup(const PolygonMesh& mesh) {
  std::vector<Triangle> soup;
  const auto at = [&](std::int32_t i) {
    const Eigen::Vector3d& p = mesh.vertices[static_cast<std::size_t>(i)];
    return std::array<double, 3>{p.x(), p.y(), p.z()};
  };
  for (const std::vector<std::int32_t>& face : mesh.faces) {
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      Triangle t{at(face[0]), at(face[k]), at(face[k + 1])};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      soup.push_back(t);
    }
  }
  std::sort(soup.begin(), soup.end());
  return soup;
}

/// `mesh` with each coordinate rounded to float32, as binary STL stores it.
inline PolygonMesh RoundedToFloat(PolygonMesh mesh) {
  for (Eigen::Vector3d& p : mesh.vertices) {
    for (int axis = 0; axis < 3; ++axis) {
      // Through a volatile: GCC 12.2's SLP vectorizer at -O2 drops the plain
      // double(float(x)) round trip in this loop (seen in RelWithDebInfo builds).
      volatile float rounded = static_cast<float>(p[axis]);
      p[axis] = rounded;
    }
  }
  return mesh;
}

/// True if both meshes have exactly the same vertices (bitwise-equal values, same order)
/// and the same faces.
inline bool SameMesh(const PolygonMesh& a, const PolygonMesh& b) {
  return a.vertices == b.vertices && a.faces == b.faces;
}

}  // namespace sparsedyn::testing
