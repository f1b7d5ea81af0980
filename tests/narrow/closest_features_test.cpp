// SPDX-License-Identifier: MIT
// The closest-feature walk: exact small cases, penetration, frames, tables, the tracker, and a
// brute-force cross-check on a few thousand random and degenerate pairs.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "narrow/angle_tables.hpp"
#include "narrow/feature_distance.hpp"
#include "narrow/pair_frame.hpp"
#include "narrow/tables.hpp"
#include "narrow/zone_check.hpp"
#include "oracle_check.hpp"

namespace sparsedyn {
namespace {

using testing::MakeShape;
using testing::Shape;

Pose At(double x, double y, double z,
        Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity()) {
  Pose pose;
  pose.translation = {x, y, z};
  pose.rotation = rotation;
  return pose;
}

const Shape& Cube() {
  static const Shape cube = MakeShape("cube", *MakeBox({1, 1, 1}));
  return cube;
}

TEST(ClosestFeatures, FacingCubesAreOneApartAlongX) {
  const ClosestFeatures r =
      FindClosestFeatures(*Cube().tracked, At(0, 0, 0), *Cube().tracked, At(3, 0.5, 0.25));
  EXPECT_EQ(r.status, ClosestFeatures::Status::kSeparated);
  EXPECT_NEAR(r.distance, 1.0, 1e-15);
  EXPECT_NEAR(r.normal.x(), 1.0, 1e-15);
  EXPECT_NEAR(r.point_a.x(), 1.0, 1e-15);
  EXPECT_NEAR(r.point_b.x(), 2.0, 1e-15);
}

TEST(ClosestFeatures, CornerToCornerDistanceIsTheDiagonalGap) {
  const ClosestFeatures r =
      FindClosestFeatures(*Cube().tracked, At(0, 0, 0), *Cube().tracked, At(3, 3, 3));
  EXPECT_NEAR(r.distance, std::sqrt(3.0), 1e-15);
  EXPECT_EQ(r.features.a, FeatureId::Vertex(Cube().polyhedron->SupportVertex({1, 1, 1})));
  EXPECT_EQ(r.features.b, FeatureId::Vertex(Cube().polyhedron->SupportVertex({-1, -1, -1})));
}

TEST(ClosestFeatures, CrossedEdgesMeetAtTheirMidpoints) {
  // B turned 90 degrees about x and lifted so its lowest edge runs along y above A's top edge.
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()));
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY()));
  const ClosestFeatures r = FindClosestFeatures(*Cube().tracked, At(0, 0, 0, tilt), *Cube().tracked,
                                                At(0, 0, 2 * std::sqrt(2.0) + 0.5, turn));
  EXPECT_EQ(r.features.a.type, FeatureType::kEdge);
  EXPECT_EQ(r.features.b.type, FeatureType::kEdge);
  EXPECT_NEAR(r.distance, 0.5, 1e-14);
}

TEST(ClosestFeatures, OverlappingCubesReportTheirPenetrationDepth) {
  const ClosestFeatures r =
      FindClosestFeatures(*Cube().tracked, At(0, 0, 0), *Cube().tracked, At(1.7, 0.2, -0.1));
  EXPECT_EQ(r.status, ClosestFeatures::Status::kPenetrating);
  EXPECT_NEAR(r.distance, -0.3, 1e-14);
  EXPECT_NEAR(r.normal.x(), 1.0, 1e-14);
  EXPECT_NEAR(r.normal.dot(r.point_b - r.point_a), r.distance, 1e-14);
}

TEST(ClosestFeatures, ACubeInsideAnotherIsPenetratingByTheEscapeDistance) {
  static const Shape small = MakeShape("small cube", *MakeBox({0.1, 0.1, 0.1}));
  const ClosestFeatures r =
      FindClosestFeatures(*Cube().tracked, At(0, 0, 0), *small.tracked, At(0.5, 0.0, 0.0));
  EXPECT_EQ(r.status, ClosestFeatures::Status::kPenetrating);
  // Pushing B out through x = 1: 1 - (0.5 - 0.1).
  EXPECT_NEAR(r.distance, -0.6, 1e-14);
}

TEST(ClosestFeatures, ExactlyTouchingFacesAreAtDistanceZero) {
  const ClosestFeatures r =
      FindClosestFeatures(*Cube().tracked, At(0, 0, 0), *Cube().tracked, At(0, 2, 0.5));
  EXPECT_EQ(r.status, ClosestFeatures::Status::kPenetrating);
  EXPECT_EQ(r.distance, 0.0);
}

TEST(ClosestFeatures, PairsFarFromTheOriginKeepTheirPrecision) {
  // A 1e-9 gap between cubes 3e6 from the origin: the walk works in A's frame, so it matches the
  // long double oracle to round-off of the gap's neighbourhood, not of the coordinates (5e-10).
  const Eigen::Vector3d far(1e6, -2e6, 3e6);
  const Eigen::Quaterniond q = Eigen::Quaterniond(0.9, 0.1, -0.3, 0.2).normalized();
  Pose X_WA = At(0, 0, 0, q), X_WB = At(0, 0, 0, q);
  X_WA.translation = far;
  X_WB.translation = far + q * Eigen::Vector3d(2.0 + 1e-9, 0.25, 0.0);
  const ClosestFeatures r = FindClosestFeatures(*Cube().tracked, X_WA, *Cube().tracked, X_WB);
  const double reference = static_cast<double>(
      testing::ReferenceSignedDistance(*Cube().polyhedron, X_WA, *Cube().polyhedron, X_WB));
  EXPECT_GT(reference, 0.0);
  EXPECT_NEAR(r.distance, reference, 1e-15);
}

TEST(ClosestFeatures, AngleTablesDecideLikeTheirPlanes) {
  // Every face and vertex table against a scan of the zone planes, on random points.
  testing::PairGenerator generator(11);
  int tested = 0;
  for (const Shape& shape : generator.generic_shapes()) {
    const ConvexPolyhedron& p = *shape.polyhedron;
    const TrackedPolyhedron::Tables& tables = shape.tracked->tables();
    for (int f = 0; f < p.face_count(); ++f) {
      const narrow::FaceAngleTable* table = tables.face(f);
      if (table == nullptr) continue;
      for (int i = 0; i < 200; ++i) {
        const Eigen::Vector3d q =
            2.0 * p.bounding_radius() * generator.RandomUnit() * generator.Uniform();
        EXPECT_EQ(narrow::IsOverFace(p, f, table, q), narrow::IsOverFace(p, f, nullptr, q));
        ++tested;
      }
    }
    for (int v = 0; v < p.vertex_count(); ++v) {
      const narrow::VertexAngleTable* table = tables.vertex(v);
      if (table == nullptr) continue;
      const auto planes = p.VoronoiPlanes(FeatureId::Vertex(v));
      for (int i = 0; i < 200; ++i) {
        const Eigen::Vector3d q = p.vertex(v) + generator.RandomUnit();
        bool inside = true;
        for (const VoronoiPlane& plane : planes)
          inside = inside && plane.plane.SignedDistance(q) >= 0.0;
        const std::int32_t deciding = table->DecidingPlane(q - p.vertex(v));
        const bool table_inside =
            deciding >= 0 &&
            planes[static_cast<std::size_t>(deciding)].plane.SignedDistance(q) >= 0.0;
        EXPECT_EQ(table_inside, inside);
        ++tested;
      }
    }
  }
  EXPECT_GT(tested, 2000);
}

TEST(PairFrame, RotationOfAnyNormIsTheNormalisedQuaternionsRotation) {
  testing::PairGenerator generator(13);
  int exact = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d v = generator.RandomUnit();
    Eigen::Quaterniond q(generator.Uniform() - 0.5, v.x(), v.y(), v.z());
    const Eigen::Matrix3d reference = q.normalized().toRotationMatrix();
    q.coeffs() *= std::pow(10.0, 6.0 * generator.Uniform() - 3.0);
    EXPECT_LT((narrow::PairFrame::RotationOf(q) - reference).cwiseAbs().maxCoeff(), 4e-15);
    const Eigen::Quaterniond unit = q.normalized();
    if (unit.squaredNorm() == 1.0) {
      EXPECT_EQ(narrow::PairFrame::RotationOf(unit), unit.toRotationMatrix());
      ++exact;
    }
  }
  EXPECT_GT(exact, 100);
}

TEST(ClosestFeatures, SegmentAgainstFaceMatchesAConvexSearchAlongTheSegment) {
  // The oracle: the distance from a point to a convex polygon is exact (ClosestPointOnFace), and
  // along a segment it is a convex function of the parameter, so a golden-section search finds
  // its minimum independently of the pruned edge scan in ClosestSegmentFace.
  testing::PairGenerator generator(14);
  int tested = 0, pruned_cases = 0;
  for (const Shape& shape : generator.generic_shapes()) {
    const ConvexPolyhedron& p = *shape.polyhedron;
    const double r = p.bounding_radius();
    for (int f = 0; f < p.face_count(); ++f) {
      const Plane& plane = p.face(f).plane;
      for (int i = 0; i < 30; ++i) {
        // Ends near the face: some over it, some beside it, some on either side of its plane.
        const Eigen::Vector3d on_face = p.vertex(p.FaceVertices(f)[0]);
        auto near = [&] {
          return Eigen::Vector3d(on_face + r * generator.Uniform() * generator.RandomUnit() +
                                 0.3 * r * (generator.Uniform() - 0.2) * plane.normal);
        };
        const Eigen::Vector3d s0 = near(), s1 = near();
        auto distance_at = [&](double t) {
          const Eigen::Vector3d x = s0 + t * (s1 - s0);
          return (narrow::ClosestPointOnFace(p, f, nullptr, x).point - x).norm();
        };
        double lo = 0.0, hi = 1.0;
        const double g = (std::sqrt(5.0) - 1.0) / 2.0;
        for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) {
          const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
          if (distance_at(m1) < distance_at(m2)) {
            hi = m2;
          } else {
            lo = m1;
          }
        }
        const double oracle = std::min({distance_at(0.0), distance_at(1.0), distance_at(lo)});
        for (const narrow::FaceAngleTable* table :
             {shape.tracked->tables().face(f),
              static_cast<const narrow::FaceAngleTable*>(nullptr)}) {
          const narrow::SegmentFaceClosest c = narrow::ClosestSegmentFace(p, f, table, s0, s1);
          const double walk = (c.on_face - c.on_segment).norm();
          EXPECT_NEAR(walk, oracle, 1e-9 * r) << shape.name << " face " << f;
          EXPECT_LE(walk, oracle + 1e-12 * r);  // never farther than a sampled point
          ++tested;
        }
        pruned_cases += !narrow::IsOverFace(p, f, nullptr, s0) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(tested, 5000);
  EXPECT_GT(pruned_cases, tested / 10);
}

TEST(ClosestFeatures, InZoneIsTrueExactlyWhenZoneMovesIsEmpty) {
  // The walk's fast test against the moves it stands for, on every feature of the generic
  // shapes, with and without tables, for random points and for points put on a zone plane (the
  // tie rule: on a plane is inside).
  testing::PairGenerator generator(12);
  int tested = 0, inside = 0, one_move = 0;
  for (const Shape& shape : generator.generic_shapes()) {
    const ConvexPolyhedron& p = *shape.polyhedron;
    const TrackedPolyhedron::Tables* tables = &shape.tracked->tables();
    auto check = [&](FeatureId f) {
      const auto planes = p.VoronoiPlanes(f);
      for (int i = 0; i < 40; ++i) {
        Eigen::Vector3d q =
            2.0 * p.bounding_radius() * generator.RandomUnit() * generator.Uniform();
        if (i % 4 == 0) {  // onto a zone plane
          const Plane& plane = planes[static_cast<std::size_t>(i / 4) % planes.size()].plane;
          q -= plane.SignedDistance(q) * plane.normal;
        }
        for (const TrackedPolyhedron::Tables* t :
             {tables, static_cast<decltype(tables)>(nullptr)}) {
          for (const int slot : {-1, 0}) {
            const narrow::Moves moves = narrow::ZoneMoves(p, t, f, q, slot);
            const bool empty = moves.count == 0;
            EXPECT_EQ(narrow::InZone(p, t, f, q, slot), empty)
                << shape.name << " feature " << static_cast<int>(f.type) << ":" << f.index;
            // The one-pass test's single move is the list's only move.
            const narrow::ZoneTest test = narrow::TestZone(p, t, f, q, slot);
            if (test.result == narrow::ZoneTest::Result::kOneMove) {
              ASSERT_EQ(moves.count, 1);
              EXPECT_EQ(moves.list[0].to, test.move.to);
              EXPECT_EQ(moves.list[0].kind, test.move.kind);
              ++one_move;
            }
            inside += empty ? 1 : 0;
            ++tested;
          }
        }
      }
    };
    for (int v = 0; v < p.vertex_count(); ++v) check(FeatureId::Vertex(v));
    for (int e = 0; e < p.edge_count(); ++e) check(FeatureId::Edge(e));
    for (int f = 0; f < p.face_count(); ++f) check(FeatureId::Face(f));
  }
  EXPECT_GT(tested, 10000);
  EXPECT_GT(inside, tested / 50);  // both answers occur
  EXPECT_GT(one_move, tested / 50);
}

TEST(ClosestFeatures, AFaceVerdictIsTheFaceZoneTestOfTheVertex) {
  // A vertex against a face: the verdict ClosestPointsOfFeatures records must be what the zone
  // test of the face against the vertex says (InZone and ZoneMoves without it), on both sides,
  // on random placements (about half of them overlapping, so behind-the-face occurs too). Any
  // other pair of feature types has no verdict.
  testing::PairGenerator generator(20261125);
  int tested = 0;
  int seen[4] = {0, 0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    const testing::PlacedPair pair = generator.Next();
    SCOPED_TRACE(pair.Describe());
    const ConvexPolyhedron& a = *pair.a->polyhedron;
    const ConvexPolyhedron& b = *pair.b->polyhedron;
    const TrackedPolyhedron::Tables* tables_a = &pair.a->tracked->tables();
    const TrackedPolyhedron::Tables* tables_b = &pair.b->tracked->tables();
    const narrow::PairFrame frame(pair.X_WA, pair.X_WB);
    auto expect_same_moves = [](const narrow::Moves& x, const narrow::Moves& y) {
      ASSERT_EQ(x.count, y.count);
      for (std::size_t i = 0; i < static_cast<std::size_t>(x.count); ++i) {
        EXPECT_EQ(x.list[i].to, y.list[i].to);
        EXPECT_EQ(x.list[i].kind, y.list[i].kind);
      }
    };
    for (int v = 0; v < std::min(a.vertex_count(), 12); ++v) {
      for (int f = 0; f < std::min(b.face_count(), 12); ++f) {
        // A's vertex against B's face: B's zone test, in B's frame.
        const narrow::FeatureClosest c = narrow::ClosestPointsOfFeatures(
            a, tables_a, FeatureId::Vertex(v), b, tables_b, FeatureId::Face(f), frame);
        EXPECT_EQ(c.verdict_a, narrow::FaceVerdict::kUnknown);
        ASSERT_NE(c.verdict_b, narrow::FaceVerdict::kUnknown);
        const Eigen::Vector3d q = frame.ToB(c.p_a);
        EXPECT_EQ(narrow::InZone(b, tables_b, FeatureId::Face(f), q, c.slot_b),
                  c.verdict_b == narrow::FaceVerdict::kInZone);
        expect_same_moves(
            narrow::ZoneMoves(b, tables_b, FeatureId::Face(f), q, c.slot_b, c.verdict_b),
            narrow::ZoneMoves(b, tables_b, FeatureId::Face(f), q, c.slot_b));
        ++seen[static_cast<int>(c.verdict_b)];
        // The roles swapped (the face's polyhedron first): the first one's zone test.
        const narrow::PairFrame swapped(pair.X_WB, pair.X_WA);
        const narrow::FeatureClosest e = narrow::ClosestPointsOfFeatures(
            b, tables_b, FeatureId::Face(f), a, tables_a, FeatureId::Vertex(v), swapped);
        EXPECT_EQ(e.verdict_b, narrow::FaceVerdict::kUnknown);
        ASSERT_NE(e.verdict_a, narrow::FaceVerdict::kUnknown);
        EXPECT_EQ(narrow::InZone(b, tables_b, FeatureId::Face(f), e.p_b, e.slot_a),
                  e.verdict_a == narrow::FaceVerdict::kInZone);
        expect_same_moves(
            narrow::ZoneMoves(b, tables_b, FeatureId::Face(f), e.p_b, e.slot_a, e.verdict_a),
            narrow::ZoneMoves(b, tables_b, FeatureId::Face(f), e.p_b, e.slot_a));
        ++seen[static_cast<int>(e.verdict_a)];
        tested += 2;
      }
    }
    // No verdict without a vertex-face pair.
    const narrow::FeatureClosest ee = narrow::ClosestPointsOfFeatures(
        a, tables_a, FeatureId::Edge(0), b, tables_b, FeatureId::Face(0), frame);
    EXPECT_EQ(ee.verdict_a, narrow::FaceVerdict::kUnknown);
    EXPECT_EQ(ee.verdict_b, narrow::FaceVerdict::kUnknown);
  }
  EXPECT_GT(tested, 10000);
  // Every verdict occurs.
  EXPECT_GT(seen[static_cast<int>(narrow::FaceVerdict::kInZone)], 100);
  EXPECT_GT(seen[static_cast<int>(narrow::FaceVerdict::kBeside)], 100);
  EXPECT_GT(seen[static_cast<int>(narrow::FaceVerdict::kBehind)], 100);
}

TEST(ClosestFeatures, AngleAndDirectionTablesGiveThePlainWalksAnswers) {
  // Shapes whose faces (prism caps) and vertices (pyramid apex) have many edges, so that the
  // J.1.1 tables are used, against the plain walk from vertex 0.
  const Shape shapes[] = {MakeShape("prism 64", *MakePrism(64, 1.0, 0.3)),
                          MakeShape("pyramid 40", testing::MakePyramid(40, 0.5)),
                          MakeShape("random hull F=120", *RandomConvexPolyhedron(120, 9))};
  EXPECT_GT(shapes[0].tracked->tables().face_table_count(), 0);
  EXPECT_GT(shapes[1].tracked->tables().vertex_table_count(), 0);
  ClosestFeaturesOptions plain, angles_only;
  plain.use_angle_tables = plain.use_direction_table = false;
  angles_only.use_direction_table = false;
  testing::PairGenerator generator(3);
  long long table_steps = 0, plain_steps = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Shape& a = shapes[trial % 3];
    const Shape& b = shapes[(trial / 3) % 3];
    Pose X_WA, X_WB;
    X_WA.rotation = generator.RandomRotation();
    X_WB.rotation = generator.RandomRotation();
    X_WB.translation = (0.4 + 1.2 * generator.Uniform()) * 2.0 * generator.RandomUnit();
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " " << a.name << " / " << b.name);
    const double bound =
        1e-12 * 2.0 * std::max(a.polyhedron->bounding_radius(), b.polyhedron->bounding_radius());
    const ClosestFeatures with = FindClosestFeatures(*a.tracked, X_WA, *b.tracked, X_WB);
    const ClosestFeatures without =
        FindClosestFeatures(*a.tracked, X_WA, *b.tracked, X_WB, std::nullopt, plain);
    const ClosestFeatures angles =
        FindClosestFeatures(*a.tracked, X_WA, *b.tracked, X_WB, std::nullopt, angles_only);
    EXPECT_NEAR(with.distance, without.distance, bound);
    EXPECT_NEAR(angles.distance, without.distance, bound);
    if (std::abs(without.distance) > bound) {
      EXPECT_EQ(with.status, without.status);
      EXPECT_EQ(angles.status, without.status);
    }
    table_steps += with.steps;
    plain_steps += without.steps;
  }
  // The direction table starts near the answer: fewer steps than starting at vertex 0.
  EXPECT_LT(table_steps, plain_steps);
}

TEST(ClosestFeatures, DirectionTableStartsAtTheSupportVertex) {
  const Shape& shape = Cube();
  EXPECT_EQ(shape.tracked->StartingFeature({1, 1, 1}),
            FeatureId::Vertex(shape.polyhedron->SupportVertex({1, 1, 1})));
  EXPECT_EQ(shape.tracked->StartingFeature({-1, 2, -1}),
            FeatureId::Vertex(shape.polyhedron->SupportVertex({-1, 2, -1})));
}

TEST(ClosestFeatureTracker, FollowsARotatingPairWithFewStepsAndNoCapFailures) {
  testing::PairGenerator generator(5);
  const Shape big = MakeShape("random hull F=200", *RandomConvexPolyhedron(200, 42));
  ClosestFeatureTracker tracker(*big.tracked, *big.tracked);
  const Pose X_WA = At(0, 0, 0);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, 1.0, 0.4).normalized();
  for (int step = 0; step < 360; ++step) {
    const Pose X_WB =
        At(2.5, 0.3, 0.1, Eigen::Quaterniond(Eigen::AngleAxisd(step * M_PI / 180, axis)));
    const ClosestFeatures& warm = tracker.Update(X_WA, X_WB);
    const ClosestFeatures cold = FindClosestFeatures(*big.tracked, X_WA, *big.tracked, X_WB);
    ASSERT_NEAR(warm.distance, cold.distance, 1e-12) << "step " << step;
  }
  EXPECT_EQ(tracker.calls(), 360u);
  EXPECT_EQ(tracker.iteration_cap_failures(), 0u);
  // Coherence: 1 degree per call needs about one step on average.
  EXPECT_LT(static_cast<double>(tracker.steps()) / static_cast<double>(tracker.calls()), 3.0);
}

// The tracker fills its cached answer in place: every field must come from the new query, also
// when a penetrating answer (depth, axis features) is followed by a separated one and back.
TEST(ClosestFeatureTracker, InPlaceAnswerEqualsAFreshQueryFromTheSameStart) {
  const Shape hull = MakeShape("random hull F=60", *RandomConvexPolyhedron(60, 7));
  ClosestFeatureTracker tracker(*hull.tracked, *Cube().tracked);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.7, -0.2, 0.5).normalized();
  std::optional<FeaturePair> start;
  int penetrating = 0;
  for (int step = 0; step < 240; ++step) {
    // B moves into A and out again every 40 steps while it spins.
    const double x = 2.2 + std::sin(step * M_PI / 20);
    const Pose X_WA = At(0, 0, 0);
    const Pose X_WB = At(x, 0.2, -0.1, Eigen::Quaterniond(Eigen::AngleAxisd(step * 0.05, axis)));
    const ClosestFeatures fresh =
        FindClosestFeatures(*hull.tracked, X_WA, *Cube().tracked, X_WB, start);
    const ClosestFeatures& tracked = tracker.Update(X_WA, X_WB);
    SCOPED_TRACE("step " + std::to_string(step));
    ASSERT_EQ(tracked.status, fresh.status);
    ASSERT_EQ(tracked.distance, fresh.distance);
    ASSERT_EQ(tracked.point_a, fresh.point_a);
    ASSERT_EQ(tracked.point_b, fresh.point_b);
    ASSERT_EQ(tracked.normal, fresh.normal);
    ASSERT_EQ(tracked.features, fresh.features);
    ASSERT_EQ(tracked.steps, fresh.steps);
    start = tracked.features;
    penetrating += tracked.status == ClosestFeatures::Status::kPenetrating ? 1 : 0;
  }
  EXPECT_GT(penetrating, 0);
  EXPECT_LT(penetrating, 240);
}

TEST(ClosestFeatures, IterationCapIsReportedAsAFailureStatus) {
  ClosestFeaturesOptions options;
  options.max_steps = 0;
  const ClosestFeatures r = FindClosestFeatures(*Cube().tracked, At(0, 0, 0), *Cube().tracked,
                                                At(3, 0.5, 0.25), std::nullopt, options);
  EXPECT_EQ(r.status, ClosestFeatures::Status::kIterationCap);
}

TEST(ClosestFeatureTracker, CapFailuresAreCountedAndDescribedForARegressionTest) {
  ClosestFeaturesOptions options;
  options.max_steps = 0;
  ClosestFeatureTracker tracker(*Cube().tracked, *Cube().tracked, options);
  EXPECT_TRUE(tracker.last_failure().empty());
  tracker.Update(At(0, 0, 0), At(3, 0.1, 1.0 / 3.0));
  EXPECT_EQ(tracker.iteration_cap_failures(), 1u);
  const std::string& text = tracker.last_failure();
  EXPECT_NE(text.find("0.33333333333333331"), std::string::npos) << text;  // 17 digits
  EXPECT_NE(text.find("PolygonMesh{.vertices = {{"), std::string::npos) << text;
  EXPECT_NE(text.find("start = cold"), std::string::npos) << text;
}

TEST(ClosestFeatures, AgreesWithBruteForceOnRandomAndDegeneratePairs) {
  const testing::OracleFigures figures = testing::RunOracleCheck(/*seed=*/20261122, 3000);
  testing::PrintFigures("fast brute-force check", figures);
  testing::ExpectFiguresInRange(figures);
}

}  // namespace
}  // namespace sparsedyn
