// SPDX-License-Identifier: MIT
#include "narrow/feature_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "sparsedyn/assert.hpp"

namespace sparsedyn::narrow {
namespace {

double ClosestParameterOnSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& p) {
  const Eigen::Vector3d ab = b - a;
  const double length_squared = ab.squaredNorm();
  if (length_squared == 0.0) return 0.0;
  return std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0);
}

// Below this |sin|^2 of the angle between two segments the 2x2 system is ill-conditioned and the
// endpoint pairs decide instead (the minimum of parallel segments is attained at an endpoint).
constexpr double kParallelSine2 = 1e-14;

const FaceAngleTable* FaceTable(const TrackedPolyhedron::Tables* tables, int f) {
  return tables == nullptr ? nullptr : tables->face(f);
}

// Endpoints of a vertex (twice the same point) or an edge, in the polyhedron's frame.
std::array<Eigen::Vector3d, 2> Ends(const ConvexPolyhedron& p, FeatureId feature) {
  if (feature.type == FeatureType::kVertex)
    return {p.vertex(feature.index), p.vertex(feature.index)};
  const Edge& e = p.edge(feature.index);
  return {p.vertex(e.vertices[0]), p.vertex(e.vertices[1])};
}

// Keeps the candidate with the smallest squared distance; the first one wins ties.
struct Best {
  FeatureClosest value;
  double distance_squared = std::numeric_limits<double>::infinity();
  void Offer(const FeatureClosest& candidate) {
    const double d2 = (candidate.p_b - candidate.p_a).squaredNorm();
    if (d2 < distance_squared) {
      distance_squared = d2;
      value = candidate;
    }
  }
};

}  // namespace

SegmentClosest ClosestSegmentSegment(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                     const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  // Ericson, "Real-Time Collision Detection" 5.1.9, with a different parallel case.
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm();
  SegmentClosest out;
  if (a == 0.0 || e == 0.0) {
    if (a != 0.0) out.s = ClosestParameterOnSegment(p0, p1, q0);
    if (e != 0.0) out.t = ClosestParameterOnSegment(q0, q1, p0);
  } else {
    const double b = d1.dot(d2), c = d1.dot(r), f = d2.dot(r);
    const double denominator = a * e - b * b;
    if (denominator > kParallelSine2 * a * e) {
      out.s = std::clamp((b * f - c * e) / denominator, 0.0, 1.0);
      out.t = (b * out.s + f) / e;
      if (out.t < 0.0) {
        out.t = 0.0;
        out.s = std::clamp(-c / a, 0.0, 1.0);
      } else if (out.t > 1.0) {
        out.t = 1.0;
        out.s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    } else {
      // Parallel: the best of p0, p1 against [q0, q1] and q0, q1 against [p0, p1].
      double best = std::numeric_limits<double>::infinity();
      auto offer = [&](double s, double t) {
        const double d = ((p0 + s * d1) - (q0 + t * d2)).squaredNorm();
        if (d < best) {
          best = d;
          out.s = s;
          out.t = t;
        }
      };
      offer(0.0, ClosestParameterOnSegment(q0, q1, p0));
      offer(1.0, ClosestParameterOnSegment(q0, q1, p1));
      offer(ClosestParameterOnSegment(p0, p1, q0), 0.0);
      offer(ClosestParameterOnSegment(p0, p1, q1), 1.0);
    }
  }
  out.p = p0 + out.s * d1;
  out.q = q0 + out.t * d2;
  return out;
}

namespace {

// The closest point of face f's boundary to q, for q outside the face's prism; O(n), only while
// the walk moves.
FacePoint ClosestBoundaryPoint(const ConvexPolyhedron& polyhedron, int f,
                               const Eigen::Vector3d& q) {
  const auto loop = polyhedron.FaceVertices(f);
  FacePoint best{polyhedron.vertex(loop[0]), 0};
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Eigen::Vector3d& a = polyhedron.vertex(loop[k]);
    const Eigen::Vector3d& b = polyhedron.vertex(loop[(k + 1) % loop.size()]);
    const Eigen::Vector3d point = a + ClosestParameterOnSegment(a, b, q) * (b - a);
    const double d = (point - q).squaredNorm();
    if (d < best_distance) {
      best_distance = d;
      best = {point, static_cast<int>(k)};
    }
  }
  return best;
}

}  // namespace

FacePoint ClosestPointOnFace(const ConvexPolyhedron& polyhedron, int f, const FaceAngleTable* table,
                             const Eigen::Vector3d& q) {
  if (!IsOverFace(polyhedron, f, table, q)) return ClosestBoundaryPoint(polyhedron, f, q);
  const Plane& plane = polyhedron.face(f).plane;
  const double height = plane.SignedDistance(q);
  return {q - height * plane.normal, -1, height};
}

namespace {

// The zone test of face f against q decided from q's closest point on the face: as InFaceZone
// and FaceMoves (a point on the face plane counts as in front of it).
FaceVerdict VerdictOf(const FacePoint& c) {
  if (c.edge_slot >= 0) return FaceVerdict::kBeside;
  return c.height < 0.0 ? FaceVerdict::kBehind : FaceVerdict::kInZone;
}

}  // namespace

SegmentFaceClosest ClosestSegmentFace(const ConvexPolyhedron& polyhedron, int f,
                                      const FaceAngleTable* table, const Eigen::Vector3d& s0,
                                      const Eigen::Vector3d& s1) {
  if (s0 == s1) {
    const FacePoint on_face = ClosestPointOnFace(polyhedron, f, table, s0);
    return {0.0, s0, on_face.point, on_face.edge_slot};
  }
  // A segment that crosses the face plane over the polygon meets it: distance 0.
  const Plane& plane = polyhedron.face(f).plane;
  const double d0 = plane.SignedDistance(s0), d1 = plane.SignedDistance(s1);
  if (((d0 <= 0.0 && d1 >= 0.0) || (d0 >= 0.0 && d1 <= 0.0)) && d0 != d1) {
    const double s = d0 / (d0 - d1);
    const Eigen::Vector3d crossing = s0 + s * (s1 - s0);
    if (IsOverFace(polyhedron, f, table, crossing)) return {s, crossing, crossing, -1};
  }
  // Both ends over the polygon and on one side of its plane: the whole segment is over it
  // (the prism is convex) and its height is linear along it, so the lower end is closest; no
  // boundary edge can be closer (its points are at least that high above the segment).
  const bool over0 = IsOverFace(polyhedron, f, table, s0);
  const bool over1 = IsOverFace(polyhedron, f, table, s1);
  if (over0 && over1) {
    if (std::abs(d1) < std::abs(d0)) return {1.0, s1, s1 - d1 * plane.normal, -1};
    return {0.0, s0, s0 - d0 * plane.normal, -1};
  }
  // Otherwise an endpoint against the polygon, or the segment against a boundary edge.
  SegmentFaceClosest best;
  double best_distance = std::numeric_limits<double>::infinity();
  auto offer = [&](const SegmentFaceClosest& candidate) {
    const double d = (candidate.on_face - candidate.on_segment).squaredNorm();
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  };
  // An end over the polygon is closest to its projection; an end outside is closest to a point
  // of the boundary, which the boundary edges below already cover.
  const Eigen::Vector3d& normal = plane.normal;
  if (over0) offer({0.0, s0, s0 - d0 * normal, -1});
  if (over1) offer({1.0, s1, s1 - d1 * normal, -1});
  // A closest pair off the polygon's prism has its polygon point on a boundary edge whose side
  // plane the segment point violates (at a vertex, one of its two edges); a plane meets a
  // segment once, so an end violates it too. Edges whose side plane both ends satisfy are
  // never closer (docs/narrow-phase.md#edge-against-face).
  const auto loop = polyhedron.FaceVertices(f);
  const auto sides = polyhedron.FacePlanes(f).subspan(1);
  auto offer_edge = [&](std::size_t k) {
    const SegmentClosest c = ClosestSegmentSegment(s0, s1, polyhedron.vertex(loop[k]),
                                                   polyhedron.vertex(loop[(k + 1) % loop.size()]));
    offer({c.s, c.p, c.q, static_cast<int>(k)});
  };
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Plane& side = sides[k].plane;
    if (side.SignedDistance(s0) < 0.0 || side.SignedDistance(s1) < 0.0) offer_edge(k);
  }
  // An end not over the polygon violates a side plane, so something was offered; only NaN
  // input gets here, and then every edge is offered rather than nothing.
  if (best_distance == std::numeric_limits<double>::infinity()) {
    for (std::size_t k = 0; k < loop.size(); ++k) offer_edge(k);
  }
  return best;
}

void ClosestPointsOfFeatures(const ConvexPolyhedron& a, const TrackedPolyhedron::Tables* tables_a,
                             FeatureId fa, const ConvexPolyhedron& b,
                             const TrackedPolyhedron::Tables* tables_b, FeatureId fb,
                             const PairFrame& frame, FeatureClosest& out) {
  const bool face_a = fa.type == FeatureType::kFace, face_b = fb.type == FeatureType::kFace;
  // Every branch below sets both points and the distance; the rest is per branch.
  out.slot_a = out.slot_b = -1;
  out.verdict_a = out.verdict_b = FaceVerdict::kUnknown;
  const bool vertex_a = fa.type == FeatureType::kVertex, vertex_b = fb.type == FeatureType::kVertex;
  if (vertex_a && (vertex_b || face_b)) {
    // A vertex of A against a vertex or a face of B: one point to transform.
    out.p_a = a.vertex(fa.index);
    if (vertex_b) {
      out.p_b = frame.ToA(b.vertex(fb.index));
    } else {
      const FacePoint c =
          ClosestPointOnFace(b, fb.index, FaceTable(tables_b, fb.index), frame.ToB(out.p_a));
      out.p_b = frame.ToA(c.point);
      out.slot_b = c.edge_slot;
      out.verdict_b = VerdictOf(c);
    }
  } else if (vertex_b) {
    // A's edge or face against B's vertex (the vertex-vertex case is above).
    out.p_b = frame.ToA(b.vertex(fb.index));
    if (face_a) {
      const FacePoint c = ClosestPointOnFace(a, fa.index, FaceTable(tables_a, fa.index), out.p_b);
      out.p_a = c.point;
      out.slot_a = c.edge_slot;
      out.verdict_a = VerdictOf(c);
    } else {
      const auto ea = Ends(a, fa);
      out.p_a = ea[0] + ClosestParameterOnSegment(ea[0], ea[1], out.p_b) * (ea[1] - ea[0]);
    }
  } else if (!face_a && !face_b) {
    // Points and segments: in A's frame.
    const auto ea = Ends(a, fa), eb = Ends(b, fb);
    const SegmentClosest c =
        ClosestSegmentSegment(ea[0], ea[1], frame.ToA(eb[0]), frame.ToA(eb[1]));
    out.p_a = c.p;
    out.p_b = c.q;
  } else if (!face_a) {
    // A's vertex or edge against B's face: in B's frame, so the face is used as stored.
    const auto ea = Ends(a, fa);
    const SegmentFaceClosest c = ClosestSegmentFace(b, fb.index, FaceTable(tables_b, fb.index),
                                                    frame.ToB(ea[0]), frame.ToB(ea[1]));
    out.p_a = ea[0] + c.s * (ea[1] - ea[0]);
    out.p_b = frame.ToA(c.on_face);
    out.slot_b = c.edge_slot;
  } else if (!face_b) {
    const auto eb = Ends(b, fb);
    const Eigen::Vector3d b0 = frame.ToA(eb[0]), b1 = frame.ToA(eb[1]);
    const SegmentFaceClosest c =
        ClosestSegmentFace(a, fa.index, FaceTable(tables_a, fa.index), b0, b1);
    out.p_a = c.on_face;
    out.p_b = c.on_segment;
    out.slot_a = c.edge_slot;
  } else {
    // Face against face: the closest pair has a point on the boundary of one of them (or they
    // meet, and then a boundary edge of one crosses the other).
    Best best;
    const auto loop_a = a.FaceVertices(fa.index);
    for (std::size_t k = 0; k < loop_a.size(); ++k) {
      const Eigen::Vector3d& a0 = a.vertex(loop_a[k]);
      const Eigen::Vector3d& a1 = a.vertex(loop_a[(k + 1) % loop_a.size()]);
      const SegmentFaceClosest c = ClosestSegmentFace(b, fb.index, FaceTable(tables_b, fb.index),
                                                      frame.ToB(a0), frame.ToB(a1));
      best.Offer(
          {a0 + c.s * (a1 - a0), frame.ToA(c.on_face), 0.0, static_cast<int>(k), c.edge_slot});
    }
    const auto loop_b = b.FaceVertices(fb.index);
    for (std::size_t k = 0; k < loop_b.size(); ++k) {
      const Eigen::Vector3d b0 = frame.ToA(b.vertex(loop_b[k]));
      const Eigen::Vector3d b1 = frame.ToA(b.vertex(loop_b[(k + 1) % loop_b.size()]));
      const SegmentFaceClosest c =
          ClosestSegmentFace(a, fa.index, FaceTable(tables_a, fa.index), b0, b1);
      best.Offer({c.on_face, c.on_segment, 0.0, c.edge_slot, static_cast<int>(k)});
    }
    out = best.value;
  }
  out.distance = (out.p_b - out.p_a).norm();
}

}  // namespace sparsedyn::narrow
