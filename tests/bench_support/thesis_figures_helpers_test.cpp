// SPDX-License-Identifier: MIT
// The helpers of bench/scenes/thesis_figures.cpp: the fits behind §7.2 and App. I.1 and the
// collision matching behind the equal-accuracy search of §7.0.
#include <gtest/gtest.h>

#include <vector>

#include "bench/support/collision_match.hpp"
#include "bench/support/least_squares.hpp"

namespace sparsedyn::bench {
namespace {

// Round-off of a few sums of small numbers.
constexpr double kFitTolerance = 1e-12;

TEST(FitLine, ExactLineHasItsCoefficientsAndRSquaredOne) {
  const LineFit fit = FitLine({1, 2, 3, 4}, {3, 5, 7, 9});
  EXPECT_NEAR(fit.slope, 2, kFitTolerance);
  EXPECT_NEAR(fit.intercept, 1, kFitTolerance);
  EXPECT_NEAR(fit.r2, 1, kFitTolerance);
}

TEST(FitLine, ScatterAboutALineGivesTheKnownLeastSquaresFit) {
  // y = x + (1, -1, -1, 1): the residuals are orthogonal to 1 and x, so the fit is y = x with
  // SS_res = 4; mean y = 1.5, SS_tot = 0.25 + 2.25 + 0.25 + 6.25 = 9.
  const LineFit fit = FitLine({0, 1, 2, 3}, {1, 0, 1, 4});
  EXPECT_NEAR(fit.slope, 1.0, kFitTolerance);
  EXPECT_NEAR(fit.intercept, 0.0, kFitTolerance);
  EXPECT_NEAR(fit.r2, 1 - 4.0 / 9.0, kFitTolerance);
}

TEST(FitProportional, LawThroughTheOriginRecoversItsConstant) {
  // App. I.1's form: y = k D / (1 - D).
  std::vector<double> x, y;
  for (double d : {0.01, 0.05, 0.1, 0.2, 0.3}) {
    x.push_back(d / (1 - d));
    y.push_back(2.1 * x.back());
  }
  const ProportionalFit fit = FitProportional(x, y);
  EXPECT_NEAR(fit.k, 2.1, kFitTolerance);
  EXPECT_NEAR(fit.r2, 1, kFitTolerance);
}

TEST(FitProportional, OffsetDataIsFittedThroughTheOriginNotItsMean) {
  // y = 1 + x on x = 1, 2: k = (1*2 + 2*3) / (1 + 4) = 8/5; fitted 1.6, 3.2 against 2, 3.
  const ProportionalFit fit = FitProportional({1, 2}, {2, 3});
  EXPECT_NEAR(fit.k, 1.6, kFitTolerance);
  EXPECT_NEAR(fit.r2, 1 - (0.16 + 0.04) / 0.5, kFitTolerance);
}

TEST(MatchCollisions, SameCollisionsInAnotherOrderAndSwappedPairsMatch) {
  const std::vector<CollisionRecord> world = {
      PairCollision(0.5, 1, 2), {0.7, 3, 4, true}, PairCollision(0.9, 1, 2)};
  const std::vector<CollisionRecord> stepped = {
      {0.7 + 1e-9, 3, 4, true}, PairCollision(0.9, 2, 1), PairCollision(0.5 - 1e-9, 2, 1)};
  const CollisionMatch match = MatchCollisions(world, stepped, 1e-6);
  EXPECT_TRUE(match.Same());
  EXPECT_EQ(match.matched, 3u);
}

TEST(MatchCollisions, MissedAndSpuriousCollisionsAreCounted) {
  const std::vector<CollisionRecord> world = {PairCollision(0.5, 1, 2), PairCollision(0.6, 3, 4)};
  // The pair 3-4 is missed, the pair 1-2 is found late (another collision), 5 hits a wall.
  const std::vector<CollisionRecord> stepped = {PairCollision(0.8, 1, 2), {0.9, 5, 0, true}};
  const CollisionMatch match = MatchCollisions(world, stepped, 1e-6);
  EXPECT_FALSE(match.Same());
  EXPECT_EQ(match.matched, 0u);
  EXPECT_EQ(match.missing, 2u);
  EXPECT_EQ(match.spurious, 2u);
}

TEST(MatchCollisions, WallAndBodyWithTheSameIndicesAreDifferentCollisions) {
  const CollisionMatch match =
      MatchCollisions({PairCollision(0.5, 1, 2)}, {{0.5, 1, 2, true}}, 1e-6);
  EXPECT_EQ(match.missing, 1u);
  EXPECT_EQ(match.spurious, 1u);
}

TEST(CountEncounters, RepeatedStrikesOfAPairCountOnceAndWallsNotAtAll) {
  // Pair 1-2 strikes at 0.5 and 0.6 (one encounter) and again at 3.0 (a second); pair 3-4 once;
  // a wall collision is no encounter.
  const std::vector<CollisionRecord> collisions = {PairCollision(0.6, 2, 1),
                                                   PairCollision(3.0, 1, 2),
                                                   PairCollision(0.5, 1, 2),
                                                   PairCollision(1.0, 3, 4),
                                                   {0.7, 1, 2, true}};
  EXPECT_EQ(CountEncounters(collisions, /*gap=*/1.0), 3u);
}

}  // namespace
}  // namespace sparsedyn::bench
