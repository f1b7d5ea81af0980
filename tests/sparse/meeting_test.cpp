// SPDX-License-Identifier: MIT
#include "sparse/meeting.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "scenes/random.hpp"
#include "support/fp_traps.hpp"
#include "support/meeting_oracle.hpp"

namespace sparsedyn {
namespace {

// Analytic meeting times are reproduced to a few ulps of the time scale.
constexpr double kAnalyticTolerance = 1e-13;

Mover Sphere(Vec3 p, Vec3 v, double r, Vec3 a = Vec3::Zero()) {
  return Mover{p, v, a, r, 0.0, 0.0};
}

TEST(MeetingTime, HeadOnSpheresMeetAtGapOverClosingSpeed) {
  // Centres 10 apart, radii 1 + 1: gap 8 closed at 2 + 2 = 4 m/s -> 2 s.
  const Mover a = Sphere({0, 0, 0}, {2, 0, 0}, 1);
  const Mover b = Sphere({10, 0, 0}, {-2, 0, 0}, 1);
  const double dt = PredictMeeting(a, b, Vec3::Zero());
  EXPECT_NEAR(dt, 2.0, kAnalyticTolerance);
  EXPECT_LE(dt, 2.0);  // never late
}

TEST(MeetingTime, GlancingSpheresMeetWhereLateralOffsetAllows) {
  // b moves along x at lateral offset h = 1.2 < R = 2: meets when the x-gap is sqrt(R^2 - h^2).
  const double h = 1.2, reach = 2.0;
  const Mover a = Sphere({0, 0, 0}, {0, 0, 0}, 1);
  const Mover b = Sphere({10, h, 0}, {-1, 0, 0}, 1);
  const double expected = 10 - std::sqrt(reach * reach - h * h);
  EXPECT_NEAR(PredictMeeting(a, b, Vec3::Zero()), expected, kAnalyticTolerance);
}

TEST(MeetingTime, SpheresThatPassWideNeverMeet) {
  const Mover a = Sphere({0, 0, 0}, {0, 0, 0}, 1);
  const Mover b = Sphere({10, 2.0001, 0}, {-1, 0, 0}, 1);
  EXPECT_EQ(PredictMeeting(a, b, Vec3::Zero()), kInfinity);
}

TEST(MeetingTime, ExactlyGrazingSpheresMeetAtClosestApproachNotLater) {
  // Lateral offset equal to the summed radii: the spheres touch once, at x = 0 (t = 10).
  const Mover a = Sphere({0, 0, 0}, {0, 0, 0}, 1);
  const Mover b = Sphere({10, 2, 0}, {-1, 0, 0}, 1);
  const double dt = PredictMeeting(a, b, Vec3::Zero());
  ASSERT_NE(dt, kInfinity);
  EXPECT_LE(dt, 10.0);
  EXPECT_NEAR(dt, 10.0, 1e-6);  // a double root is only determined to ~sqrt(eps)
}

TEST(MeetingTime, EqualVelocitiesNeverMeet) {
  const Mover a = Sphere({0, 0, 0}, {3, -1, 2}, 1);
  const Mover b = Sphere({5, 0, 0}, {3, -1, 2}, 1);
  EXPECT_EQ(PredictMeeting(a, b, Vec3::Zero()), kInfinity);
}

TEST(MeetingTime, ZeroRelativeVelocityTouchingIsNotAMeeting) {
  const Mover a = Sphere({0, 0, 0}, {1, 0, 0}, 1);
  const Mover b = Sphere({2, 0, 0}, {1, 0, 0}, 1);
  EXPECT_EQ(PredictMeeting(a, b, Vec3::Zero()), kInfinity);
}

TEST(MeetingTime, OverlapByRoundOffMeetsNowIfApproachingElseIgnored) {
  const Mover a = Sphere({0, 0, 0}, {0, 0, 0}, 1);
  const Mover closing = Sphere({2 - 1e-15, 0, 0}, {-1, 0, 0}, 1);
  const Mover opening = Sphere({2 - 1e-15, 0, 0}, {1, 0, 0}, 1);
  EXPECT_EQ(PredictMeeting(a, closing, Vec3::Zero()), 0.0);
  EXPECT_EQ(PredictMeeting(a, opening, Vec3::Zero()), kInfinity);
}

TEST(MeetingTime, BothUnderGravityIsTheSameAsNoGravity) {
  const Vec3 g(0, 0, -9.81);
  const Mover a = Sphere({0, 0, 0}, {2, 0, 0}, 1, g);
  const Mover b = Sphere({10, 0, 0}, {-2, 0, 0}, 1, g);
  EXPECT_NEAR(PredictMeeting(a, b, Vec3::Zero()), 2.0, 1e-12);
}

TEST(MeetingTime, ThrustingSphereMeetsAtQuadraticRoot) {
  // b at rest 8 m beyond contact, a starts at 1 m/s with thrust 2 m/s^2: t + t^2 = 8.
  const Mover a = Sphere({0, 0, 0}, {1, 0, 0}, 1, {2, 0, 0});
  const Mover b = Sphere({10, 0, 0}, {0, 0, 0}, 1);
  const double expected = (-1 + std::sqrt(1 + 4 * 8.0)) / 2;
  const double dt = PredictMeeting(a, b, Vec3::Zero());
  EXPECT_NEAR(dt, expected, 1e-12);
  EXPECT_LE(dt, expected + 1e-15);
}

TEST(MeetingTime, ThrustReversesAndStillMeets) {
  // a moves away at 1 m/s but is pushed back at 1 m/s^2: x = -t + t^2/2 reaches +8 at
  // t = 1 + sqrt(17).
  const Mover a = Sphere({0, 0, 0}, {-1, 0, 0}, 1, {1, 0, 0});
  const Mover b = Sphere({10, 0, 0}, {0, 0, 0}, 1);
  EXPECT_NEAR(PredictMeeting(a, b, Vec3::Zero()), 1 + std::sqrt(17.0), 1e-12);
}

TEST(MeetingTime, GrowingEnvelopesMeetEarlier) {
  // Gap 8 closing at 2 m/s while each envelope grows at 0.5 m/s: 8 = (2 + 1) t.
  Mover a = Sphere({0, 0, 0}, {1, 0, 0}, 1);
  Mover b = Sphere({10, 0, 0}, {-1, 0, 0}, 1);
  a.r1 = b.r1 = 0.5;
  EXPECT_NEAR(PredictMeeting(a, b, Vec3::Zero()), 8.0 / 3.0, 1e-12);
  // And a quadratic envelope: 8 = 2 t + (0.5 + 0.5) t^2 / 2 * 2 ... with e2 = 1 each:
  // R(t) grows by t^2 (two envelopes of t^2/2), so 8 = 2t + t^2 -> t = 2.
  a.r1 = b.r1 = 0.0;
  a.r2 = b.r2 = 1.0;
  EXPECT_NEAR(PredictMeeting(a, b, Vec3::Zero()), 2.0, 1e-12);
}

TEST(MeetingTime, PeriodicImageShiftIsApplied) {
  const Mover a = Sphere({0.5, 0, 0}, {-1, 0, 0}, 0.5);
  const Mover b = Sphere({9.5, 0, 0}, {0, 0, 0}, 0.5);
  // Box of side 10: b's image at -0.5 is 1 away, touching distance 1 -> already touching...
  // put it at 9.0 -> image at -1.0, gap 0.5 at closing speed 1.
  const Mover b2 = Sphere({9.0, 0, 0}, {0, 0, 0}, 0.5);
  EXPECT_NEAR(PredictMeeting(a, b2, Vec3(-10, 0, 0)), 0.5, 1e-14);
  EXPECT_EQ(PredictMeeting(a, b, Vec3::Zero()), kInfinity);
}

TEST(WallMeetingTime, SphereReachesWallAtGapOverSpeed) {
  const Mover a = Sphere({5, 0, 0}, {-2, 0, 0}, 1);
  // Wall x = 0 with normal +x: the sphere's surface reaches it when x = 1 -> t = 2.
  EXPECT_NEAR(PredictWallMeeting(a, Vec3(1, 0, 0), 0.0), 2.0, kAnalyticTolerance);
  EXPECT_EQ(PredictWallMeeting(Sphere({5, 0, 0}, {2, 0, 0}, 1), Vec3(1, 0, 0), 0.0), kInfinity);
}

TEST(WallMeetingTime, BallThrownUpFallsOntoFloor) {
  // Floor z = 0; ball radius 0.5 at z = 1.5 thrown up at 4 m/s under g = 10:
  // 1 + 4t - 5t^2 = 0 -> t = (4 + sqrt(36)) / 10 = 1.
  const Mover a = Sphere({0, 0, 1.5}, {0, 0, 4}, 0.5, {0, 0, -10});
  EXPECT_NEAR(PredictWallMeeting(a, Vec3(0, 0, 1), 0.0), 1.0, 1e-12);
}

TEST(SeparationTime, HeadOnPassThroughEndsAtLargerRoot) {
  const Mover a = Sphere({0, 0, 0}, {0, 0, 0}, 1);
  const Mover b = Sphere({1, 0, 0}, {1, 0, 0}, 1);  // overlapping, leaving at 1 m/s
  const double dt = PredictSeparation(a, b, Vec3::Zero());
  EXPECT_NEAR(dt, 1.0, 1e-12);
  EXPECT_GE(dt, 1.0);  // never early
}

// The 10^4 random pairs of this fast test (10^5 in meeting_slow_test.cpp) against the oracle.
void CheckRandomPairs(int pairs, std::uint64_t seed) {
  constexpr double kHorizon = 10.0;
  // The oracle bisects in long double; predictions are double: a prediction may not be later
  // than the oracle's root by more than the double rounding of the time itself.
  constexpr long double kLateSlack = 4e-15L;
  scenes::Random random(seed);
  int met = 0, late = 0, missed = 0, spurious = 0;
  for (int trial = 0; trial < pairs; ++trial) {
    const int kind = trial % 4;  // linear, accelerated, envelope, accelerated + envelope
    const auto [a, b] = testing::RandomMoverPair(random, kind == 1 || kind == 3, kind >= 2);
    if (testing::OracleGap(a, b, 0) <= 0) continue;  // start separated
    SCOPED_TRACE(::testing::Message() << "seed " << seed << " trial " << trial);
    const double predicted = PredictMeeting(a, b, Vec3::Zero(), kHorizon);
    const std::optional<long double> truth = testing::OracleMeeting(a, b, kHorizon);
    if (truth) {
      ++met;
      if (predicted == kInfinity) {
        ++missed;
      } else if (predicted > *truth + kLateSlack * (1 + *truth)) {
        ++late;
      }
    } else if (predicted != kInfinity && testing::OracleGap(a, b, predicted) >
                                             1e-9L * (1 + a.p.squaredNorm() + b.p.squaredNorm())) {
      ++spurious;  // a predicted meeting that is no meeting at all
    }
  }
  EXPECT_EQ(late, 0);
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(spurious, 0);
  EXPECT_GT(met, pairs / 10) << "the sample should contain many meetings";
  std::printf("random pairs: %d, meetings %d, late %d, missed %d, spurious %d\n", pairs, met, late,
              missed, spurious);
}

TEST(MeetingTime, AgreesWithDenseSamplingOnRandomPairs) { CheckRandomPairs(10000, 20261122); }

// The distance bound that lets a scan skip a pair: whenever it says "apart within h", the oracle
// finds no meeting in [0, h]; and it does say so for many pairs (else it would skip nothing).
TEST(CertainlyApart, NeverClaimsAPairThatMeetsWithinTheTime) {
  scenes::Random random(20261128);
  int apart = 0, meet_within = 0, wrong = 0;
  constexpr int kPairs = 4000;
  for (int trial = 0; trial < kPairs; ++trial) {
    const int kind = trial % 4;  // linear, accelerated, envelope, accelerated + envelope
    auto [a, b] = testing::RandomMoverPair(random, kind == 1 || kind == 3, kind >= 2);
    if (testing::OracleGap(a, b, 0) <= 0) continue;
    // Shrinking envelopes too: the bound must take only the growth.
    if (trial % 8 == 6) b.r1 = -0.5 * b.r1;
    const double h = random.Uniform(0.0, 4.0);
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " h " << h);
    const std::optional<long double> truth = testing::OracleMeeting(a, b, h);
    meet_within += truth ? 1 : 0;
    if (!CertainlyApartWithin(a, b, Vec3::Zero(), h)) continue;
    ++apart;
    if (truth) ++wrong;
    // The prediction, when finite, is later than h as well.
    const double dt = PredictMeeting(a, b, Vec3::Zero());
    EXPECT_GT(dt, h);
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(apart, kPairs / 10);
  EXPECT_GT(meet_within, kPairs / 10);
}

// The slab verdicts AllPairs uses for the 26 images after the nearest (ApartAlongEach): whenever
// the test along axis k says "apart" for step s, every image whose shift along k is along[s][k]
// is apart by the oracle and by Within itself (a skip the per-image test would make too); and it
// settles most far images (else it would save nothing). Each axis has its own period, so
// verdicts read with the axis and step swapped would name the wrong images. With no time span
// (h < 0) or an unbounded one, no verdict at all.
TEST(CertainlyApart, SlabVerdictHoldsForEveryImageInTheSlab) {
  // Floating-point traps paused (docs/reliability.md): spans of -1,
  // infinity and NaN on purpose (the bound's guard !(h >= 0) compares NaN).
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  scenes::Random random(20261129);
  const Vec3 length(11, 12, 13);  // RandomMoverPair's points are within [-5, 5]^3
  const std::array<Vec3, 3> along = {-length, Vec3::Zero(), length};
  std::vector<Vec3> shifts;
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        shifts.emplace_back(dx * length[0], dy * length[1], dz * length[2]);
      }
    }
  }
  int slabs = 0, images_skipped = 0, wrong = 0, without_span = 0;
  constexpr int kPairs = 600;
  for (int trial = 0; trial < kPairs; ++trial) {
    const int kind = trial % 4;
    const auto [a, b] = testing::RandomMoverPair(random, kind == 1 || kind == 3, kind >= 2);
    const double h = random.Uniform(0.0, 3.0);
    const ApartBound bound(a, b);
    for (const double no_span : {-1.0, kInfinity, std::nan("")}) {
      for (const auto& axis : bound.ApartAlongEach(along, length, no_span)) {
        for (const bool apart : axis) without_span += apart ? 1 : 0;
      }
    }
    const ApartBound::SlabVerdicts apart = bound.ApartAlongEach(along, length, h);
    for (int k = 0; k < 3; ++k) {
      for (std::size_t s = 0; s < 3; ++s) {
        if (!apart[k][s]) continue;
        ++slabs;
        for (const Vec3& shift : shifts) {
          if (shift[k] != along[s][k]) continue;
          SCOPED_TRACE(::testing::Message() << "trial " << trial << " axis " << k << " shift "
                                            << shift.transpose() << " h " << h);
          ++images_skipped;
          EXPECT_TRUE(bound.Within(shift, h));
          EXPECT_EQ(bound.Within(shift, h), CertainlyApartWithin(a, b, shift, h));
          Mover image = b;
          image.p += shift;
          if (testing::OracleGap(a, image, 0) <= 0 || testing::OracleMeeting(a, image, h)) ++wrong;
        }
      }
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(without_span, 0);
  // Of the 9 slabs per pair, the 6 off the middle are far: most should be settled.
  EXPECT_GT(slabs, kPairs * 5);
  EXPECT_GT(images_skipped, kPairs * 15);
}

// The images the slab verdicts skip, against the images themselves: every one of the 512
// verdict sets, each image by its steps along z, y and x (x fastest), and the 26 other than
// each possible nearest one at once.
TEST(CertainlyApart, SlabVerdictsSkipTheImagesOfTheirSteps) {
  int all_others = 0;
  for (unsigned bits = 0; bits < 512; ++bits) {
    ApartBound::SlabVerdicts apart{};
    for (unsigned b = 0; b < 9; ++b) apart[b / 3][b % 3] = ((bits >> b) & 1u) != 0;
    std::array<bool, 27> skipped{};
    std::size_t r = 0;
    for (std::size_t sz = 0; sz < 3; ++sz) {
      for (std::size_t sy = 0; sy < 3; ++sy) {
        for (std::size_t sx = 0; sx < 3; ++sx, ++r) {
          skipped[r] = apart[0][sx] || apart[1][sy] || apart[2][sz];
          EXPECT_EQ(ImageApart(apart, r), skipped[r]) << "verdicts " << bits << " image " << r;
        }
      }
    }
    for (std::size_t nearest = 0; nearest < 27; ++nearest) {
      bool others = true;
      for (std::size_t q = 0; q < 27; ++q) others = others && (q == nearest || skipped[q]);
      EXPECT_EQ(OtherImagesApart(apart, nearest), others)
          << "verdicts " << bits << " nearest " << nearest;
      all_others += others ? 1 : 0;
    }
  }
  EXPECT_GT(all_others, 0);
  EXPECT_LT(all_others, 512 * 27);
}

// Head-on at closing speed 2 from a gap of 3 (contact at dt = 1.5): apart within a time just
// short of the contact, not within the contact time itself; the axis bound alone settles a pair
// offset along z that the overall distance would not.
TEST(CertainlyApart, IsTightForAHeadOnPairAndUsesEachAxis) {
  // Floating-point traps paused (docs/reliability.md): infinite and NaN
  // spans on purpose (the bound's guard !(h >= 0) compares NaN).
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  const Mover a = Sphere(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5);
  const Mover b = Sphere(Vec3(4, 0, 0), Vec3(-1, 0, 0), 0.5);
  EXPECT_TRUE(CertainlyApartWithin(a, b, Vec3::Zero(), 1.5 * (1 - 1e-4)));
  EXPECT_FALSE(CertainlyApartWithin(a, b, Vec3::Zero(), 1.5));
  EXPECT_FALSE(CertainlyApartWithin(a, b, Vec3::Zero(), 1.5 * (1 - 1e-9)));  // within the margin
  // Growing envelopes close the gap sooner: r1 = 1 each (reach 1 + 2 dt) meets at dt = 0.75.
  Mover ga = a, gb = b;
  ga.r1 = gb.r1 = 1.0;
  EXPECT_FALSE(CertainlyApartWithin(ga, gb, Vec3::Zero(), 0.8));
  EXPECT_TRUE(CertainlyApartWithin(ga, gb, Vec3::Zero(), 0.7));
  // b far along z, moving fast along x only: the distance closes at speed 10 overall, but the
  // z separation of 5 (less the reach 1) never closes.
  const Mover c = Sphere(Vec3(0, 0, 0), Vec3::Zero(), 0.5);
  const Mover d = Sphere(Vec3(-1, 0, 5), Vec3(10, 0, 0), 0.5);
  EXPECT_TRUE(CertainlyApartWithin(c, d, Vec3::Zero(), 100.0));
  // The periodic image shift counts: the image below is within reach at once.
  EXPECT_FALSE(CertainlyApartWithin(c, d, Vec3(1, 0, -5), 0.01));
  // No time, no verdict beyond the start; infinity or NaN: no verdict.
  EXPECT_FALSE(CertainlyApartWithin(c, d, Vec3::Zero(), kInfinity));
  EXPECT_FALSE(CertainlyApartWithin(c, d, Vec3::Zero(), std::nan("")));
}

}  // namespace
}  // namespace sparsedyn
