// SPDX-License-Identifier: MIT
// The sphere-polyhedron cross-checks of sphere_polyhedron_test.cpp on larger samples, and at
// the World's tolerance scale (1e-8 here against 1e-4 there).
#include <gtest/gtest.h>

#include "point_walk_check.hpp"
#include "sphere_toi_check.hpp"

namespace sparsedyn {
namespace {

using testing::Still;

TEST(PointWalkSlow, ThreeThousandHullsFromEveryWarmStart) {
  const testing::PointWalkFigures f =
      testing::RunPointWalkCheck(/*seed=*/20261230, /*hull_count=*/3000, /*points_per_hull=*/6);
  f.Print("slow");
  EXPECT_LE(f.max_relative_error, testing::kPointErrorBound);
  EXPECT_EQ(f.brute_force_cold, 0);
}

TEST(SphereContactSlow, TranslatingAndStaticPairsMatchTheOracleExactly) {
  for (const Still still : {Still::kNeither, Still::kPolyhedron, Still::kSphere}) {
    const testing::ToiFigures f = testing::RunSphereCheck(
        20261231 + static_cast<std::uint64_t>(still), 5000, 0.0, /*accelerate=*/true, still);
    testing::ExpectNoErrors(f,
                            still == Still::kNeither      ? "slow sphere, translating"
                            : still == Still::kPolyhedron ? "slow sphere, static polyhedron"
                                                          : "slow static sphere, translating",
                            /*exact=*/true);
  }
}

TEST(SphereContactSlow, RotatingPolyhedraAreNeverLate) {
  const testing::ToiFigures f =
      testing::RunSphereCheck(20261234, 5000, /*spin=*/10.0, /*accelerate=*/true, Still::kNeither);
  testing::ExpectNoErrors(f, "slow sphere, rotating", /*exact=*/false);
}

TEST(SphereContactSlow, TinyToleranceKeepsTheGuarantees) {
  const testing::ToiFigures f =
      testing::RunSphereCheck(20261235, 3000, 0.0, true, Still::kNeither, /*tolerance=*/1e-8);
  testing::ExpectNoErrors(f, "tol 1e-8 sphere, translating", /*exact=*/true);
  const testing::ToiFigures r =
      testing::RunSphereCheck(20261236, 2000, 10.0, true, Still::kNeither, /*tolerance=*/1e-8);
  testing::ExpectNoErrors(r, "tol 1e-8 sphere, rotating", /*exact=*/false);
}

}  // namespace
}  // namespace sparsedyn
