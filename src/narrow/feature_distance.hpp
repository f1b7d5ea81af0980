// SPDX-License-Identifier: MIT
// Closest points between two features (vertex = point, edge = segment, face = filled convex
// polygon): the distance the walk minimises. Each primitive works in the frame of the polyhedron
// that owns the face, so a large face is never transformed.
#pragma once

#include <Eigen/Core>

#include "narrow/angle_tables.hpp"
#include "narrow/pair_frame.hpp"
#include "narrow/tables.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn::narrow {

/// Closest points p = p0 + s (p1 - p0), q = q0 + t (q1 - q0) of two segments (either may be a
/// point). Nearly parallel segments are decided among the four endpoint-to-segment pairs, so the
/// answer does not depend on a near-zero determinant.
struct SegmentClosest {
  double s = 0.0, t = 0.0;
  Eigen::Vector3d p, q;
};
SegmentClosest ClosestSegmentSegment(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                     const Eigen::Vector3d& q0, const Eigen::Vector3d& q1);

/// Whether q lies over face f (in the prism its side planes bound; on a side plane counts as
/// over): the J.1.1 table decides with one plane when given, else all side planes are tested.
/// Inline: the zone test of a face runs at every update whose closest feature is a face.
inline bool IsOverFace(const ConvexPolyhedron& polyhedron, int f, const FaceAngleTable* table,
                       const Eigen::Vector3d& q) {
  const auto planes = polyhedron.FacePlanes(f);
  if (table != nullptr) {
    return planes[static_cast<std::size_t>(table->DecidingPlane(q))].plane.SignedDistance(q) >= 0.0;
  }
  for (std::size_t i = 1; i < planes.size(); ++i) {
    if (planes[i].plane.SignedDistance(q) < 0.0) return false;
  }
  return true;
}

/// Closest point of face f's polygon to q (polyhedron frame). edge_slot is the position in
/// FaceEdges(f) of the boundary edge the point lies on, or -1 when it is inside the polygon;
/// then height is q's signed distance from the face plane.
struct FacePoint {
  Eigen::Vector3d point;
  int edge_slot = -1;
  double height = 0.0;
};
FacePoint ClosestPointOnFace(const ConvexPolyhedron& polyhedron, int f, const FaceAngleTable* table,
                             const Eigen::Vector3d& q);

/// Closest points of segment s0 + s (s1 - s0) and face f's polygon (polyhedron frame).
struct SegmentFaceClosest {
  double s = 0.0;
  Eigen::Vector3d on_segment, on_face;
  int edge_slot = -1;  // as in FacePoint
};
SegmentFaceClosest ClosestSegmentFace(const ConvexPolyhedron& polyhedron, int f,
                                      const FaceAngleTable* table, const Eigen::Vector3d& s0,
                                      const Eigen::Vector3d& s1);

/// A face's zone test against the other feature's closest point, when that feature is a vertex:
/// finding the vertex's closest point on the face has already decided it (the same point against
/// the same planes), so the walk need not test again. kBeside: outside a side plane, the walk
/// steps to the boundary edge of the face's edge slot; kBehind: over the face, behind its plane.
enum class FaceVerdict : std::uint8_t { kUnknown, kInZone, kBeside, kBehind };

/// Closest points of feature fa of A and fb of B, both in A's frame, with the face edge slots
/// (see FacePoint) of the two points when their feature is a face, and the face's verdict when
/// the other feature is a vertex.
struct FeatureClosest {
  Eigen::Vector3d p_a = Eigen::Vector3d::Zero(), p_b = Eigen::Vector3d::Zero();
  double distance = 0.0;
  int slot_a = -1, slot_b = -1;
  FaceVerdict verdict_a = FaceVerdict::kUnknown, verdict_b = FaceVerdict::kUnknown;
};
/// `tables_a` / `tables_b` may be nullptr (no J.1.1 tables). Written into `out` (every field is
/// set): the walk computes a candidate in place instead of copying a returned answer.
void ClosestPointsOfFeatures(const ConvexPolyhedron& a, const TrackedPolyhedron::Tables* tables_a,
                             FeatureId fa, const ConvexPolyhedron& b,
                             const TrackedPolyhedron::Tables* tables_b, FeatureId fb,
                             const PairFrame& frame, FeatureClosest& out);
/// The same, returned.
inline FeatureClosest ClosestPointsOfFeatures(const ConvexPolyhedron& a,
                                              const TrackedPolyhedron::Tables* tables_a,
                                              FeatureId fa, const ConvexPolyhedron& b,
                                              const TrackedPolyhedron::Tables* tables_b,
                                              FeatureId fb, const PairFrame& frame) {
  FeatureClosest out;
  ClosestPointsOfFeatures(a, tables_a, fa, b, tables_b, fb, frame, out);
  return out;
}

}  // namespace sparsedyn::narrow
