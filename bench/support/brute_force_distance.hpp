// SPDX-License-Identifier: MIT
// An obviously correct (and slow) distance between two separated convex polyhedra, for the
// agreement checks of the closest-feature benchmarks: it does not depend on any walk or GJK.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::bench {

/// Distance between segments [p0, p1] and [q0, q1]: minimise |p0 + s d1 - q0 - t d2| over
/// [0, 1]^2. The unconstrained minimum in s (with t eliminated) is clamped, t follows from s and
/// is clamped, and s is recomputed for a clamped t; this visits the minimiser of the convex
/// quadratic on the square.
inline double SegmentDistance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                              const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.dot(d1), e = d2.dot(d2), b = d1.dot(d2), c = d1.dot(r), f = d2.dot(r);
  const double denominator = a * e - b * b;  // >= 0; 0 for parallel segments
  double s = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return (p0 + s * d1 - q0 - t * d2).norm();
}

/// The distance from point p_W to the faces of `polyhedron` whose polygon contains p_W's
/// projection (infinity if none does); vertices_W are its vertices in the world frame.
inline double PointFaceDistance(const ConvexPolyhedron& polyhedron,
                                const std::vector<Eigen::Vector3d>& vertices_W,
                                const Eigen::Quaterniond& R_WB, const Eigen::Vector3d& p_W) {
  double best = std::numeric_limits<double>::infinity();
  for (int f = 0; f < polyhedron.face_count(); ++f) {
    const Eigen::Vector3d n_W = R_WB * polyhedron.face(f).plane.normal;
    const auto loop = polyhedron.FaceVertices(f);
    // Inside the counter-clockwise loop: left of (or on) every boundary edge seen along n_W.
    bool inside = true;
    for (std::size_t i = 0; i < loop.size() && inside; ++i) {
      const Eigen::Vector3d& u = vertices_W[static_cast<std::size_t>(loop[i])];
      const Eigen::Vector3d& v = vertices_W[static_cast<std::size_t>(loop[(i + 1) % loop.size()])];
      inside = (v - u).cross(p_W - u).dot(n_W) >= 0;
    }
    if (inside) {
      const Eigen::Vector3d& u = vertices_W[static_cast<std::size_t>(loop[0])];
      best = std::min(best, std::abs(n_W.dot(p_W - u)));
    }
  }
  return best;
}

/// Distance between separated convex polyhedra A at X_WA and B at X_WB: the closest pair of
/// points lies on a vertex-face, face-vertex or edge-edge pair (a vertex-vertex or vertex-edge
/// pair is also an edge-edge pair), so the minimum over those pairs is exact. O(V F + E^2).
inline double BruteForceDistance(const ConvexPolyhedron& a, const Pose& X_WA,
                                 const ConvexPolyhedron& b, const Pose& X_WB) {
  std::vector<Eigen::Vector3d> a_W, b_W;
  for (const Eigen::Vector3d& p : a.vertices()) a_W.push_back(X_WA.ToWorld(p));
  for (const Eigen::Vector3d& p : b.vertices()) b_W.push_back(X_WB.ToWorld(p));
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : a_W)
    best = std::min(best, PointFaceDistance(b, b_W, X_WB.rotation, p));
  for (const Eigen::Vector3d& p : b_W)
    best = std::min(best, PointFaceDistance(a, a_W, X_WA.rotation, p));
  for (const Edge& ea : a.edges()) {
    const Eigen::Vector3d& p0 = a_W[static_cast<std::size_t>(ea.vertices[0])];
    const Eigen::Vector3d& p1 = a_W[static_cast<std::size_t>(ea.vertices[1])];
    for (const Edge& eb : b.edges()) {
      best = std::min(best, SegmentDistance(p0, p1, b_W[static_cast<std::size_t>(eb.vertices[0])],
                                            b_W[static_cast<std::size_t>(eb.vertices[1])]));
    }
  }
  return best;
}

}  // namespace sparsedyn::bench
