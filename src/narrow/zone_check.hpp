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

/// A zone test in one pass: in the zone, or out of it with the move when the zone proposes
/// exactly one (the one ZoneMoves gives), or out of it with possibly several (then ZoneMoves
/// lists them). The walk's steps need no second evaluation of the planes in the common cases.
struct ZoneTest {
  enum class Result : std::uint8_t { kInZone, kOneMove, kSeveral };
  Result result = Result::kInZone;
  Move move;
};

namespace zone_detail {
inline ZoneTest Out(FeatureId to, Move::Kind kind) {
  return {ZoneTest::Result::kOneMove, {to, kind}};
}

// The vertex table's deciding plane names the one move; a plain scan leaves the sorting of the
// violated planes to VertexMoves.
inline ZoneTest TestVertexZone(const ConvexPolyhedron& polyhedron,
                               const TrackedPolyhedron::Tables* tables, int v,
                               const Eigen::Vector3d& q) {
  const auto planes = polyhedron.VertexPlanes(v);
  const VertexAngleTable* table = tables == nullptr ? nullptr : tables->vertex(v);
  if (table != nullptr) {
    const std::int32_t deciding = table->DecidingPlane(q - polyhedron.vertex(v));
    if (deciding >= 0) {
      const VoronoiPlane& plane = planes[static_cast<std::size_t>(deciding)];
      if (!(plane.plane.SignedDistance(q) < 0.0)) return {};
      return Out(plane.neighbor, Move::Kind::kHigher);
    }
  }
  for (const VoronoiPlane& plane : planes) {
    if (plane.plane.SignedDistance(q) < 0.0) return {ZoneTest::Result::kSeveral, {}};
  }
  return {};
}

// As EdgeMoves: an end plane first (the more violated), then the face planes; both face planes
// violated leaves their order to EdgeMoves.
inline ZoneTest TestEdgeZone(const ConvexPolyhedron& polyhedron, int e, const Eigen::Vector3d& q) {
  const auto planes = polyhedron.EdgePlanes(e);
  const double d0 = planes[0].plane.SignedDistance(q), d1 = planes[1].plane.SignedDistance(q);
  if (d0 < 0.0 || d1 < 0.0) return Out(planes[d0 <= d1 ? 0 : 1].neighbor, Move::Kind::kLower);
  const bool out2 = planes[2].plane.SignedDistance(q) < 0.0;
  const bool out3 = planes[3].plane.SignedDistance(q) < 0.0;
  if (out2 == out3) return {out2 ? ZoneTest::Result::kSeveral : ZoneTest::Result::kInZone, {}};
  return Out(planes[out2 ? 2 : 3].neighbor, Move::Kind::kHigher);
}

// As FaceMoves: outside the prism with no boundary slot counts as over the face.
inline ZoneTest TestFaceZone(const ConvexPolyhedron& polyhedron,
                             const TrackedPolyhedron::Tables* tables, int f,
                             const Eigen::Vector3d& q, int own_slot, FaceVerdict verdict) {
  bool over = verdict != FaceVerdict::kBeside, behind = verdict == FaceVerdict::kBehind;
  if (verdict == FaceVerdict::kUnknown) {
    over = IsOverFace(polyhedron, f, tables == nullptr ? nullptr : tables->face(f), q);
    behind = over && polyhedron.face(f).plane.SignedDistance(q) < 0.0;
  }
  if (!over) {
    if (own_slot < 0) return {};
    return Out(FeatureId::Edge(polyhedron.FaceEdges(f)[static_cast<std::size_t>(own_slot)]),
               Move::Kind::kLower);
  }
  if (behind) return Out(FeatureId::Face(f), Move::Kind::kBehindFace);
  return {};
}

}  // namespace zone_detail

/// The zone test of ZoneMoves(polyhedron, tables, f, q, own_slot, verdict) in one pass: the test
/// of almost every warm-started update, whose closest pair has not changed. Inline: it runs
/// twice per update.
inline ZoneTest TestZone(const ConvexPolyhedron& polyhedron,
                         const TrackedPolyhedron::Tables* tables, FeatureId f,
                         const Eigen::Vector3d& q, int own_slot,
                         FaceVerdict verdict = FaceVerdict::kUnknown) {
  switch (f.type) {
    case FeatureType::kVertex:
      return zone_detail::TestVertexZone(polyhedron, tables, f.index, q);
    case FeatureType::kEdge:
      return zone_detail::TestEdgeZone(polyhedron, f.index, q);
    case FeatureType::kFace:
      return zone_detail::TestFaceZone(polyhedron, tables, f.index, q, own_slot, verdict);
    case FeatureType::kNone:
      break;
  }
  return {};
}

/// Whether ZoneMoves(polyhedron, tables, f, q, own_slot, verdict) is empty.
inline bool InZone(const ConvexPolyhedron& polyhedron, const TrackedPolyhedron::Tables* tables,
                   FeatureId f, const Eigen::Vector3d& q, int own_slot,
                   FaceVerdict verdict = FaceVerdict::kUnknown) {
  return TestZone(polyhedron, tables, f, q, own_slot, verdict).result == ZoneTest::Result::kInZone;
}

}  // namespace sparsedyn::narrow
