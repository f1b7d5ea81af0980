// SPDX-License-Identifier: MIT
// PointBoxTree against the loop it replaces: every point above a plane is visited, on random
// clouds (not convex) and on a convex polyhedron's vertices, for fixed and rising thresholds.
#include "geometry/point_box_tree.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

namespace sparsedyn {
namespace {

std::vector<Vec3> Cloud(std::mt19937_64& rng, int n) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) points.emplace_back(normal(rng), normal(rng), 3 * normal(rng));
  return points;
}

TEST(PointBoxTree, VisitsEveryPointAboveAFixedThreshold) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const int n : {1, 5, 9, 100, 2000}) {
    const std::vector<Vec3> points = Cloud(rng, n);
    const PointBoxTree tree(points);
    for (int q = 0; q < 50; ++q) {
      const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
      const double offset = normal(rng), threshold = 0.5 * normal(rng);
      std::set<std::uint32_t> expected, visited;
      for (std::uint32_t v = 0; v < points.size(); ++v) {
        if (direction.dot(points[v]) - offset >= threshold) expected.insert(v);
      }
      tree.ForEachAbove(
          direction, offset, [&] { return threshold; },
          [&](std::uint32_t v, double above) {
            EXPECT_EQ(above, direction.dot(points[v]) - offset);
            if (above >= threshold) visited.insert(v);
          });
      EXPECT_EQ(visited, expected) << n << " points, query " << q;
    }
  }
}

TEST(PointBoxTree, ARisingThresholdStillFindsTheHighestPoint) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  const std::vector<Vec3> points = Cloud(rng, 5000);
  const PointBoxTree tree(points);
  for (int q = 0; q < 100; ++q) {
    const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    double best = -1e300, expected = -1e300;
    std::size_t visits = 0;
    for (const Vec3& p : points) expected = std::max(expected, direction.dot(p));
    tree.ForEachAbove(
        direction, 0.0, [&] { return best; },
        [&](std::uint32_t, double above) {
          ++visits;
          best = std::max(best, above);
        });
    EXPECT_EQ(best, expected) << q;
    EXPECT_LT(visits, points.size() / 4) << q;  // the boxes below the best are not opened
  }
}

TEST(PointBoxTree, NoPointsNoVisits) {
  const std::vector<Vec3> none;
  const PointBoxTree tree(none);
  int visits = 0;
  tree.ForEachAbove(
      Vec3::UnitX(), 0.0, [] { return -1e300; }, [&](std::uint32_t, double) { ++visits; });
  EXPECT_EQ(visits, 0);
}

}  // namespace
}  // namespace sparsedyn
