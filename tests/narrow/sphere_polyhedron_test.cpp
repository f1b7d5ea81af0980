// SPDX-License-Identifier: MIT
// The sphere-polyhedron detailed phase (issue #36): the closest feature of a polyhedron to a
// point against brute force from every warm start, and PredictSphereContact against dense
// sampling of the true gap (translating, static, rotating) and on exact cases: grazing passes,
// a centre moving along a face, along an edge and on a zone plane, starting inside the
// tolerance or the polyhedron, open-ended intervals, checkpoints, a fall under gravity.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "narrow/sphere_contact.hpp"
#include "point_walk_check.hpp"
#include "sphere_toi_check.hpp"

namespace sparsedyn {
namespace {

using Kind = ContactPrediction::Kind;
using testing::Still;

// The contact tolerance of the exact cases, and how far their contact times may be off the
// closed forms (s; speeds ~1 m/s, sizes ~1 m: round-off of a few operations, amplified by at
// most ~1e3 where a pass grazes).
constexpr double kTolerance = 1e-4;
constexpr double kTimeError = 1e-10;

TEST(PointWalk, AgreesWithBruteForceFromEveryWarmStart) {
  const testing::PointWalkFigures f =
      testing::RunPointWalkCheck(/*seed=*/20261210, /*hull_count=*/400, /*points_per_hull=*/4);
  f.Print("fast");
  EXPECT_LE(f.max_relative_error, testing::kPointErrorBound);
  EXPECT_EQ(f.brute_force_cold, 0);
  EXPECT_GE(f.inside, f.points / 10);
  EXPECT_LE(f.inside, f.points / 2);
}

struct Cube {
  testing::Shape shape = testing::MakeShape("cube", *MakeBox({1, 1, 1}));
  const TrackedPolyhedron& tracked() const { return *shape.tracked; }
};

TEST(PointWalk, CubeCases) {
  const Cube cube;
  const Pose X;
  // Inside: the nearest face plane, its normal, the projection.
  PointClosest c = FindClosestFeatureToPoint(cube.tracked(), X, {0.2, 0.3, 0.9});
  EXPECT_NEAR(c.distance, -0.1, 1e-15);
  EXPECT_EQ(c.normal, Vec3::UnitZ());
  EXPECT_LT((c.point - Vec3(0.2, 0.3, 1.0)).norm(), 1e-15);
  // On a vertex: distance 0, the feature's outward normal.
  c = FindClosestFeatureToPoint(cube.tracked(), X, {1, 1, 1});
  EXPECT_EQ(c.distance, 0.0);
  EXPECT_LT((c.normal - Vec3::Ones().normalized()).norm(), 1e-15);
  // Beyond a vertex, an edge and a face.
  c = FindClosestFeatureToPoint(cube.tracked(), X, {2, 3, 1 + 2 * std::sqrt(3.0)});
  EXPECT_EQ(c.feature.type, FeatureType::kVertex);
  EXPECT_NEAR(c.distance, std::sqrt(1 + 4 + 12.0), 1e-14);
  c = FindClosestFeatureToPoint(cube.tracked(), X, {0.5, 4, 5});
  EXPECT_EQ(c.feature.type, FeatureType::kEdge);
  EXPECT_NEAR(c.distance, 5.0, 1e-14);
  c = FindClosestFeatureToPoint(cube.tracked(), X, {0.5, -0.25, -3});
  EXPECT_EQ(c.feature.type, FeatureType::kFace);
  EXPECT_NEAR(c.distance, 2.0, 1e-15);
  EXPECT_EQ(c.normal, -Vec3::UnitZ());
}

// The random motion cases: the prediction is never late, and for a polyhedron that does not
// rotate it is the oracle's time to round-off.
TEST(SphereContact, TranslatingPairsMatchTheOracleExactly) {
  const testing::ToiFigures f =
      testing::RunSphereCheck(20261211, 1000, /*spin=*/0.0, /*accelerate=*/true, Still::kNeither);
  testing::ExpectNoErrors(f, "sphere, translating polyhedron", /*exact=*/true);
  EXPECT_GE(f.contacts, 300);
  EXPECT_LE(f.contacts, 700);
}

TEST(SphereContact, StaticPolyhedronOrStaticSphereMatchesTheOracleExactly) {
  const testing::ToiFigures a =
      testing::RunSphereCheck(20261212, 500, 0.0, /*accelerate=*/true, Still::kPolyhedron);
  testing::ExpectNoErrors(a, "sphere, static polyhedron", /*exact=*/true);
  const testing::ToiFigures b =
      testing::RunSphereCheck(20261213, 500, 0.0, /*accelerate=*/true, Still::kSphere);
  testing::ExpectNoErrors(b, "static sphere, translating polyhedron", /*exact=*/true);
}

TEST(SphereContact, RotatingPolyhedraAreNeverLate) {
  const testing::ToiFigures f =
      testing::RunSphereCheck(20261214, 1000, /*spin=*/10.0, /*accelerate=*/true, Still::kNeither);
  testing::ExpectNoErrors(f, "sphere, rotating polyhedron", /*exact=*/false);
  const testing::ToiFigures still =
      testing::RunSphereCheck(20261215, 500, /*spin=*/10.0, /*accelerate=*/true, Still::kSphere);
  testing::ExpectNoErrors(still, "static sphere, rotating polyhedron", /*exact=*/false);
}

// A sphere of radius 0.5 on a straight line past the static cube [-1, 1]^3.
SphereContactPrediction Pass(const Vec3& p0, const Vec3& v0, double t_end = 10.0,
                             const Vec3& a = Vec3::Zero(), int max_iterations = 64) {
  static const Cube cube;
  ContactPredictionOptions options;
  options.tolerance = kTolerance;
  options.max_iterations = max_iterations;
  return PredictSphereContact(cube.tracked(), RigidPath{}, Path{p0, v0, a, 0.0}, 0.5, 0.0, t_end,
                              std::nullopt, options);
}

TEST(SphereContact, GrazingPastAFaceMissesOrHitsByTheTolerance) {
  const double reach = 0.5 + kTolerance;
  // Sliding over the top face 1e-7 above the tolerance: no contact, all the way across.
  EXPECT_EQ(Pass({-3, 0, 1 + reach + 1e-7}, {1, 0, 0}).kind, Kind::kNone);
  // 1e-7 below: contact as the centre comes within reach of the face's edge x = -1, z = 1.
  const double h = reach - 1e-7;
  const SphereContactPrediction p = Pass({-3, 0, 1 + h}, {1, 0, 0});
  ASSERT_EQ(p.kind, Kind::kContact);
  EXPECT_NEAR(p.time, 2.0 - std::sqrt(reach * reach - h * h), kTimeError);
  EXPECT_LE(p.gap, kTolerance);
}

TEST(SphereContact, MovingAlongAnEdgeOrAZonePlaneStaysExact) {
  const double reach = 0.5 + kTolerance;
  // Parallel to the edge y = z = 1 at 2 tolerances off the sphere: past the vertex
  // (-1, 1, 1), then along the edge, no contact.
  const double d = (reach + kTolerance) / std::sqrt(2.0);
  SphereContactPrediction p = Pass({-3, 1 + d, 1 + d}, {1, 0, 0});
  EXPECT_EQ(p.kind, Kind::kNone);
  EXPECT_LE(p.iterations, 8);
  // Closer than the reach: contact with the vertex at |(x + 1, e, e)| = reach.
  const double e = (reach - 1e-7) / std::sqrt(2.0);
  p = Pass({-3, 1 + e, 1 + e}, {1, 0, 0});
  ASSERT_EQ(p.kind, Kind::kContact);
  EXPECT_NEAR(p.time, 2.0 - std::sqrt(reach * reach - 2 * e * e), kTimeError);
  // Exactly on the zone plane y = 1 between the top face's zone and the edge's: no contact...
  p = Pass({-3, 1, 1 + reach + kTolerance}, {1, 0, 0});
  EXPECT_EQ(p.kind, Kind::kNone);
  EXPECT_EQ(p.advancement_steps, 0);
  EXPECT_LE(p.iterations, 8);
  // ... and, sinking by one tolerance in 3 s, contact over the face at t = 3.
  p = Pass({-3, 1, 1 + reach + kTolerance}, {1, 0, -kTolerance / 3});
  ASSERT_EQ(p.kind, Kind::kContact);
  EXPECT_NEAR(p.time, 3.0, kTimeError);
  EXPECT_NE(p.closest.feature.type, FeatureType::kVertex);  // the face, or the edge beside it
}

TEST(SphereContact, WithinTheToleranceOrInsideAtTheStartIsContactNow) {
  SphereContactPrediction p = Pass({0.3, 0, 1.5 + kTolerance / 2}, {1, 0, 0});
  EXPECT_EQ(p.kind, Kind::kContact);
  EXPECT_EQ(p.time, 0.0);
  EXPECT_EQ(p.iterations, 0);
  EXPECT_NEAR(p.gap, kTolerance / 2, 1e-15);
  p = Pass({0.3, 0.1, 0.9}, {0, 0, 1});
  EXPECT_EQ(p.kind, Kind::kContact);
  EXPECT_EQ(p.time, 0.0);
  EXPECT_NEAR(p.closest.distance, -0.1, 1e-15);
  EXPECT_NEAR(p.gap, -0.6, 1e-15);
  EXPECT_EQ(p.closest.normal, Vec3::UnitZ());
}

TEST(SphereContact, OpenEndedIntervals) {
  const double inf = std::numeric_limits<double>::infinity();
  SphereContactPrediction p = Pass({5, 0.2, 0.1}, {-2, 0, 0}, inf);
  ASSERT_EQ(p.kind, Kind::kContact);
  EXPECT_NEAR(p.time, (5 - 1.5 - kTolerance) / 2, kTimeError);
  p = Pass({5, 0.2, 0.1}, {2, 0, 0}, inf);
  EXPECT_EQ(p.kind, Kind::kNone);
  EXPECT_EQ(p.time, inf);
}

TEST(SphereContact, FallUnderGravityOntoATiltedStaticBoxIsTheQuadraticRoot) {
  const Cube cube;
  RigidPath box;
  box.q0 = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3(1, 2, 0).normalized()));
  box.centre.p0 = {0.4, -0.2, 0.1};
  const Vec3 n = box.q0 * Vec3::UnitZ();  // the top face's normal
  const Vec3 g(0, 0, -9.81);
  const double r = 0.25, h0 = 2.0;  // the centre starts h0 above the face's centre
  const Path centre{box.centre.p0 + n + h0 * n, {0.1, 0, 0.5}, g, 0.0};
  ContactPredictionOptions options;
  options.tolerance = kTolerance;
  const SphereContactPrediction p =
      PredictSphereContact(cube.tracked(), box, centre, r, 0.0, 5.0, std::nullopt, options);
  ASSERT_EQ(p.kind, Kind::kContact);
  // Height over the face plane: h0 + (n . v) t + (n . g) t^2 / 2 = r + tolerance.
  const long double A = 0.5L * n.dot(g), B = n.dot(centre.v0), C = h0 - r - kTolerance;
  const long double t = (-B - std::sqrt(B * B - 4 * A * C)) / (2 * A);
  EXPECT_NEAR(p.time, static_cast<double>(t), kTimeError);
  EXPECT_EQ(p.iterations, 1);
}

TEST(SphereContact, CheckpointsResumeToTheSameAnswer) {
  const Cube cube;
  RigidPath spinning;
  spinning.omega = {0.5, 1.0, 6.0};
  ContactPredictionOptions options;
  options.tolerance = kTolerance;
  const Path centre{{4, 0.3, 0.2}, {-1.5, 0, 0}, Vec3::Zero(), 0.0};
  const SphereContactPrediction whole =
      PredictSphereContact(cube.tracked(), spinning, centre, 0.4, 0.0, 10.0, std::nullopt, options);
  ASSERT_EQ(whole.kind, Kind::kContact);
  options.max_iterations = 1;
  SphereContactPrediction p;
  double t = 0.0;
  std::optional<FeatureId> warm;
  int calls = 0;
  do {
    p = PredictSphereContact(cube.tracked(), spinning, centre, 0.4, t, 10.0, warm, options);
    t = p.time;
    warm = p.closest.feature;
  } while (p.kind == Kind::kCheckpoint && ++calls < 1000);
  EXPECT_GT(calls, 1);
  EXPECT_EQ(p.kind, Kind::kContact);
  EXPECT_EQ(p.time, whole.time);
}

}  // namespace
}  // namespace sparsedyn

namespace sparsedyn {
namespace {

// Two cases of the slow suite (seeds 20261233 and 20261235) where the first root of the gap
// left the walk's gap 5e-16 above the tolerance, the step onto the tolerance mistook the
// walk's round-off for a rising gap, and the prediction went on from inside the band to its
// far root: a dip 1e-6 deep was missed. The gap's dip is now probed halfway.
TEST(SphereContact, ADipThatTheWalkSeesOnlyPastTheFirstRootIsFound) {
  struct Case {
    std::uint64_t seed;
    int trial;
    Still still;
    double tolerance;
  };
  for (const Case& k :
       {Case{20261233, 966, Still::kSphere, 1e-4}, Case{20261235, 309, Still::kNeither, 1e-8}}) {
    testing::MotionCaseGenerator generator(k.seed);
    std::optional<testing::SphereCase> c;
    for (int trial = 0; trial <= k.trial; ++trial) {
      const double fraction = 0.1 + 0.9 * generator.Uniform();
      c = testing::SphereFromPair(generator.Pair(0.0, true), fraction, k.still);
    }
    testing::ToiFigures f;
    f.tolerance = k.tolerance;
    ContactPredictionOptions options;
    options.tolerance = k.tolerance;
    int iterations = 0, checkpoints = 0;
    const SphereContactPrediction p =
        testing::PredictSphereResuming(*c, options, iterations, checkpoints);
    ASSERT_EQ(p.kind, Kind::kContact) << c->Describe();
    const testing::PointOracle oracle(*c->motion.a->polyhedron);
    testing::CheckAgainstOracle(
        c->motion, p.kind, p.time, p.gap, iterations, /*exact=*/true, k.tolerance,
        [&](double t) {
          return static_cast<double>(oracle.SignedDistance(c->motion.path_a.PoseAt(t),
                                                           c->motion.path_b.centre.PositionAt(t))) -
                 c->radius;
        },
        f);
    EXPECT_EQ(f.Errors(/*exact=*/true), 0);
  }
}

}  // namespace
}  // namespace sparsedyn
