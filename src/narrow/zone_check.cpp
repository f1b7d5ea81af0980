// SPDX-License-Identifier: MIT
#include "narrow/zone_check.hpp"

#include <algorithm>

#include "narrow/feature_distance.hpp"

namespace sparsedyn::narrow {
namespace {

// Violated planes of a vertex zone, most violated first (lowest plane index on ties). The
// neighbour of every vertex plane is an edge that contains the vertex: a higher step.
Moves VertexMoves(const ConvexPolyhedron& polyhedron, const TrackedPolyhedron::Tables* tables,
                  int v, const Eigen::Vector3d& q) {
  const auto planes = polyhedron.VertexPlanes(v);
  Moves moves;
  const VertexAngleTable* table = tables == nullptr ? nullptr : tables->vertex(v);
  if (table != nullptr) {
    // J.1.1: one plane decides, unless q lies on the far side of the cone's axis.
    const std::int32_t deciding = table->DecidingPlane(q - polyhedron.vertex(v));
    if (deciding >= 0) {
      const VoronoiPlane& plane = planes[static_cast<std::size_t>(deciding)];
      if (plane.plane.SignedDistance(q) < 0.0) moves.Add({plane.neighbor, Move::Kind::kHigher});
      return moves;
    }
  }
  std::array<std::pair<double, std::size_t>, kMaxMoves> worst{};
  int count = 0;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const double d = planes[i].plane.SignedDistance(q);
    if (!(d < 0.0)) continue;
    // Keep the kMaxMoves most negative distances, sorted (earlier plane first on ties).
    if (count < kMaxMoves) {
      worst[static_cast<std::size_t>(count++)] = {d, i};
    } else if (d < worst[kMaxMoves - 1].first) {
      worst[kMaxMoves - 1] = {d, i};
    } else {
      continue;
    }
    for (int k = count - 1; k > 0 && worst[static_cast<std::size_t>(k)].first <
                                         worst[static_cast<std::size_t>(k - 1)].first;
         --k) {
      std::swap(worst[static_cast<std::size_t>(k)], worst[static_cast<std::size_t>(k - 1)]);
    }
  }
  for (int k = 0; k < count; ++k) {
    moves.Add({planes[worst[static_cast<std::size_t>(k)].second].neighbor, Move::Kind::kHigher});
  }
  return moves;
}

// Edge zone: an end plane first (the closest point of the edge is then that end: a lower step),
// then the face planes, the more violated first.
Moves EdgeMoves(const ConvexPolyhedron& polyhedron, int e, const Eigen::Vector3d& q) {
  const auto planes = polyhedron.EdgePlanes(e);
  Moves moves;
  const double d0 = planes[0].plane.SignedDistance(q), d1 = planes[1].plane.SignedDistance(q);
  if (d0 < 0.0 || d1 < 0.0) {
    moves.Add({planes[d0 <= d1 ? 0 : 1].neighbor, Move::Kind::kLower});
    return moves;
  }
  const double f0 = planes[2].plane.SignedDistance(q), f1 = planes[3].plane.SignedDistance(q);
  // The distances just computed decide (no second evaluation of the same planes).
  const bool f1_first = f1 < f0;
  const double d_first = f1_first ? f1 : f0, d_second = f1_first ? f0 : f1;
  const std::size_t first = f1_first ? 3 : 2, second = f1_first ? 2 : 3;
  if (d_first < 0.0) moves.Add({planes[first].neighbor, Move::Kind::kHigher});
  if (d_second < 0.0) moves.Add({planes[second].neighbor, Move::Kind::kHigher});
  return moves;
}

// Face zone: outside a side plane, step to the boundary edge that holds the face's closest point
// (a lower step); over the face but behind its plane, report it (the walk resolves it).
Moves FaceMoves(const ConvexPolyhedron& polyhedron, const TrackedPolyhedron::Tables* tables, int f,
                const Eigen::Vector3d& q, int own_slot, FaceVerdict verdict) {
  Moves moves;
  const FaceAngleTable* table = tables == nullptr ? nullptr : tables->face(f);
  const bool over = verdict != FaceVerdict::kUnknown ? verdict != FaceVerdict::kBeside
                                                     : IsOverFace(polyhedron, f, table, q);
  if (!over) {
    // The closest point of the polygon is on its boundary, on edge own_slot. (own_slot < 0 only
    // when round-off put the point a hair outside: then it counts as over the face.)
    if (own_slot >= 0) {
      moves.Add({FeatureId::Edge(polyhedron.FaceEdges(f)[static_cast<std::size_t>(own_slot)]),
                 Move::Kind::kLower});
    }
    return moves;
  }
  const bool behind = verdict != FaceVerdict::kUnknown
                          ? verdict == FaceVerdict::kBehind
                          : polyhedron.face(f).plane.SignedDistance(q) < 0.0;
  if (behind) {
    moves.Add({FeatureId::Face(f), Move::Kind::kBehindFace});
  }
  return moves;
}

}  // namespace

Moves ZoneMoves(const ConvexPolyhedron& polyhedron, const TrackedPolyhedron::Tables* tables,
                FeatureId f, const Eigen::Vector3d& q, int own_slot, FaceVerdict verdict) {
  switch (f.type) {
    case FeatureType::kVertex:
      return VertexMoves(polyhedron, tables, f.index, q);
    case FeatureType::kEdge:
      return EdgeMoves(polyhedron, f.index, q);
    case FeatureType::kFace:
      return FaceMoves(polyhedron, tables, f.index, q, own_slot, verdict);
    case FeatureType::kNone:
      break;
  }
  return {};
}

}  // namespace sparsedyn::narrow
