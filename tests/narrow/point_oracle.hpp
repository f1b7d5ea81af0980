// SPDX-License-Identifier: MIT
// The slow, obviously correct twin of FindClosestFeatureToPoint, in long double: inside (behind
// every face plane) the signed distance is the largest face height; outside it is the distance
// to the nearest face polygon (every face, brute force). And random query points around a
// polyhedron: inside, on and near its vertices, edges and faces, far away.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <random>

#include "narrow_oracles.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/pose.hpp"

namespace sparsedyn::testing {

/// The polyhedron's own frame in long double (placed once, queried many times).
class PointOracle {
 public:
  explicit PointOracle(const ConvexPolyhedron& poly)
      : placed_(Place(poly, LMat::Identity(), LVec::Zero())) {}

  /// Signed distance of the world point p_W from the polyhedron at X_WA (the point taken into
  /// the body frame in long double, so a pose far from the origin costs no precision).
  long double SignedDistance(const Pose& X_WA, const Eigen::Vector3d& p_W) const {
    const LVec q = LongRotation(X_WA.rotation).transpose() *
                   (p_W.cast<long double>() - X_WA.translation.cast<long double>());
    return SignedDistanceInBody(q);
  }

  long double SignedDistanceInBody(const LVec& q) const {
    long double height = -std::numeric_limits<long double>::infinity();
    for (std::size_t f = 0; f < placed_.loops.size(); ++f)
      height = std::max(height, placed_.normals[f].dot(q) - placed_.offsets[f]);
    if (height <= 0) return height;
    long double best = std::numeric_limits<long double>::infinity();
    for (std::size_t f = 0; f < placed_.loops.size(); ++f)
      best = std::min(best, PointFaceDistance2(q, placed_, f));
    return std::sqrt(best);
  }

 private:
  LongPolyhedron placed_;
};

/// Random points (body frame) about a polyhedron of bounding radius R around its centroid:
/// in a ball of 2.5 R (inside and out), on and near a random vertex, edge or face point
/// (offsets along the outward direction of 0, +-1e-12 R, +-1e-6 R, +-0.1 R), and far away.
class PointSampler {
 public:
  explicit PointSampler(std::uint64_t seed) : rng_(seed) {}

  Eigen::Vector3d Next(const ConvexPolyhedron& poly) {
    const double R = poly.bounding_radius();
    const Eigen::Vector3d c = poly.centroid();
    switch (rng_() % 6) {
      case 0:
      case 1:
        return c + 2.5 * R * std::cbrt(Uniform()) * Unit();
      case 2:
        return c + R * (1e3 + 1e3 * Uniform()) * Unit();
      default: {
        Eigen::Vector3d normal;
        const Eigen::Vector3d p = SurfacePoint(poly, normal);
        const double offsets[] = {0.0, 1e-12, -1e-12, 1e-6, -1e-6, 0.1, -0.1, 0.0};
        return p + offsets[rng_() % 8] * R * normal;
      }
    }
  }

  double Uniform() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }
  Eigen::Vector3d Unit() {
    while (true) {
      const Eigen::Vector3d p(2 * Uniform() - 1, 2 * Uniform() - 1, 2 * Uniform() - 1);
      if (p.squaredNorm() > 1e-4 && p.squaredNorm() <= 1.0) return p.normalized();
    }
  }
  std::mt19937_64& rng() { return rng_; }

 private:
  // A vertex, a point of an edge or a point inside a face, with an outward direction there.
  Eigen::Vector3d SurfacePoint(const ConvexPolyhedron& poly, Eigen::Vector3d& normal) {
    const auto pick = [&](int n) { return static_cast<int>(rng_() % static_cast<unsigned>(n)); };
    switch (rng_() % 3) {
      case 0: {
        const int v = pick(poly.vertex_count());
        normal = Eigen::Vector3d::Zero();
        for (const int f : poly.VertexFaces(v)) normal += poly.face(f).plane.normal;
        normal.normalize();
        return poly.vertex(v);
      }
      case 1: {
        const Edge& e = poly.edge(pick(poly.edge_count()));
        normal =
            (poly.face(e.faces[0]).plane.normal + poly.face(e.faces[1]).plane.normal).normalized();
        const double s = rng_() % 4 == 0 ? 0.5 : Uniform();
        return poly.vertex(e.vertices[0]) +
               s * (poly.vertex(e.vertices[1]) - poly.vertex(e.vertices[0]));
      }
      default: {
        const int f = pick(poly.face_count());
        normal = poly.face(f).plane.normal;
        // A random convex combination of the loop's vertices: inside the polygon.
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        double weight = 0.0;
        for (const int v : poly.FaceVertices(f)) {
          const double w = Uniform();
          sum += w * poly.vertex(v);
          weight += w;
        }
        return sum / weight;
      }
    }
  }

  std::mt19937_64 rng_;
};

}  // namespace sparsedyn::testing
