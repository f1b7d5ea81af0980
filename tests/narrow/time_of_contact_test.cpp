// SPDX-License-Identifier: MIT
// Contact prediction (src/narrow/time_of_contact.hpp): exact cases, degenerate cases, and the
// oracle cross-check on a few thousand random cases (more in time_of_contact_slow_test.cpp).
#include "narrow/time_of_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "toi_check.hpp"

namespace sparsedyn {
namespace {

using Kind = ContactPrediction::Kind;
using testing::kToiTolerance;

// Exact cases are solved to round-off: 1e-12 s on times of order 1 s.
constexpr double kExact = 1e-12;

struct Cubes {
  testing::Shape cube = testing::MakeShape("cube", *MakeBox({0.5, 0.5, 0.5}));
};

RigidPath At(const Vec3& p, const Vec3& v = Vec3::Zero(),
             const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  RigidPath path;
  path.centre.p0 = p;
  path.centre.v0 = v;
  path.q0 = q;
  return path;
}

ContactPredictionOptions Options(int max_iterations = 64) {
  ContactPredictionOptions options;
  options.tolerance = kToiTolerance;
  options.max_iterations = max_iterations;
  return options;
}

ContactPrediction Predict(const testing::Shape& a, const RigidPath& path_a, const testing::Shape& b,
                          const RigidPath& path_b, double t_end,
                          const ContactPredictionOptions& options = Options()) {
  return PredictContact(*a.tracked, path_a, *b.tracked, path_b, 0.0, t_end, std::nullopt, options);
}

TEST(TimeOfContact, ParallelFacesApproachingFlushMeetAtGapOverSpeed) {
  Cubes s;
  const Eigen::Quaterniond common(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  // Face to face, offset sideways by 0.3: the closest points form a whole patch.
  const ContactPrediction p =
      Predict(s.cube, At(Vec3::Zero(), Vec3::Zero(), common), s.cube,
              At(common * Vec3(2.0, 0.3, 0.0), common * Vec3(-1, 0, 0), common), 5.0);
  ASSERT_EQ(p.kind, Kind::kContact);
  EXPECT_NEAR(p.time, 1.0 - kToiTolerance, kExact);
  EXPECT_EQ(p.advancement_steps, 0) << "reduced to a vertex-face pair, solved exactly";
}

TEST(TimeOfContact, ParallelEdgesMeetAtGapOverSpeed) {
  Cubes s;
  // Both turned 45 degrees about z: their vertical edges face each other, parallel.
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()));
  const ContactPrediction p = Predict(s.cube, At(Vec3::Zero(), Vec3::Zero(), turn), s.cube,
                                      At(Vec3(3.0, 0.0, 0.2), Vec3(-2.0, 0.0, 0.0), turn), 5.0);
  ASSERT_EQ(p.kind, Kind::kContact);
  EXPECT_NEAR(p.time, (3.0 - std::sqrt(2.0) - kToiTolerance) / 2.0, kExact);
  EXPECT_EQ(p.advancement_steps, 0) << "reduced to a vertex-edge pair, solved exactly";
}

TEST(TimeOfContact, FallingCubeMeetsAtTheQuadraticRoot) {
  Cubes s;
  RigidPath falling = At(Vec3(0.2, -0.1, 2.5), Vec3(0.3, 0.0, 0.0));
  falling.centre.a = Vec3(0.0, 0.0, -9.81);
  const ContactPrediction p = Predict(s.cube, At(Vec3::Zero()), s.cube, falling, 5.0);
  ASSERT_EQ(p.kind, Kind::kContact);
  EXPECT_NEAR(p.time, std::sqrt(2.0 * (1.5 - kToiTolerance) / 9.81), kExact);
}

TEST(TimeOfContact, GrazingPassThatMissesBy1e7IsNone) {
  Cubes s;
  const double gap = kToiTolerance + 1e-7;
  // Face sliding past face, then a cube turned 45 degrees about x sliding an edge past a face.
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()));
  const double edge_height = 0.5 + 0.5 * std::sqrt(2.0) + gap;
  for (const auto& [q, height] :
       {std::pair{Eigen::Quaterniond::Identity(), 1.0 + gap}, std::pair{turn, edge_height}}) {
    const ContactPrediction p = Predict(s.cube, At(Vec3::Zero()), s.cube,
                                        At(Vec3(-3.0, height, 0.1), Vec3(1, 0, 0), q), 6.0);
    EXPECT_EQ(p.kind, Kind::kNone) << "at " << p.time << " distance " << p.features.distance;
    EXPECT_EQ(p.time, 6.0);
  }
}

TEST(TimeOfContact, RotatingGrazingPassThatMissesIsNoneAndAHitIsFound) {
  Cubes s;
  // B spins slowly about the axis through its centre parallel to the gap's normal, so its
  // distance to A never changes while it slides past: gap tol + 1e-7 misses, tol - 1e-7 hits.
  for (const double extra : {1e-7, -1e-7}) {
    RigidPath b = At(Vec3(-3.0, 1.0 + kToiTolerance + extra, 0.1), Vec3(1, 0, 0));
    b.omega = Vec3(0.0, 0.5, 0.0);
    const ContactPrediction p = Predict(s.cube, At(Vec3::Zero()), s.cube, b, 6.0);
    EXPECT_EQ(p.kind, extra > 0 ? Kind::kNone : Kind::kContact) << "extra " << extra;
  }
}

TEST(TimeOfContact, AlreadyInContactOrPenetratingReturnsTheBeginTime) {
  Cubes s;
  for (const double gap : {0.5 * kToiTolerance, 0.0, -0.1}) {
    for (const double spin : {0.0, 3.0}) {
      RigidPath b = At(Vec3(1.0 + gap, 0.2, 0.0), Vec3(1, 0, 0));  // even when moving apart
      b.omega = Vec3(0.0, 0.0, spin);
      b.centre.t0 = 0.25;
      const ContactPrediction p = PredictContact(*s.cube.tracked, At(Vec3::Zero()), *s.cube.tracked,
                                                 b, 0.25, 2.0, std::nullopt, Options());
      EXPECT_EQ(p.kind, Kind::kContact) << "gap " << gap << " spin " << spin;
      EXPECT_EQ(p.time, 0.25);
      EXPECT_EQ(p.iterations, 0);
    }
  }
}

TEST(TimeOfContact, ZeroRelativeVelocityOrSeparatingIsNone) {
  Cubes s;
  const Vec3 v(0.3, -2.0, 1.0);
  const ContactPrediction same =
      Predict(s.cube, At(Vec3::Zero(), v), s.cube, At(Vec3(1.5, 0.4, 0.0), v), 10.0);
  EXPECT_EQ(same.kind, Kind::kNone);
  EXPECT_EQ(same.time, 10.0);
  // Spinning slowly but flying apart fast: the advancement bound's speed is negative at once.
  RigidPath b = At(Vec3(1.5, 0.0, 0.0), Vec3(5.0, 0.0, 0.0));
  b.omega = Vec3(0.0, 0.0, 1.0);
  const ContactPrediction apart = Predict(s.cube, At(Vec3::Zero()), s.cube, b, 10.0);
  EXPECT_EQ(apart.kind, Kind::kNone);
  EXPECT_EQ(apart.iterations, 1);
}

TEST(TimeOfContact, AnOpenEndedIntervalFindsContactOrReportsNoneAtInfinity) {
  Cubes s;
  const double inf = std::numeric_limits<double>::infinity();
  for (const double spin : {0.0, 2.0}) {
    for (const double speed : {-1.0, 1.0}) {  // approaching, separating
      RigidPath b = At(Vec3(3.0, 0.2, 0.0), Vec3(speed, 0.0, 0.0));
      b.omega = Vec3(0.0, 0.0, spin);
      const ContactPrediction p = PredictContact(*s.cube.tracked, At(Vec3::Zero()), *s.cube.tracked,
                                                 b, 0.0, inf, std::nullopt, Options());
      SCOPED_TRACE("spin " + std::to_string(spin) + " speed " + std::to_string(speed));
      if (speed < 0) {
        EXPECT_EQ(p.kind, Kind::kContact);
        EXPECT_LE(p.time, 2.0 - kToiTolerance + kExact);
        EXPECT_GT(p.time, 1.0);
      } else {
        EXPECT_EQ(p.kind, Kind::kNone);
        EXPECT_EQ(p.time, inf);
      }
      // The wall x = -1, allowed side x >= -1: approached when speed < 0.
      const WallContactPrediction w =
          PredictWallContact(*s.cube.tracked, b, Vec3::UnitX(), -1.0, 0.0, inf, kToiTolerance);
      EXPECT_EQ(w.kind, speed < 0 ? Kind::kContact : Kind::kNone);
      EXPECT_EQ(w.time == inf, speed > 0);
    }
  }
}

TEST(TimeOfContact, CheckpointsResumeToTheSameAnswer) {
  testing::MotionCaseGenerator generator(/*seed=*/20261122);
  int checkpointed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const testing::MotionCase c = generator.Pair(trial % 2 ? 10.0 : 0.0, trial % 4 == 0);
    SCOPED_TRACE(c.Describe());
    ContactPredictionOptions options = Options(1000000);
    const testing::Resumed whole = testing::PredictResuming(c, options);
    options.max_iterations = 1;
    const testing::Resumed pieces = testing::PredictResuming(c, options);
    checkpointed += pieces.checkpoints > 0;
    EXPECT_EQ(whole.checkpoints, 0);
    EXPECT_EQ(pieces.last.kind, whole.last.kind);
    EXPECT_EQ(pieces.last.time, whole.last.time);
    EXPECT_EQ(pieces.iterations, whole.iterations);
  }
  EXPECT_GT(checkpointed, 100);
}

TEST(TimeOfContact, TranslatingPairsMatchTheOracleExactly) {
  const testing::ToiFigures f =
      testing::RunPairCheck(/*seed=*/20261101, 2000, /*spin=*/0.0, /*accelerate=*/true);
  testing::ExpectNoErrors(f, "translating pairs", /*exact=*/true);
  EXPECT_GT(f.oracle_contacts, 600);
  EXPECT_LT(f.oracle_contacts, 1400);
}

TEST(TimeOfContact, AlignedBoxesWithParallelFacesAndEdgesMatchTheOracleExactly) {
  const testing::ToiFigures f = testing::RunPairCheck(/*seed=*/20261105, 1000, /*spin=*/0.0,
                                                      /*accelerate=*/false, /*aligned=*/true);
  testing::ExpectNoErrors(f, "aligned translating pairs", /*exact=*/true);
  EXPECT_GT(f.oracle_contacts, 300);
  EXPECT_LT(f.oracle_contacts, 900);
}

TEST(TimeOfContact, RotatingPairsAreNeverLate) {
  const testing::ToiFigures f =
      testing::RunPairCheck(/*seed=*/20261102, 2000, /*spin=*/10.0, /*accelerate=*/true);
  testing::ExpectNoErrors(f, "rotating pairs", /*exact=*/false);
  EXPECT_GT(f.oracle_contacts, 600);
  EXPECT_LT(f.oracle_contacts, 1400);
}

TEST(TimeOfContact, WallsMatchTheOracle) {
  const testing::ToiFigures still =
      testing::RunWallCheck(/*seed=*/20261103, 1000, /*spin=*/0.0, /*accelerate=*/true);
  testing::ExpectNoErrors(still, "translating walls", /*exact=*/true);
  const testing::ToiFigures spinning =
      testing::RunWallCheck(/*seed=*/20261104, 1000, /*spin=*/10.0, /*accelerate=*/true);
  testing::ExpectNoErrors(spinning, "rotating walls", /*exact=*/false);
  for (const testing::ToiFigures* f : {&still, &spinning}) {
    EXPECT_GT(f->oracle_contacts, 300);
    EXPECT_LT(f->oracle_contacts, 700);
  }
}

}  // namespace
}  // namespace sparsedyn
