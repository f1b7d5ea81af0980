// SPDX-License-Identifier: MIT
// Slow, obviously correct twins of the closest-feature walk, in long double: the signed distance
// of two convex polyhedra by brute force over all feature pairs (disjoint case) and by the
// separating axis test over every face normal and every edge-pair cross product (overlapping
// case, whose largest separation is minus the penetration depth).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::testing {

using LVec = Eigen::Matrix<long double, 3, 1>;
using LMat = Eigen::Matrix<long double, 3, 3>;

// One polyhedron's vertices, faces (loops and outward planes) and edges in a common frame.
struct LongPolyhedron {
  std::vector<LVec> vertices;
  std::vector<std::vector<int>> loops;
  std::vector<LVec> normals;
  std::vector<long double> offsets;
  std::vector<std::array<int, 2>> edges;
};

// `poly` placed by (R, t) in long double.
inline LongPolyhedron Place(const ConvexPolyhedron& poly, const LMat& R, const LVec& t) {
  LongPolyhedron out;
  for (const Eigen::Vector3d& p : poly.vertices())
    out.vertices.push_back(R * p.cast<long double>() + t);
  for (int f = 0; f < poly.face_count(); ++f) {
    const auto loop = poly.FaceVertices(f);
    out.loops.emplace_back(loop.begin(), loop.end());
    // Newell normal of the placed loop, so that the plane is exact to long double.
    LVec n = LVec::Zero();
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const LVec& a = out.vertices[static_cast<std::size_t>(loop[i])];
      const LVec& b = out.vertices[static_cast<std::size_t>(loop[(i + 1) % loop.size()])];
      n += a.cross(b);
    }
    n.normalize();
    long double offset = 0;
    for (const int v : loop) offset += n.dot(out.vertices[static_cast<std::size_t>(v)]);
    out.normals.push_back(n);
    out.offsets.push_back(offset / static_cast<long double>(loop.size()));
  }
  for (const Edge& e : poly.edges()) out.edges.push_back({e.vertices[0], e.vertices[1]});
  return out;
}

inline long double PointSegmentDistance2(const LVec& p, const LVec& a, const LVec& b) {
  const LVec ab = b - a;
  const long double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0L, 1.0L);
  return (a + t * ab - p).squaredNorm();
}

inline long double SegmentSegmentDistance2(const LVec& p0, const LVec& p1, const LVec& q0,
                                           const LVec& q1) {
  const LVec d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const long double a = d1.squaredNorm(), e = d2.squaredNorm(), b = d1.dot(d2);
  const long double c = d1.dot(r), f = d2.dot(r), denominator = a * e - b * b;
  long double best =
      std::min({PointSegmentDistance2(p0, q0, q1), PointSegmentDistance2(p1, q0, q1),
                PointSegmentDistance2(q0, p0, p1), PointSegmentDistance2(q1, p0, p1)});
  if (denominator > 0) {
    const long double s = (b * f - c * e) / denominator, t = (a * f - b * c) / denominator;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
      best = std::min(best, ((p0 + s * d1) - (q0 + t * d2)).squaredNorm());
    }
  }
  return best;
}

inline long double PointFaceDistance2(const LVec& p, const LongPolyhedron& poly, std::size_t f) {
  const auto& loop = poly.loops[f];
  const LVec& n = poly.normals[f];
  const LVec projected = p - (n.dot(p) - poly.offsets[f]) * n;
  bool inside = true;
  long double boundary = std::numeric_limits<long double>::infinity();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const LVec& a = poly.vertices[static_cast<std::size_t>(loop[i])];
    const LVec& b = poly.vertices[static_cast<std::size_t>(loop[(i + 1) % loop.size()])];
    if ((b - a).cross(projected - a).dot(n) < 0) inside = false;
    boundary = std::min(boundary, PointSegmentDistance2(p, a, b));
  }
  return inside ? (p - projected).squaredNorm() : boundary;
}

// Distance between the boundaries: min over vertex-face and edge-edge pairs (every closest pair
// of two disjoint convex polyhedra is one of these, possibly degenerate).
inline long double BoundaryDistance(const LongPolyhedron& a, const LongPolyhedron& b) {
  long double best = std::numeric_limits<long double>::infinity();
  for (const LVec& p : a.vertices) {
    for (std::size_t f = 0; f < b.loops.size(); ++f)
      best = std::min(best, PointFaceDistance2(p, b, f));
  }
  for (const LVec& p : b.vertices) {
    for (std::size_t f = 0; f < a.loops.size(); ++f)
      best = std::min(best, PointFaceDistance2(p, a, f));
  }
  for (const auto& ea : a.edges) {
    for (const auto& eb : b.edges) {
      best = std::min(best, SegmentSegmentDistance2(a.vertices[static_cast<std::size_t>(ea[0])],
                                                    a.vertices[static_cast<std::size_t>(ea[1])],
                                                    b.vertices[static_cast<std::size_t>(eb[0])],
                                                    b.vertices[static_cast<std::size_t>(eb[1])]));
    }
  }
  return std::sqrt(best);
}

// Separation of the projections on a unit axis (positive: a gap).
inline long double AxisSeparation(const LongPolyhedron& a, const LongPolyhedron& b, const LVec& n) {
  long double max_a = -std::numeric_limits<long double>::infinity();
  long double min_b = std::numeric_limits<long double>::infinity();
  for (const LVec& p : a.vertices) max_a = std::max(max_a, n.dot(p));
  for (const LVec& p : b.vertices) min_b = std::min(min_b, n.dot(p));
  return min_b - max_a;
}

// The largest separation over every face normal and every edge-pair cross product, both signs:
// > 0 iff the polyhedra are disjoint; when <= 0 it is minus the penetration depth.
inline long double MaxSeparation(const LongPolyhedron& a, const LongPolyhedron& b) {
  long double best = -std::numeric_limits<long double>::infinity();
  for (const LVec& n : a.normals) best = std::max(best, AxisSeparation(a, b, n));
  for (const LVec& n : b.normals) best = std::max(best, AxisSeparation(a, b, LVec(-n)));
  for (const auto& ea : a.edges) {
    const LVec da =
        a.vertices[static_cast<std::size_t>(ea[1])] - a.vertices[static_cast<std::size_t>(ea[0])];
    for (const auto& eb : b.edges) {
      const LVec db =
          b.vertices[static_cast<std::size_t>(eb[1])] - b.vertices[static_cast<std::size_t>(eb[0])];
      LVec n = da.cross(db);
      if (n.norm() <= 1e-12L * da.norm() * db.norm()) continue;
      n.normalize();
      best = std::max({best, AxisSeparation(a, b, n), AxisSeparation(a, b, LVec(-n))});
    }
  }
  return best;
}

// Face axes only: a cheap certificate of separation when positive.
inline long double MaxFaceSeparation(const LongPolyhedron& a, const LongPolyhedron& b) {
  long double best = -std::numeric_limits<long double>::infinity();
  for (const LVec& n : a.normals) best = std::max(best, AxisSeparation(a, b, n));
  for (const LVec& n : b.normals) best = std::max(best, AxisSeparation(a, b, LVec(-n)));
  return best;
}

inline LMat LongRotation(const Eigen::Quaterniond& q) {
  Eigen::Quaternion<long double> ql = q.cast<long double>();
  ql.normalize();
  return ql.toRotationMatrix();
}

// The signed distance of A at X_WA and B at X_WB, in A's frame (so 1e6 translations cancel
// exactly before anything is rounded): the distance when disjoint, minus the penetration depth
// when they overlap.
inline long double ReferenceSignedDistance(const ConvexPolyhedron& a, const Pose& X_WA,
                                           const ConvexPolyhedron& b, const Pose& X_WB) {
  const LMat R_WA = LongRotation(X_WA.rotation), R_WB = LongRotation(X_WB.rotation);
  const LVec t = R_WA.transpose() *
                 (X_WB.translation.cast<long double>() - X_WA.translation.cast<long double>());
  const LongPolyhedron la = Place(a, LMat::Identity(), LVec::Zero());
  const LongPolyhedron lb = Place(b, R_WA.transpose() * R_WB, t);
  if (MaxFaceSeparation(la, lb) > 0) return BoundaryDistance(la, lb);
  const long double separation = MaxSeparation(la, lb);
  if (separation > 0) return BoundaryDistance(la, lb);
  return separation;
}

// Largest signed distance of world point p_W from A's face planes: ~0 on A's surface.
inline double SurfaceOffset(const ConvexPolyhedron& a, const Pose& X_WA,
                            const Eigen::Vector3d& p_W) {
  const Eigen::Vector3d p = X_WA.ToBody(p_W);
  double best = -std::numeric_limits<double>::infinity();
  for (const Face& f : a.faces()) best = std::max(best, f.plane.SignedDistance(p));
  return best;
}

}  // namespace sparsedyn::testing
