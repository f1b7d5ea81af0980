// SPDX-License-Identifier: MIT
// ContactFromFeatures on boxes placed by hand, with the features found by FindClosestFeatures:
// the contact region (point, segment, polygon) against areas and vertices worked out on paper.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "dynamics/rigid_collision.hpp"
#include "rigid_test_bodies.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {
namespace {

// Contact tolerance of these unit-size scenes; the separations tested are far below it.
constexpr double kTolerance = 1e-9;
// Positions of region vertices: a few round-offs of O(1) coordinates.
constexpr double kPointTolerance = 1e-9;

TrackedPolyhedron Box(double half) {
  return TrackedPolyhedron(
      std::make_shared<const ConvexPolyhedron>(*MakeBox(Vec3::Constant(half))));
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

// Uniform random unit vector from our own stream (see test::RandomRotation).
Vec3 RandomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

TEST(ContactFromFeatures, CubeOnCubeFaceGivesTheOverlapRectangle) {
  const TrackedPolyhedron a = Box(1.0), b = Box(1.0);
  for (const double s : kSeparations) {
    SCOPED_TRACE(s);
    const ContactGeometry c = Contact(a, At(Vec3::Zero()), b, At(Vec3(1.2, 0.5, 2.0 + s)));
    EXPECT_LT((c.normal - Vec3::UnitZ()).norm(), 1e-15);
    EXPECT_NEAR(c.distance, s, 1e-15);
    EXPECT_NEAR(PolygonArea(c), 0.8 * 1.5, 1e-12);
    const double z = 1.0 + s / 2;
    ExpectSamePoints(c.points,
                     {Vec3(0.2, -0.5, z), Vec3(1, -0.5, z), Vec3(1, 1, z), Vec3(0.2, 1, z)});
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
    const ContactGeometry c =
        Contact(a, At(Vec3::Zero()), b,
                At(Vec3(0.8, 0, 1 + 0.5 * std::sqrt(2.0) + s), Turn(M_PI / 4, Vec3::UnitX())));
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
    const ContactGeometry c = Contact(a, At(Vec3::Zero(), Turn(M_PI / 4, Vec3::UnitX())), b,
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
    const ContactGeometry point = Contact(
        a, At(Vec3::Zero()), b, At(Vec3(0, 0, 1 + s) - Vec3(0, 0, lowest.z()), tilted), 1e-3);
    ASSERT_EQ(point.points.size(), 1u);
    EXPECT_NEAR(point.points[0].x(), lowest.x(), 1e-9);
    EXPECT_NEAR(point.points[0].y(), lowest.y(), 1e-9);

    const ContactGeometry flat =
        Contact(a, At(Vec3::Zero()), b, At(Vec3(0, 0, 1.5 + s), Turn(1e-10, Vec3(1, 2, 0))));
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

int VertexAt(const ConvexPolyhedron& p, const Pose& X, const Vec3& world) {
  for (int v = 0; v < p.vertex_count(); ++v) {
    if ((X.ToWorld(p.vertex(v)) - world).norm() < 1e-12) return v;
  }
  ADD_FAILURE() << "no vertex at " << world.transpose();
  return 0;
}

int FaceAlong(const ConvexPolyhedron& p, const Vec3& normal) {
  for (int f = 0; f < p.face_count(); ++f) {
    if ((p.face(f).plane.normal - normal).norm() < 1e-12) return f;
  }
  ADD_FAILURE() << "no face along " << normal.transpose();
  return 0;
}

// The walk returns one of several equally close pairs; whichever lower-dimensional pair it
// names, the face-face region is found. B = [0.5, 2.5] x [-0.5, 1.5] x [1, 3] on A = [-1, 1]^3.
TEST(ContactFromFeatures, AnyOfTheEquallyClosePairsGivesTheFaceRegion) {
  const TrackedPolyhedron a = Box(1.0), b = Box(1.0);
  const ConvexPolyhedron& pa = a.polyhedron();
  const ConvexPolyhedron& pb = b.polyhedron();
  const Pose X_WA = At(Vec3::Zero()), X_WB = At(Vec3(1.5, 0.5, 2));
  const int a_corner = VertexAt(pa, X_WA, Vec3(1, 1, 1));
  const int a_edge_end = VertexAt(pa, X_WA, Vec3(1, -1, 1));
  int a_edge = -1;
  for (const int e : pa.VertexEdges(a_corner)) {
    if (pa.OtherVertex(e, a_corner) == a_edge_end) a_edge = e;
  }
  ASSERT_GE(a_edge, 0);
  const int b_corner = VertexAt(pb, X_WB, Vec3(0.5, -0.5, 1));
  struct Case {
    FeaturePair pair;
    Vec3 witness;
  };
  const Case cases[] = {
      {{FeatureId::Vertex(a_corner), FeatureId::Face(FaceAlong(pb, -Vec3::UnitZ()))},
       Vec3(1, 1, 1)},
      {{FeatureId::Face(FaceAlong(pa, Vec3::UnitZ())), FeatureId::Vertex(b_corner)},
       Vec3(0.5, -0.5, 1)},
      {{FeatureId::Edge(a_edge), FeatureId::Face(FaceAlong(pb, -Vec3::UnitZ()))}, Vec3(1, 0, 1)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(ToString(c.pair.a) + " / " + ToString(c.pair.b));
    ClosestFeatures f;
    f.status = ClosestFeatures::Status::kPenetrating;
    f.features = c.pair;
    f.point_a = f.point_b = c.witness;
    f.normal = Vec3(0.3, 0.1, 1).normalized();  // a poor witness normal must not matter
    const ContactGeometry g = ContactFromFeatures(pa, X_WA, pb, X_WB, f, kTolerance);
    EXPECT_LT((g.normal - Vec3::UnitZ()).norm(), 1e-15);
    EXPECT_NEAR(PolygonArea(g), 0.5 * 1.5, 1e-12);
    ExpectSamePoints(g.points,
                     {Vec3(0.5, -0.5, 1), Vec3(1, -0.5, 1), Vec3(1, 1, 1), Vec3(0.5, 1, 1)});
  }
}

// Corners that coincide (vertex-vertex, or an edge through the other's corner) at distance 0
// carry no witness normal; the separating face next to them gives it. B = [0, 1]^2 x [1, 2].
TEST(ContactFromFeatures, CoincidentCornersStillGiveTheFaceRegion) {
  const TrackedPolyhedron a = Box(1.0), b = Box(0.5);
  const ConvexPolyhedron& pa = a.polyhedron();
  const ConvexPolyhedron& pb = b.polyhedron();
  const Pose X_WA = At(Vec3::Zero()), X_WB = At(Vec3(0.5, 0.5, 1.5));
  const int a_corner = VertexAt(pa, X_WA, Vec3(1, 1, 1));
  const int b_corner = VertexAt(pb, X_WB, Vec3(1, 1, 1));
  int b_edge = -1;  // B's bottom edge from (1, 1, 1) to (0, 1, 1)
  for (const int e : pb.VertexEdges(b_corner)) {
    if ((X_WB.ToWorld(pb.vertex(pb.OtherVertex(e, b_corner))) - Vec3(0, 1, 1)).norm() < 1e-12) {
      b_edge = e;
    }
  }
  ASSERT_GE(b_edge, 0);
  for (const FeatureId fb : {FeatureId::Vertex(b_corner), FeatureId::Edge(b_edge)}) {
    SCOPED_TRACE(ToString(fb));
    ClosestFeatures f;
    f.status = ClosestFeatures::Status::kPenetrating;
    f.features = {FeatureId::Vertex(a_corner), fb};
    f.point_a = f.point_b = Vec3(1, 1, 1);
    f.normal = Vec3(1, 1, 1).normalized();  // the walk's guess: not a separating direction
    const ContactGeometry g = ContactFromFeatures(pa, X_WA, pb, X_WB, f, kTolerance);
    EXPECT_LT((g.normal - Vec3::UnitZ()).norm(), 1e-15);
    EXPECT_NEAR(PolygonArea(g), 1.0, 1e-12);
    EXPECT_EQ(g.points.size(), 4u);
  }
}

// Oracle for the overlap area of two convex polygons, by another method than clipping: the
// overlap's vertices are the corners of each inside the other and the crossings of their
// edges; sorted by angle about their mean they give the area by the shoelace formula.
double OverlapAreaOracle(const std::vector<Eigen::Vector2d>& p,
                         const std::vector<Eigen::Vector2d>& q) {
  using V2 = Eigen::Vector2d;
  auto cross = [](const V2& a, const V2& b) { return a.x() * b.y() - a.y() * b.x(); };
  auto inside = [&](const V2& x, const std::vector<V2>& poly) {  // counter-clockwise poly
    for (std::size_t i = 0; i < poly.size(); ++i) {
      if (cross(poly[(i + 1) % poly.size()] - poly[i], x - poly[i]) < 0) return false;
    }
    return true;
  };
  std::vector<V2> corners;
  for (const V2& x : p) {
    if (inside(x, q)) corners.push_back(x);
  }
  for (const V2& x : q) {
    if (inside(x, p)) corners.push_back(x);
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = 0; j < q.size(); ++j) {
      const V2 a = p[i], da = p[(i + 1) % p.size()] - a;
      const V2 b = q[j], db = q[(j + 1) % q.size()] - b;
      const double den = cross(da, db);
      if (den == 0) continue;
      const double s = cross(b - a, db) / den, t = cross(b - a, da) / den;
      if (s >= 0 && s <= 1 && t >= 0 && t <= 1) corners.push_back(a + s * da);
    }
  }
  if (corners.size() < 3) return 0;
  V2 mean = V2::Zero();
  for (const V2& x : corners) mean += x;
  mean /= static_cast<double>(corners.size());
  std::sort(corners.begin(), corners.end(), [&](const V2& a, const V2& b) {
    return std::atan2(a.y() - mean.y(), a.x() - mean.x()) <
           std::atan2(b.y() - mean.y(), b.x() - mean.x());
  });
  double area = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    area += cross(corners[i], corners[(i + 1) % corners.size()]);
  }
  return 0.5 * area;
}

// Random boxes resting flush on each other (B turned about the normal, shifted in the plane,
// the pair then turned and moved as a whole): the region's area equals the oracle's, and every
// region vertex lies on both touching faces.
TEST(ContactFromFeatures, RandomFlushBoxesAgreeWithTheOverlapOracle) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int regions = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 ha(0.3 + unit(rng), 0.3 + unit(rng), 0.3 + unit(rng));
    const Vec3 hb(0.3 + unit(rng), 0.3 + unit(rng), 0.3 + unit(rng));
    const TrackedPolyhedron a(std::make_shared<const ConvexPolyhedron>(*MakeBox(ha)));
    const TrackedPolyhedron b(std::make_shared<const ConvexPolyhedron>(*MakeBox(hb)));
    const double turn = 2 * M_PI * unit(rng);
    const Eigen::Vector2d shift(2 * (unit(rng) - 0.5) * (ha.x() + hb.x()),
                                2 * (unit(rng) - 0.5) * (ha.y() + hb.y()));
    const double s = kSeparations[trial % 3];
    const Eigen::Quaterniond q = test::RandomRotation(rng);
    const Vec3 t(unit(rng), unit(rng), unit(rng));
    const Pose X_WA = At(t, q);
    const Pose X_WB =
        At(t + q * Vec3(shift.x(), shift.y(), ha.z() + hb.z() + s), q * Turn(turn, Vec3::UnitZ()));
    SCOPED_TRACE(trial);
    const ContactGeometry c = Contact(a, X_WA, b, X_WB);

    // The oracle in A's frame: A's top face and B's bottom face (both counter-clockwise).
    std::vector<Eigen::Vector2d> top, bottom;
    const Eigen::Rotation2Dd r(turn);
    for (const Eigen::Vector2d& corner : {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1),
                                          Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1)}) {
      top.push_back(corner.cwiseProduct(ha.head<2>()));
      bottom.push_back(shift + r * corner.cwiseProduct(hb.head<2>()));
    }
    const double area = OverlapAreaOracle(top, bottom);
    if (area < 1e-6) continue;  // the faces meet at a corner or an edge only
    ++regions;
    EXPECT_LT((c.normal - q * Vec3::UnitZ()).norm(), 1e-12);
    EXPECT_NEAR(PolygonArea(c), area, 1e-9);
    for (const Vec3& p : c.points) {
      const Vec3 p_A = X_WA.ToBody(p);
      EXPECT_NEAR(p_A.z(), ha.z() + s / 2, 1e-12);
      EXPECT_LE((p_A.head<2>().cwiseAbs() - ha.head<2>()).maxCoeff(), 1e-9);
      const Vec3 p_B = X_WB.ToBody(p);
      EXPECT_NEAR(p_B.z(), -hb.z() - s / 2, 1e-12);
      EXPECT_LE((p_B.head<2>().cwiseAbs() - hb.head<2>()).maxCoeff(), 1e-9);
    }
  }
  EXPECT_GT(regions, 200);
}

// Random hulls moved into touching: the normal separates the two bodies and every contact
// point lies on both surfaces (point contacts, generic orientations).
TEST(ContactFromFeatures, RandomTouchingHullsGiveASeparatingNormal) {
  std::mt19937_64 rng(99);
  for (int trial = 0; trial < 500; ++trial) {
    const auto hull_a = RandomConvexPolyhedron(20 + static_cast<int>(rng() % 40), rng());
    const auto hull_b = RandomConvexPolyhedron(20 + static_cast<int>(rng() % 40), rng());
    ASSERT_TRUE(hull_a && hull_b);
    const TrackedPolyhedron a(std::make_shared<const ConvexPolyhedron>(*hull_a));
    const TrackedPolyhedron b(std::make_shared<const ConvexPolyhedron>(*hull_b));
    const Pose X_WA = At(Vec3::Zero(), test::RandomRotation(rng));
    Pose X_WB = At(3.0 * RandomDirection(rng), test::RandomRotation(rng));
    const ClosestFeatures apart = FindClosestFeatures(a, X_WA, b, X_WB);
    X_WB.translation -= (apart.distance + kSeparations[trial % 3]) * apart.normal;
    SCOPED_TRACE(trial);
    const ContactGeometry c = Contact(a, X_WA, b, X_WB);
    double top_a = -kInfinity, bottom_b = kInfinity;
    for (const Vec3& v : a.polyhedron().vertices()) {
      top_a = std::max(top_a, c.normal.dot(X_WA.ToWorld(v)));
    }
    for (const Vec3& v : b.polyhedron().vertices()) {
      bottom_b = std::min(bottom_b, c.normal.dot(X_WB.ToWorld(v)));
    }
    EXPECT_NEAR(bottom_b - top_a, kSeparations[trial % 3], 1e-9);
    ASSERT_FALSE(c.points.empty());
    for (const Vec3& p : c.points) {
      EXPECT_NEAR(c.normal.dot(p), 0.5 * (top_a + bottom_b), 1e-9);
    }
  }
}

}  // namespace
}  // namespace sparsedyn
