// SPDX-License-Identifier: MIT
// The brute-force cross-check of FindClosestFeatureToPoint shared by the fast and slow tests:
// random hulls (and boxes, prisms, needles, scaled and far-away hulls) at random poses, random
// points about them, the cold walk against the long double oracle and the walk from every
// feature of the hull as a warm start against the cold one.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <memory>

#include "narrow/point_features.hpp"
#include "pair_generator.hpp"
#include "point_oracle.hpp"

namespace sparsedyn::testing {

// Allowed |walk - oracle| x (the hull's bounding diameter + the distance): the pair walk's
// bound (issue #3), widened by the distance for points far from the hull (whose coordinates'
// round-off is that much larger). Measured: 1e-12, where a point 1e-12 from the surface meets
// a face that Qhull merged from facets within 1e-9 x scale of its plane (the walk uses the
// stored plane, the oracle the plane through the vertices).
inline constexpr double kPointErrorBound = 1e-9;

struct PointWalkFigures {
  int hulls = 0, points = 0, inside = 0, walks = 0;
  int brute_force_cold = 0, brute_force_warm = 0;
  double max_relative_error = 0.0;
  long cold_steps = 0, warm_steps = 0;
  int max_cold_steps = 0, max_warm_steps = 0;

  void Print(const char* what) const {
    std::printf(
        "[point walk] %s: %d hulls, %d points (%.1f%% inside), %d walks, max error %.3g x "
        "(diameter + distance), cold steps mean %.2f max %d, warm (every feature) steps mean %.2f "
        "max %d, "
        "brute-force endings cold %d warm %d\n",
        what, hulls, points, 100.0 * inside / std::max(points, 1), walks, max_relative_error,
        static_cast<double>(cold_steps) / std::max(points, 1), max_cold_steps,
        static_cast<double>(warm_steps) / std::max(walks - points, 1), max_warm_steps,
        brute_force_cold, brute_force_warm);
  }
};

// The hull of trial i: mostly random hulls of 4-64 faces, then the degenerate classes.
inline Shape PointWalkHull(int i, std::mt19937_64& rng, bool& grid_points) {
  grid_points = false;
  const auto seed = static_cast<std::uint64_t>(i) + 9000;
  switch (i % 10) {
    case 0:
      return MakeShape("ellipsoidal", *RandomEllipsoidalPolyhedron(
                                          12 + static_cast<int>(rng() % 40), {1, 0.6, 2.5}, seed));
    case 1:
      grid_points = true;  // an axis-aligned box, points on a 1/2 grid: on zone planes
      return MakeShape("box", *MakeBox({1, 1, 1}));
    case 2:
      return MakeShape("prism", *MakePrism(3 + static_cast<int>(rng() % 30), 1.0, 0.5));
    case 3:
      return MakeShape(rng() % 2 ? "needle" : "slab",
                       rng() % 2 ? *MakeNeedle(2.0, 200.0) : *MakeSlab(2.0, 200.0));
    case 4:
      return MakeShape("scaled", RandomConvexPolyhedron(8 + static_cast<int>(rng() % 30), seed)
                                     ->Scaled(rng() % 2 ? 1e-3 : 1e3));
    default:
      return MakeShape("random hull",
                       *RandomConvexPolyhedron(4 + static_cast<int>(rng() % 61), seed));
  }
}

inline PointWalkFigures RunPointWalkCheck(std::uint64_t seed, int hull_count, int points_per_hull) {
  PairGenerator poses(seed);
  PointSampler sampler(seed + 1);
  PointWalkFigures f;
  for (int i = 0; i < hull_count; ++i) {
    bool grid_points = false;
    const Shape shape = PointWalkHull(i, sampler.rng(), grid_points);
    const ConvexPolyhedron& poly = *shape.polyhedron;
    const PointOracle oracle(poly);
    Pose X_WA;
    X_WA.rotation = grid_points ? Eigen::Quaterniond::Identity() : poses.RandomRotation();
    X_WA.translation = poses.RandomUnit() * poly.bounding_radius() * (i % 7 == 6 ? 1e6 : 1.0);
    ++f.hulls;
    const double diameter = 2.0 * poly.bounding_radius();
    for (int k = 0; k < points_per_hull; ++k) {
      Eigen::Vector3d q_B = sampler.Next(poly);
      if (grid_points) {
        for (int axis = 0; axis < 3; ++axis)
          q_B[axis] = 0.5 * static_cast<double>(static_cast<int>(sampler.rng()() % 13) - 6);
      }
      const Eigen::Vector3d p_W = X_WA.ToWorld(q_B);
      SCOPED_TRACE(::testing::Message()
                   << std::setprecision(17) << "seed " << seed << " hull " << i << " ("
                   << shape.name << ") point " << k << " p_W = (" << p_W.transpose() << ")");
      const double reference = static_cast<double>(oracle.SignedDistance(X_WA, p_W));
      const double scale = diameter + std::abs(reference);
      const double bound = kPointErrorBound * scale;
      const PointClosest cold = FindClosestFeatureToPoint(*shape.tracked, X_WA, p_W);
      ++f.points;
      ++f.walks;
      f.inside += reference <= 0.0;
      f.brute_force_cold += cold.brute_force;
      f.cold_steps += cold.steps;
      f.max_cold_steps = std::max(f.max_cold_steps, cold.steps);
      const double error = std::abs(cold.distance - reference);
      f.max_relative_error = std::max(f.max_relative_error, error / scale);
      EXPECT_LE(error, bound) << "walk " << cold.distance << " oracle " << reference;
      // The witness on the surface and on the feature; the point = witness + distance x normal.
      EXPECT_NEAR(SurfaceOffset(poly, X_WA, cold.point), 0.0, bound);
      const Eigen::Vector3d witness_B = X_WA.ToBody(cold.point);
      EXPECT_LE((poly.ClosestPointOnFeature(cold.feature, witness_B) - witness_B).norm(), bound)
          << ToString(cold.feature);
      EXPECT_NEAR(cold.normal.norm(), 1.0, 1e-12);
      EXPECT_LE((cold.point + cold.distance * cold.normal - p_W).norm(), bound);
      // Re-entering from the answer takes no step.
      const PointClosest again = FindClosestFeatureToPoint(*shape.tracked, X_WA, p_W, cold.feature);
      if (cold.distance > bound) {
        EXPECT_EQ(again.steps, 0);
        EXPECT_EQ(again.feature, cold.feature);
      }
      // From every feature as the warm start: the same distance.
      auto warm_from = [&](FeatureId start) {
        const PointClosest warm = FindClosestFeatureToPoint(*shape.tracked, X_WA, p_W, start);
        ++f.walks;
        f.brute_force_warm += warm.brute_force;
        f.warm_steps += warm.steps;
        f.max_warm_steps = std::max(f.max_warm_steps, warm.steps);
        EXPECT_LE(std::abs(warm.distance - cold.distance), bound) << "from " << ToString(start);
      };
      for (int v = 0; v < poly.vertex_count(); ++v) warm_from(FeatureId::Vertex(v));
      for (int e = 0; e < poly.edge_count(); ++e) warm_from(FeatureId::Edge(e));
      for (int g = 0; g < poly.face_count(); ++g) warm_from(FeatureId::Face(g));
    }
  }
  return f;
}

}  // namespace sparsedyn::testing
