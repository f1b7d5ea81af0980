// SPDX-License-Identifier: MIT
#include "scenes/rotating_pair.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sparsedyn::scenes {
namespace {

// Angles are computed from the step index in double precision: far below this.
constexpr double kAngleTolerance = 1e-9;

// The rotation angle (radians, in [0, pi]) that takes orientation p to orientation q.
double AngleBetween(const Eigen::Quaterniond& p, const Eigen::Quaterniond& q) {
  return p.angularDistance(q);
}

TEST(RotatingPair, LoopLengthClosesSpinAndOrbit) {
  for (const auto& [degrees, steps] : {std::pair{1.0, 3600}, {5.0, 720}, {25.0, 144}}) {
    Result<RotatingPair> pair = MakeRotatingPair({.faces = 8, .degrees_per_step = degrees});
    ASSERT_TRUE(pair) << pair.error().message;
    EXPECT_EQ(pair->X_WA.size(), static_cast<std::size_t>(steps)) << degrees;
  }
}

TEST(RotatingPair, EveryStepIncludingTheWrapSpinsByTheAngleOnTheOrbit) {
  Result<RotatingPair> pair = MakeRotatingPair({.faces = 64, .degrees_per_step = 25.0});
  ASSERT_TRUE(pair) << pair.error().message;
  const std::vector<Pose>& X_WA = pair->X_WA;
  for (std::size_t k = 0; k < X_WA.size(); ++k) {
    const Pose& next = X_WA[(k + 1) % X_WA.size()];
    EXPECT_NEAR(AngleBetween(X_WA[k].rotation, next.rotation), 25.0 * M_PI / 180.0, kAngleTolerance)
        << "step " << k;
    EXPECT_NEAR(X_WA[k].translation.norm(), 2.5, kAngleTolerance) << "step " << k;
  }
}

TEST(RotatingPair, ShapesHaveTheFaceCountUnitRadiusAndDoNotDependOnTheAngle) {
  Result<RotatingPair> slow = MakeRotatingPair({.faces = 1000, .degrees_per_step = 1.0});
  Result<RotatingPair> fast = MakeRotatingPair({.faces = 1000, .degrees_per_step = 25.0});
  ASSERT_TRUE(slow && fast);
  EXPECT_EQ(slow->a->face_count(), 1000);
  EXPECT_EQ(slow->b->face_count(), 1000);
  EXPECT_NEAR(slow->a->bounding_radius(), 1.0, 1e-12);
  EXPECT_NEAR(slow->b->bounding_radius(), 1.0, 1e-12);
  EXPECT_NEAR(slow->a->centroid().norm(), 0.0, 1e-12);
  EXPECT_EQ(slow->a->vertices()[0], fast->a->vertices()[0]);
  EXPECT_NE(slow->a->vertices()[0], slow->b->vertices()[0]);
}

TEST(RotatingPair, RefusesTouchingSpheresAndLoopsThatDoNotClose) {
  EXPECT_FALSE(MakeRotatingPair({.orbit_radius = 2.0}));
  EXPECT_FALSE(MakeRotatingPair({.degrees_per_step = 0.0}));
  EXPECT_FALSE(MakeRotatingPair({.degrees_per_step = 1.0 / 3e3}));
}

}  // namespace
}  // namespace sparsedyn::scenes
