// SPDX-License-Identifier: MIT
// Lin-Canny zone (Voronoi region) tests: is the other polyhedron's closest point in the zone of
// the current feature, and if not, which neighbouring features may the walk step to.
#pragma once

#include <Eigen/Core>
#include <array>

#include "narrow/angle_tables.hpp"
#include "narrow/feature_distance.hpp"
#include "narrow/tables.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn::narrow {

/// A step the zone test proposes.
struct Move {
  enum class Kind : std::uint8_t {
    kLower,       // to a boundary feature that holds the current closest point: distance kept
    kHigher,      // to a feature that contains the current one: distance strictly lowered
    kBehindFace,  // the point is over the face but behind its plane (V-Clip's local minimum)
  };
  FeatureId to;
  Kind kind = Kind::kLower;
};

/// At most this many candidate steps per zone test: the most violated planes first.
inline constexpr int kMaxMoves = 3;

struct Moves {
  std::array<Move, kMaxMoves> list;
  int count = 0;
  void Add(Move move) {
    if (count < kMaxMoves) list[static_cast<std::size_t>(count++)] = move;
  }
};

/// The steps out of feature `f` of `polyhedron` for the other feature's closest point q (in the
/// polyhedron's frame); `own_slot` is the face edge slot of this feature's closest point (see
/// FacePoint) and `verdict` the face's zone test when already decided (see FaceVerdict; only
/// for a face). Empty when q is in the closed zone. Tie rule: a point on a zone plane
/// (SignedDistance == 0) is inside. `tables` may be nullptr.
Moves ZoneMoves(const ConvexPolyhedron& polyhedron, const TrackedPolyhedron::Tables* tables,
                FeatureId f, const Eigen::Vector3d& q, int own_slot,
                FaceVerdict verdict = FaceVerdict::kUnknown);

namespace zone_detail {
inline bool InVertexZone(const ConvexPolyhedron& polyhedron,
                         const TrackedPolyhedron::Tables* tables, int v, const Eigen::Vector3d& q) {
  const auto planes = polyhedron.VertexPlanes(v);
  const VertexAngleTable* table = tables == nullptr ? nullptr : tables->vertex(v);
  if (table != nullptr) {
    const std::int32_t deciding = table->DecidingPlane(q - polyhedron.vertex(v));
    if (deciding >= 0) {
      return !(planes[static_cast<std::size_t>(deciding)].plane.SignedDistance(q) < 0.0);
    }
  }
  for (const VoronoiPlane& plane : planes) {
    if (plane.plane.SignedDistance(q) < 0.0) return false;
  }
  return true;
}

inline bool InEdgeZone(const ConvexPolyhedron& polyhedron, int e, const Eigen::Vector3d& q) {
  for (const VoronoiPlane& plane : polyhedron.EdgePlanes(e)) {
    if (plane.plane.SignedDistance(q) < 0.0) return false;
  }
  return true;
}

inline bool InFaceZone(const ConvexPolyhedron& polyhedron, const TrackedPolyhedron::Tables* tables,
                       int f, const Eigen::Vector3d& q, int own_slot, FaceVerdict verdict) {
  if (verdict != FaceVerdict::kUnknown) return verdict == FaceVerdict::kInZone;
  const FaceAngleTable* table = tables == nullptr ? nullptr : tables->face(f);
  // As FaceMoves: outside the prism with no boundary slot counts as over the face.
  if (!IsOverFace(polyhedron, f, table, q)) return own_slot < 0;
  return !(polyhedron.face(f).plane.SignedDistance(q) < 0.0);
}

}  // namespace zone_detail

/// Whether ZoneMoves(polyhedron, tables, f, q, own_slot, verdict) is empty, without building
/// the moves: the test of almost every warm-started update, whose closest pair has not changed.
/// Inline: it runs twice per update.
inline bool InZone(const ConvexPolyhedron& polyhedron, const TrackedPolyhedron::Tables* tables,
                   FeatureId f, const Eigen::Vector3d& q, int own_slot,
                   FaceVerdict verdict = FaceVerdict::kUnknown) {
  switch (f.type) {
    case FeatureType::kVertex:
      return zone_detail::InVertexZone(polyhedron, tables, f.index, q);
    case FeatureType::kEdge:
      return zone_detail::InEdgeZone(polyhedron, f.index, q);
    case FeatureType::kFace:
      return zone_detail::InFaceZone(polyhedron, tables, f.index, q, own_slot, verdict);
    case FeatureType::kNone:
      break;
  }
  return true;
}

}  // namespace sparsedyn::narrow
