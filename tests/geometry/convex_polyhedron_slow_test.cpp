// SPDX-License-Identifier: MIT
// The heavy versions of the geometry oracles (skipped by the sanitizer run): thousands of random
// hulls, Voronoi regions on many of them, and the Archimedean solids against a brute-force hull.
#include <gtest/gtest.h>

#include <numbers>
#include <set>
#include <string>

#include "geometry/polyhedron_checks.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {
namespace {

using ::sparsedyn::testing::Describe;
using ::sparsedyn::testing::IsConsistent;

TEST(RandomHulls, ThousandsAreConsistentManifoldsWithTheRequestedFaceCount) {
  const std::uint64_t seed = 20260611;
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 3000; ++trial) {
    // The thesis's range 24-600 mostly, small counts sometimes; stretched now and then.
    const int faces =
        trial % 5 == 0 ? 4 + static_cast<int>(rng() % 20) : 24 + static_cast<int>(rng() % 577);
    RandomPolyhedronOptions options;
    if (trial % 3 == 0) {
      options.radii =
          Eigen::Vector3d(1 + 4 * testing::Uniform01(rng), 1, 0.2 + testing::Uniform01(rng));
    }
    if (trial % 7 == 0) options.min_separation = 0.0;
    const std::uint64_t shape_seed = seed + static_cast<std::uint64_t>(trial);
    SCOPED_TRACE("trial " + std::to_string(trial) + ": RandomConvexPolyhedron(" +
                 std::to_string(faces) + ", " + std::to_string(shape_seed) + ")");
    const Result<ConvexPolyhedron> p = RandomConvexPolyhedron(faces, shape_seed, options);
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_EQ(p->face_count(), faces);
    ASSERT_TRUE(IsConsistent(*p)) << Describe(*p);
  }
}

TEST(RandomHulls, VoronoiRegionsAgreeWithBruteForce) {
  const std::uint64_t seed = 77;
  for (int trial = 0; trial < 150; ++trial) {
    const int faces = 4 + trial * 4;
    RandomPolyhedronOptions options;
    options.radii = Eigen::Vector3d(1, 1 + (trial % 4), 1);
    const Result<ConvexPolyhedron> p = RandomConvexPolyhedron(faces, seed + trial, options);
    ASSERT_TRUE(p.ok()) << p.error().message;
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + Describe(*p));
    ASSERT_TRUE(testing::VoronoiPlanesAreReciprocal(*p));
    ASSERT_TRUE(testing::VoronoiRegionsAgreeWithBruteForce(*p, seed + trial, 300));
  }
}

TEST(RandomHulls, LargeFaceCountsAreHit) {
  for (int faces : {2000, 4999, 20000}) {
    const Result<ConvexPolyhedron> p = RandomConvexPolyhedron(faces, 1234);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->face_count(), faces);
  }
}

TEST(MassProperties, FineSphereHullApproachesTheBall) {
  // n = 3002 vertices: the cap deficit (~10 / n, see the fast test) is ~3.5e-3 < 5e-3.
  const ConvexPolyhedron ball = *RandomConvexPolyhedron(6000, /*seed=*/11);
  const double volume = 4.0 / 3.0 * std::numbers::pi;
  EXPECT_NEAR(ball.volume(), volume, 5e-3 * volume);
  EXPECT_LT(ball.centroid().norm(), 5e-3);
  const Eigen::Matrix3d expected = 0.4 * ball.volume() * Eigen::Matrix3d::Identity();
  EXPECT_LT((ball.inertia() - expected).norm(), 5e-3 * expected.norm());
}

TEST(ArchimedeanSolids, QhullAgreesWithBruteForceHull) {
  for (int s = 0; s < kArchimedeanSolidCount; ++s) {
    const auto solid = static_cast<ArchimedeanSolid>(s);
    SCOPED_TRACE(std::string(ToString(solid)));
    const std::vector<Eigen::Vector3d> points = SolidVertices(solid);
    const Result<ConvexPolyhedron> hull = ConvexPolyhedron::FromPoints(points);
    const Result<ConvexPolyhedron> reference =
        ConvexPolyhedron::FromMesh(testing::ReferenceHull(points));
    ASSERT_TRUE(hull.ok()) << hull.error().message;
    ASSERT_TRUE(reference.ok()) << reference.error().message;
    const auto face_sets = [](const ConvexPolyhedron& p) {
      std::set<std::set<std::int32_t>> sets;
      for (int f = 0; f < p.face_count(); ++f) {
        sets.emplace(p.FaceVertices(f).begin(), p.FaceVertices(f).end());
      }
      return sets;
    };
    EXPECT_EQ(face_sets(*hull), face_sets(*reference));
    EXPECT_NEAR(hull->volume(), reference->volume(), 1e-12 * hull->volume());
    EXPECT_TRUE(testing::VoronoiRegionsAgreeWithBruteForce(*hull, 5 + s, 500));
  }
}

}  // namespace
}  // namespace sparsedyn
