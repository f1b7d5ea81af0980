// SPDX-License-Identifier: MIT
// ContactFromFeatures on boxes placed by hand, with the features found by FindClosestFeatures:
// the contact region (point, segment, polygon) against areas and vertices worked out on paper.
#include <cmath>
#include <memory>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "dynamics/rigid_collision.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {
namespace {

// Contact tolerance of these unit-size scenes; the separations tested are far below it.
constexpr double kTolerance = 1e-9;
// Positions of region vertices: a few round-offs of O(1) coordinates.
constexpr double kPointTolerance = 1e-9;

TrackedPolyhedron Box(double half) {
  return TrackedPolyhedron(std::make_shared<const ConvexPolyhedron>(
      *MakeBox(Vec3::Constant(half))));
}

Pose At(const Vec3& p, const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  return Pose{q, p};
}

Eigen::Quaterniond Turn(double angle, const Vec3& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

ContactGeometry Contact(const TrackedPolyhedron& a, const Pose& X_WA, const TrackedPolyhedron& b,
                        const Pose& X_WB, double tolerance = kTolerance) {
  const ClosestFeatures f = FindClosestFeatures(a, X_WA, b, X_WB);
  return ContactFromFeatures(a.polyhedron(), X_WA, b.polyhedron(), X_WB, f, tolerance);
}

double PolygonArea(const ContactGeometry& c) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    sum += c.points[i].cross(c.points[(i + 1) % c.points.size()]);
  }
  return 0.5 * std::abs(sum.dot(c.normal));
}

// Every expected point is a region vertex and there are no others.
void ExpectSamePoints(const std::vector<Vec3>& got, const std::vector<Vec3>& expected) {
  ASSERT_EQ(got.size(), expected.size());
  for (const Vec3& e : expected) {
    double nearest = kInfinity;
    for (const Vec3& g : got) nearest = std::min(nearest, (g - e).norm());
    EXPECT_LT(nearest, kPointTolerance) << "missing " << e.transpose();
  }
}

constexpr double kSeparations[] = {0.0, 1e-12, -1e-12};

TEST(ContactFromFeatures, CubeOnCubeFaceGivesTheOverlapRectangle) {
  const TrackedPolyhedron a = Box(1.0), b = Box(1.0);
  for (const double s : kSeparations) {
    SCOPED_TRACE(s);
    const ContactGeometry c = Contact(a, At(Vec3::Zero()), b, At(Vec3(1.2, 0.5, 2.0 + s)));
    EXPECT_LT((c.normal - Vec3::UnitZ()).norm(), 1e-15);
    EXPECT_NEAR(c.distance, s, 1e-15);
    EXPECT_NEAR(PolygonArea(c), 0.8 * 1.5, 1e-12);
    const double z = 1.0 + s / 2;
    ExpectSamePoints(c.points, {Vec3(0.2, -0.5, z), Vec3(1, -0.5, z), Vec3(1, 1, z),
                                Vec3(0.2, 1, z)});
  }
}

// B turned 45 degrees about z, centred over A's edge x = 1: the left half of the diamond
// |x - 1| + |y| <= sqrt(2), cut by |y| <= 1: area = int_{-1}^{1} (sqrt(2) - |y|) dy.
TEST(ContactFromFeatures, TurnedCubeOnCubeGivesTheClippedPentagon) {
  const TrackedPolyhedron a = Box(1.0), b = Box(1.0);
  const double r2 = std::sqrt(2.0);
  for (const double s : kSeparations) {
    SCOPED_TRACE(s);
    const ContactGeometry c =
        Contact(a, At(Vec3::Zero()), b, At(Vec3(1, 0, 2 + s), Turn(M_PI / 4, Vec3::UnitZ())));
    EXPECT_LT((c.normal - Vec3::UnitZ()).norm(), 1e-15);
    EXPECT_NEAR(PolygonArea(c), 2 * r2 - 1, 1e-12);
    const double z = 1.0 + s / 2;
    ExpectSamePoints(c.points, {Vec3(1, 1, z), Vec3(1, -1, z), Vec3(2 - r2, 1, z),
                                Vec3(2 - r2, -1, z), Vec3(1 - r2, 0, z)});
  }
}

// The same with both boxes turned and moved together: the region only depends on the pair.
TEST(ContactFromFeatures, FaceContactIsFrameIndependent) {
  const TrackedPolyhedron a = Box(1.0), b = Box(0.5);
  const Eigen::Quaterniond q = Turn(0.7, Vec3(1, -2, 0.5));
  const Vec3 shift(3, -1, 2);
  const ContactGeometry c = Contact(a, At(shift, q), b, At(shift + q * Vec3(0.8, 0.8, 1.5), q));
  EXPECT_LT((c.normal - q * Vec3::UnitZ()).norm(), 1e-12);
  EXPECT_NEAR(PolygonArea(c), 0.7 * 0.7, 1e-9);
  EXPECT_EQ(c.points.size(), 4u);
}

// B turned 45 degrees about x rests on its lowest edge (along x, from x = 0.3 to 1.3).
TEST(ContactFromFeatures, EdgeOnFaceGivesTheClippedSegment) {
  const TrackedPolyhedron a = Box(1.0), b = Box(0.5);
  for (const double s : kSeparations) {
    SCOPED_TRACE(s);
    const ContactGeometry c = Contact(a, At(Vec3::Zero()), b,
                                      At(Vec3(0.8, 0, 1 + 0.5 * std::sqrt(2.0) + s),
                                         Turn(M_PI / 4, Vec3::UnitX())));
    EXPECT_LT((c.normal - Vec3::UnitZ()).norm(), 1e-15);
    ExpectSamePoints(c.points, {Vec3(0.3, 0, 1 + s / 2), Vec3(1, 0, 1 + s / 2)});
  }
}

// A's top edge runs along x, B's bottom edge along y: they cross at one point.
TEST(ContactFromFeatures, CrossingEdgesGiveOnePoint) {
  const TrackedPolyhedron a = Box(1.0), b = Box(1.0);
  const double h = std::sqrt(2.0);
  for (const double s : kSeparations) {
    SCOPED_TRACE(s);
    const ContactGeometry c =
        Contact(a, At(Vec3::Zero(), Turn(M_PI / 4, Vec3::UnitX())), b,
                At(Vec3(0.1, 0.2, 2 * h + s), Turn(M_PI / 4, Vec3::UnitY())));
    EXPECT_LT((c.normal - Vec3::UnitZ()).norm(), 1e-12);
    ExpectSamePoints(c.points, {Vec3(0.1, 0, h + s / 2)});
  }
}

// B stands on one corner (its diagonal (1, 1, 1) turned to -z) above A's top face.
TEST(ContactFromFeatures, VertexOnFaceGivesThatVertex) {
  const TrackedPolyhedron a = Box(1.0), b = Box(0.5);
  const Eigen::Quaterniond q =
      Eigen::Quaterniond::FromTwoVectors(Vec3(1, 1, 1).normalized(), -Vec3::UnitZ());
  for (const double s : kSeparations) {
    SCOPED_TRACE(s);
    const ContactGeometry c =
        Contact(a, At(Vec3::Zero()), b, At(Vec3(0.3, -0.4, 1 + 0.5 * std::sqrt(3.0) + s), q));
    EXPECT_LT((c.normal - Vec3::UnitZ()).norm(), 1e-12);
    ExpectSamePoints(c.points, {Vec3(0.3, -0.4, 1 + s / 2)});
  }
}

// A face tilted by 1e-6 rad about a skew axis touches at one corner, even with a tolerance loose
// enough for the heights (1e-3); a tilt of 1e-10 rad is within the angular tolerance.
TEST(ContactFromFeatures, TiltBeyondTheAngularToleranceGivesAPoint) {
  const TrackedPolyhedron a = Box(1.0), b = Box(0.5);
  for (const double s : kSeparations) {
    SCOPED_TRACE(s);
    const Eigen::Quaterniond tilted = Turn(1e-6, Vec3(1, 2, 0));
    Vec3 lowest = Vec3::Constant(kInfinity);  // the corner the tilt lowers most
    for (const Vec3& corner : b.polyhedron().vertices()) {
      if ((tilted * corner).z() < lowest.z()) lowest = tilted * corner;
    }
    const ContactGeometry point =
        Contact(a, At(Vec3::Zero()), b, At(Vec3(0, 0, 1 + s) - Vec3(0, 0, lowest.z()), tilted),
                1e-3);
    ASSERT_EQ(point.points.size(), 1u);
    EXPECT_NEAR(point.points[0].x(), lowest.x(), 1e-9);
    EXPECT_NEAR(point.points[0].y(), lowest.y(), 1e-9);

    const ContactGeometry flat = Contact(a, At(Vec3::Zero()), b,
                                         At(Vec3(0, 0, 1.5 + s), Turn(1e-10, Vec3(1, 2, 0))));
    EXPECT_EQ(flat.points.size(), 4u);
    EXPECT_NEAR(PolygonArea(flat), 1.0, 1e-9);
  }
}

// Parallel edges of two boxes turned 45 degrees about x, B shifted along x: the overlap. The
// normal of parallel edges is any direction in both normal cones (here in the yz-plane).
TEST(ContactFromFeatures, ParallelEdgesGiveTheirOverlap) {
  const TrackedPolyhedron a = Box(1.0), b = Box(1.0);
  const double h = std::sqrt(2.0);
  const Eigen::Quaterniond q = Turn(M_PI / 4, Vec3::UnitX());
  for (const double s : kSeparations) {
    SCOPED_TRACE(s);
    const ContactGeometry c = Contact(a, At(Vec3::Zero(), q), b, At(Vec3(1.5, 0, 2 * h + s), q));
    EXPECT_NEAR(c.normal.x(), 0.0, 1e-12);
    EXPECT_GE(c.normal.z(), std::sqrt(0.5) - 1e-12);
    ExpectSamePoints(c.points, {Vec3(0.5, 0, h + s / 2), Vec3(1, 0, h + s / 2)});
  }
}

}  // namespace
}  // namespace sparsedyn
