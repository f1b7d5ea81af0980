// SPDX-License-Identifier: MIT
#include "narrow/angle_tables.hpp"

#include <algorithm>
#include <cmath>

namespace sparsedyn::narrow {

double PseudoAngle(double x, double y) {
  // "Diamond angle": the position along the unit L1 circle, monotone in the true angle.
  const double l1 = std::abs(x) + std::abs(y);
  if (l1 == 0.0) return 0.0;
  if (y >= 0.0) return x >= 0.0 ? y / l1 : 1.0 - x / l1;
  return x < 0.0 ? 2.0 - y / l1 : 3.0 + x / l1;
}

std::optional<SectorTable> SectorTable::Build(const std::vector<double>& angles,
                                              const std::vector<std::int32_t>& planes) {
  const std::size_t n = angles.size();
  if (n < 3 || planes.size() != n) return std::nullopt;
  const std::size_t first =
      static_cast<std::size_t>(std::min_element(angles.begin(), angles.end()) - angles.begin());
  SectorTable table;
  for (std::size_t i = 0; i < n; ++i) {
    table.angles_.push_back(angles[(first + i) % n]);
    table.planes_.push_back(planes[(first + i) % n]);
  }
  // One counter-clockwise turn: strictly increasing once rotated to the smallest angle.
  for (std::size_t i = 1; i < n; ++i) {
    if (!(table.angles_[i] > table.angles_[i - 1])) return std::nullopt;
  }
  return table;
}

std::int32_t SectorTable::PlaneAt(double angle) const {
  const auto it = std::upper_bound(angles_.begin(), angles_.end(), angle);
  // Below the smallest boundary: the last sector, which wraps through angle 0.
  if (it == angles_.begin()) return planes_.back();
  return planes_[static_cast<std::size_t>(it - angles_.begin()) - 1];
}

std::int32_t FaceAngleTable::DecidingPlane(const Eigen::Vector3d& q) const {
  const Eigen::Vector3d d = q - centre;
  return sectors.PlaneAt(PseudoAngle(d.dot(u), d.dot(v)));
}

std::int32_t VertexAngleTable::DecidingPlane(const Eigen::Vector3d& d) const {
  if (!(d.dot(axis) > 0.0)) return -1;
  return sectors.PlaneAt(PseudoAngle(d.dot(u), d.dot(v)));
}

std::optional<FaceAngleTable> BuildFaceAngleTable(const ConvexPolyhedron& polyhedron, int f) {
  const auto loop = polyhedron.FaceVertices(f);
  if (static_cast<int>(loop.size()) < kAngleTableMinEdges) return std::nullopt;
  FaceAngleTable table;
  table.centre = Eigen::Vector3d::Zero();
  for (const std::int32_t v : loop) table.centre += polyhedron.vertex(v);
  table.centre /= static_cast<double>(loop.size());
  const Eigen::Vector3d& normal = polyhedron.face(f).plane.normal;
  table.u = (polyhedron.vertex(loop[0]) - table.centre).normalized();
  table.v = normal.cross(table.u);
  // Sector k starts at vertex k and is closed by edge k, whose side plane is VoronoiPlanes[1 + k].
  std::vector<double> angles;
  std::vector<std::int32_t> planes;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Eigen::Vector3d d = polyhedron.vertex(loop[k]) - table.centre;
    angles.push_back(PseudoAngle(d.dot(table.u), d.dot(table.v)));
    planes.push_back(static_cast<std::int32_t>(1 + k));
  }
  std::optional<SectorTable> sectors = SectorTable::Build(angles, planes);
  if (!sectors) return std::nullopt;
  table.sectors = std::move(*sectors);
  return table;
}

std::optional<VertexAngleTable> BuildVertexAngleTable(const ConvexPolyhedron& polyhedron, int v) {
  const auto faces = polyhedron.VertexFaces(v);
  const std::size_t n = faces.size();
  if (static_cast<int>(n) < kAngleTableMinEdges) return std::nullopt;
  VertexAngleTable table;
  table.axis = Eigen::Vector3d::Zero();
  for (const std::int32_t f : faces) table.axis += polyhedron.face(f).plane.normal;
  table.axis.normalize();
  // The central projection needs every normal strictly in front of the axis (margin for round-off).
  constexpr double kMinCosine = 1e-6;
  for (const std::int32_t f : faces) {
    if (!(polyhedron.face(f).plane.normal.dot(table.axis) > kMinCosine)) return std::nullopt;
  }
  const Eigen::Vector3d n0 = polyhedron.face(faces[0]).plane.normal;
  table.u = (n0 - n0.dot(table.axis) * table.axis).normalized();
  if (!table.u.allFinite()) return std::nullopt;
  table.v = table.axis.cross(table.u);
  // Face i lies between edges i and i + 1, so the cone facet between normals i and i + 1 is the
  // plane of edge i + 1 (VoronoiPlanes(vertex) is in VertexEdges order).
  std::vector<double> angles;
  std::vector<std::int32_t> planes;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& normal = polyhedron.face(faces[i]).plane.normal;
    angles.push_back(PseudoAngle(normal.dot(table.u), normal.dot(table.v)));
    planes.push_back(static_cast<std::int32_t>((i + 1) % n));
  }
  std::optional<SectorTable> sectors = SectorTable::Build(angles, planes);
  if (!sectors) {
    // The normals may turn clockwise about this axis: mirror the frame and try once more.
    table.v = -table.v;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d& normal = polyhedron.face(faces[i]).plane.normal;
      angles[i] = PseudoAngle(normal.dot(table.u), normal.dot(table.v));
    }
    sectors = SectorTable::Build(angles, planes);
    if (!sectors) return std::nullopt;
  }
  table.sectors = std::move(*sectors);
  return table;
}

}  // namespace sparsedyn::narrow
