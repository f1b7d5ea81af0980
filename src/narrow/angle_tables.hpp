// SPDX-License-Identifier: MIT
// App. J.1.1 angle tables: for a face (or a vertex) with many edges, the sector of a direction
// around the feature's centre names the one boundary plane that decides whether a point is in the
// feature's zone, so the walk finds it in O(log n) instead of testing all n planes.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn::narrow {

/// Faces and vertices with at least this many edges get a table; below it a plain scan of the
/// planes is as fast as the table's projection and search.
inline constexpr int kAngleTableMinEdges = 8;

/// A monotone stand-in for atan2(y, x) in [0, 4): cheaper, and only the order of angles matters.
double PseudoAngle(double x, double y);

/// Sorted sector boundaries around a centre: sector i spans [angles[i], angles[i + 1]) (cyclic)
/// and is bounded by the zone plane planes[i].
class SectorTable {
 public:
  SectorTable() = default;
  /// `angles` must increase cyclically (one turn) in the given order; plane i is the plane of the
  /// sector that starts at angle i. Returns nullopt when they do not.
  static std::optional<SectorTable> Build(const std::vector<double>& angles,
                                          const std::vector<std::int32_t>& planes);
  /// Index into the feature's VoronoiPlanes of the sector that contains pseudo-angle a.
  std::int32_t PlaneAt(double angle) const;

 private:
  std::vector<double> angles_;        // increasing, angles_[0] is the smallest
  std::vector<std::int32_t> planes_;  // planes_[i] bounds the sector starting at angles_[i]
};

/// J.1.1 table of a face: sectors between the rays from the vertex mean to consecutive vertices.
/// The polygon is star-shaped about that point, so a point's projection is in the polygon iff it
/// is on the inner side of the edge of its sector.
struct FaceAngleTable {
  Eigen::Vector3d centre, u, v;  // centre in the face plane; (u, v, normal) right-handed
  SectorTable sectors;
  /// The side plane (index into VoronoiPlanes(face)) that decides point q: q is over the face
  /// iff that plane is satisfied; if it is violated, it is a violated side plane.
  std::int32_t DecidingPlane(const Eigen::Vector3d& q) const;
};

/// J.1.1 table of a vertex: its zone is the normal cone spanned by the normals of its faces;
/// looking along the cone's axis, consecutive face normals bound sectors whose cone facet is the
/// plane of the edge the two faces share. Only built when every face normal is in the open
/// half-space of the axis (otherwise the central projection is not a bounded polygon).
struct VertexAngleTable {
  Eigen::Vector3d axis, u, v;
  SectorTable sectors;
  /// The plane (index into VoronoiPlanes(vertex)) that decides whether direction d = q - vertex
  /// is in the zone, or -1 when d points away from the axis (then d is outside: scan the planes).
  std::int32_t DecidingPlane(const Eigen::Vector3d& d) const;
};

std::optional<FaceAngleTable> BuildFaceAngleTable(const ConvexPolyhedron& polyhedron, int f);
std::optional<VertexAngleTable> BuildVertexAngleTable(const ConvexPolyhedron& polyhedron, int v);

}  // namespace sparsedyn::narrow
