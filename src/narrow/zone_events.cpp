// SPDX-License-Identifier: MIT
#include "narrow/zone_events.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "math/roots.hpp"
#include "narrow/poly_vec3.hpp"

namespace sparsedyn::narrow {
namespace {

// sin^2 of the angle below which two edges count as parallel: their cross product no longer
// fixes a normal (the walk's own parallel threshold, docs/narrow-phase.md "Tie rules").
constexpr double kParallelSin2 = 1e-14;

double SegmentDistance(const Vec3& p, const Vec3& e0, const Vec3& e1) {
  const Vec3 u = e1 - e0;
  const double s = std::clamp((p - e0).dot(u) / u.squaredNorm(), 0.0, 1.0);
  return (e0 + s * u - p).norm();
}

// The lowest-dimensional part of feature f that holds its witness p (body frame) within eps: a
// face or edge whose witness sits on its boundary becomes the vertex or edge there. Parallel
// pairs (face-face, edge-face, parallel edges) have a whole patch of closest points; the walk
// reports one on a boundary, and the pair reduced there has unique, polynomial witnesses.
FeatureId Reduce(const ConvexPolyhedron& poly, FeatureId f, const Vec3& p, double eps) {
  if (f.type == FeatureType::kEdge) {
    for (const int v : poly.edge(f.index).vertices) {
      if ((poly.vertex(v) - p).norm() <= eps) return FeatureId::Vertex(v);
    }
  } else if (f.type == FeatureType::kFace) {
    for (const int v : poly.FaceVertices(f.index)) {
      if ((poly.vertex(v) - p).norm() <= eps) return FeatureId::Vertex(v);
    }
    for (const int e : poly.FaceEdges(f.index)) {
      const Edge& edge = poly.edge(e);
      if (SegmentDistance(p, poly.vertex(edge.vertices[0]), poly.vertex(edge.vertices[1])) <= eps)
        return FeatureId::Edge(e);
    }
  }
  return f;
}

Vec3 EdgeVector(const ConvexPolyhedron& poly, int e) {
  const Edge& edge = poly.edge(e);
  return poly.vertex(edge.vertices[1]) - poly.vertex(edge.vertices[0]);
}
const Vec3& EdgeStart(const ConvexPolyhedron& poly, int e) {
  return poly.vertex(poly.edge(e).vertices[0]);
}

bool Parallel(const Vec3& u, const Vec3& w) {
  return u.cross(w).squaredNorm() < kParallelSin2 * u.squaredNorm() * w.squaredNorm();
}

// The pair's witnesses as polynomials in dt (A's frame), and its gap: a polynomial that is <= 0
// exactly when the pair's distance is <= the tolerance.
struct Witnesses {
  PolyVec3 on_a, on_b;
  Polynomial gap;
};

// Closest point to `target` on the line origin + s u: origin + u (u . (target - origin)) / |u|^2.
PolyVec3 LinePoint(const PolyVec3& origin, const Vec3& u, const PolyVec3& target) {
  return origin + PolyVec3::Along(u, Dot(u, target - origin) * (1.0 / u.squaredNorm()));
}

Polynomial SquaredGap(const PolyVec3& on_a, const PolyVec3& on_b, double tolerance) {
  return SquaredNorm(on_b - on_a) - Polynomial{tolerance * tolerance};
}

std::optional<Witnesses> BuildWitnesses(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                        const RelativeTranslation& m, FeaturePair pair,
                                        double tolerance) {
  const PolyVec3 p_AB = PolyVec3::Motion(m.p, m.v, m.a);
  auto b_point = [&](const Vec3& x_B) { return p_AB + PolyVec3::Constant(m.R_AB * x_B); };
  const FeatureType ta = pair.a.type, tb = pair.b.type;
  const int ia = pair.a.index, ib = pair.b.index;
  Witnesses w;
  if (ta == FeatureType::kVertex && tb == FeatureType::kVertex) {
    w.on_a = PolyVec3::Constant(a.vertex(ia));
    w.on_b = b_point(b.vertex(ib));
    w.gap = SquaredGap(w.on_a, w.on_b, tolerance);
  } else if (ta == FeatureType::kVertex && tb == FeatureType::kEdge) {
    w.on_a = PolyVec3::Constant(a.vertex(ia));
    w.on_b = LinePoint(b_point(EdgeStart(b, ib)), m.R_AB * EdgeVector(b, ib), w.on_a);
    w.gap = SquaredGap(w.on_a, w.on_b, tolerance);
  } else if (ta == FeatureType::kEdge && tb == FeatureType::kVertex) {
    w.on_b = b_point(b.vertex(ib));
    w.on_a = LinePoint(PolyVec3::Constant(EdgeStart(a, ia)), EdgeVector(a, ia), w.on_b);
    w.gap = SquaredGap(w.on_a, w.on_b, tolerance);
  } else if (ta == FeatureType::kVertex && tb == FeatureType::kFace) {
    // Height of A's vertex over B's face plane n_B . x_B = d_B, with x_B = R_AB^T (x - p_AB).
    const Vec3 n = m.R_AB * b.face(ib).plane.normal;
    w.on_a = PolyVec3::Constant(a.vertex(ia));
    const Polynomial height = Dot(n, w.on_a - p_AB) - Polynomial{b.face(ib).plane.offset};
    w.on_b = w.on_a - PolyVec3::Along(n, height);
    w.gap = height - Polynomial{tolerance};
  } else if (ta == FeatureType::kFace && tb == FeatureType::kVertex) {
    const Plane& plane = a.face(ia).plane;
    w.on_b = b_point(b.vertex(ib));
    const Polynomial height = Dot(plane.normal, w.on_b) - Polynomial{plane.offset};
    w.on_a = w.on_b - PolyVec3::Along(plane.normal, height);
    w.gap = height - Polynomial{tolerance};
  } else if (ta == FeatureType::kEdge && tb == FeatureType::kEdge) {
    const Vec3 ua = EdgeVector(a, ia), ub = m.R_AB * EdgeVector(b, ib);
    if (Parallel(ua, ub)) return std::nullopt;
    // Closest points of two lines (Ericson 5.1.8): both parameters are linear in the offset
    // w = A0 - B0(dt), hence polynomials of the same degree as the motion.
    const PolyVec3 a0 = PolyVec3::Constant(EdgeStart(a, ia));
    const PolyVec3 b0 = b_point(EdgeStart(b, ib));
    const PolyVec3 offset = a0 - b0;
    const double aa = ua.dot(ua), ab = ua.dot(ub), bb = ub.dot(ub);
    const double inv_det = 1.0 / (aa * bb - ab * ab);
    const Polynomial d = Dot(ua, offset), e = Dot(ub, offset);
    w.on_a = a0 + PolyVec3::Along(ua, (ab * e - bb * d) * inv_det);
    w.on_b = b0 + PolyVec3::Along(ub, (aa * e - ab * d) * inv_det);
    // The lines' separation along their common normal is linear-algebraically exact and better
    // conditioned than |on_b - on_a|: orient the normal from A to B at dt = 0.
    Vec3 n = ua.cross(ub).normalized();
    const Polynomial along = Dot(n, b0 - a0);
    w.gap = (along(0.0) < 0.0 ? -along : along) - Polynomial{tolerance};
  } else {
    return std::nullopt;
  }
  return w;
}

// True when p (degree <= 2) certainly stays positive on [0, limit]: its constant term beats
// every term that could pull it down, with a margin for the rounding of this very test. Saves
// the certified root isolation for the many zone planes that the witness is nowhere near.
bool StaysPositive(const Polynomial& p, double limit) {
  const double c0 = p.Coefficient(0), c1 = p.Coefficient(1) * limit,
               c2 = p.Coefficient(2) * limit * limit;
  const double low = c0 + std::min(c1, 0.0) + std::min(c2, 0.0);
  return p.Degree() <= 2 && low > 1e-12 * (std::abs(c0) + std::abs(c1) + std::abs(c2));
}

// The earliest dt in [0, limit) at which witness w leaves the zone of feature f of `poly`, whose
// planes map into A's frame by x -> R x (+ shift, already folded into w); `next` gets the pair
// across the plane (the neighbour replaces the feature on this side). Returns limit if none.
double EarliestExit(const ConvexPolyhedron& poly, FeatureId f, const Eigen::Matrix3d& R,
                    const PolyVec3& w, double slack, double limit, bool side_a, FeaturePair& next) {
  double best = limit;
  for (const VoronoiPlane& vp : poly.VoronoiPlanes(f)) {
    // A face's own plane bounds the zone towards the interior: crossing it is contact, which
    // the gap polynomial finds first (tolerance > 0).
    if (vp.neighbor.type == FeatureType::kNone) continue;
    const Polynomial g = Dot(R * vp.plane.normal, w) - Polynomial{vp.plane.offset - slack};
    if (g(0.0) < 0.0) {  // already outside by more than the slack
      best = 0.0;
      (side_a ? next.a : next.b) = vp.neighbor;
      break;
    }
    if (StaysPositive(g, best)) continue;
    const std::optional<double> root = EarliestRoot(g, 0.0, best);
    if (root && *root < best) {
      best = *root;
      (side_a ? next.a : next.b) = vp.neighbor;
    }
  }
  return best;
}

}  // namespace

ZoneEvent NextZoneEvent(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                        const RelativeTranslation& motion, FeaturePair pair, const Vec3& point_a_A,
                        const Vec3& point_b_A, double tolerance, double horizon, double slack) {
  ZoneEvent event;
  // Pairs of a face with a face or edge, and parallel edges, are reduced to where the walk put
  // the witnesses.
  const bool has_face = pair.a.type == FeatureType::kFace || pair.b.type == FeatureType::kFace;
  const bool has_edge = pair.a.type == FeatureType::kEdge || pair.b.type == FeatureType::kEdge;
  const bool both_faces = pair.a.type == FeatureType::kFace && pair.b.type == FeatureType::kFace;
  if ((has_face && has_edge) || both_faces ||
      (pair.a.type == FeatureType::kEdge && pair.b.type == FeatureType::kEdge &&
       Parallel(EdgeVector(a, pair.a.index), motion.R_AB * EdgeVector(b, pair.b.index)))) {
    const Vec3 point_b_B = motion.R_AB.transpose() * (point_b_A - motion.p);
    pair.a = Reduce(a, pair.a, point_a_A, slack);
    pair.b = Reduce(b, pair.b, point_b_B, slack);
  }
  const std::optional<Witnesses> w = BuildWitnesses(a, b, motion, pair, tolerance);
  if (!w) return event;

  // The zone exits: B's witness against A's zone planes, A's witness against B's (in A's frame,
  // B's planes turn by R_AB and move with p_AB).
  event.next = pair;
  const PolyVec3 p_AB = PolyVec3::Motion(motion.p, motion.v, motion.a);
  double exit = EarliestExit(a, pair.a, Eigen::Matrix3d::Identity(), w->on_b, slack, horizon,
                             /*side_a=*/true, event.next);
  if (exit > 0.0) {
    FeaturePair next_b = pair;
    const double exit_b = EarliestExit(b, pair.b, motion.R_AB, w->on_a - p_AB, slack, exit,
                                       /*side_a=*/false, next_b);
    if (exit_b < exit) {
      exit = exit_b;
      event.next = next_b;
    }
  }

  // The pair's distance reaches the tolerance before it stops being closest: contact.
  if (const std::optional<double> contact = EarliestRoot(w->gap, 0.0, exit)) {
    event.kind = ZoneEvent::Kind::kContact;
    event.dt = *contact;
  } else if (exit <= 0.0) {
    event.kind = ZoneEvent::Kind::kUnsupported;
    event.stalled = true;
  } else if (exit < horizon) {
    event.kind = ZoneEvent::Kind::kExit;
    event.dt = exit;
  } else {
    event.kind = ZoneEvent::Kind::kNone;
    event.dt = horizon;
  }
  return event;
}

}  // namespace sparsedyn::narrow
