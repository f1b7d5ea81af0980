// SPDX-License-Identifier: MIT
// The walk against two independent implementations on the same poses: CGAL's Polytope_distance_d
// in exact arithmetic (Gmpzf) on the vertex sets, and FCL 0.7's distance query with the libccd
// GJK solver on fcl::Convex shapes.
#include <CGAL/Gmpzf.h>
#include <CGAL/Homogeneous.h>
#include <CGAL/Polytope_distance_d.h>
#include <CGAL/Polytope_distance_d_traits_3.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

#include "pair_generator.hpp"
#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

using Kernel = CGAL::Homogeneous<double>;
using Traits = CGAL::Polytope_distance_d_traits_3<Kernel, CGAL::Gmpzf, double>;
using PolytopeDistance = CGAL::Polytope_distance_d<Traits>;

// Exact distance between the hulls of A's vertices and B's vertices placed in A's frame (the
// placement is rounded to double once; everything after it is exact).
double CgalDistance(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Pose& X_WA,
                    const Pose& X_WB) {
  const Eigen::Matrix3d R_WA = X_WA.rotation.normalized().toRotationMatrix();
  const Eigen::Matrix3d R_AB = R_WA.transpose() * X_WB.rotation.normalized().toRotationMatrix();
  const Eigen::Vector3d p_AB = R_WA.transpose() * (X_WB.translation - X_WA.translation);
  std::vector<Kernel::Point_3> pa, pb;
  for (const Eigen::Vector3d& p : a.vertices()) pa.emplace_back(p.x(), p.y(), p.z());
  for (const Eigen::Vector3d& p : b.vertices()) {
    const Eigen::Vector3d q = R_AB * p + p_AB;
    pb.emplace_back(q.x(), q.y(), q.z());
  }
  PolytopeDistance distance(pa.begin(), pa.end(), pb.begin(), pb.end());
  const double squared = CGAL::to_double(distance.squared_distance_numerator()) /
                         CGAL::to_double(distance.squared_distance_denominator());
  return std::sqrt(std::max(0.0, squared));
}

std::shared_ptr<fcl::Convexd> FclConvex(const ConvexPolyhedron& poly) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  for (const Eigen::Vector3d& p : poly.vertices()) vertices->push_back(p);
  auto faces = std::make_shared<std::vector<int>>();
  for (int f = 0; f < poly.face_count(); ++f) {
    const auto loop = poly.FaceVertices(f);
    faces->push_back(static_cast<int>(loop.size()));
    faces->insert(faces->end(), loop.begin(), loop.end());
  }
  return std::make_shared<fcl::Convexd>(vertices, poly.face_count(), faces);
}

fcl::Transform3d FclPose(const Pose& X) {
  fcl::Transform3d transform = fcl::Transform3d::Identity();
  transform.linear() = X.rotation.normalized().toRotationMatrix();
  transform.translation() = X.translation;
  return transform;
}

// Pairs from the test generator except those translated by 1e6 (FCL works in world coordinates,
// where 1e6 leaves ~1e-10 of resolution: that would test FCL's frame, not its distance).
std::vector<testing::PlacedPair> PeerPairs(testing::PairGenerator& generator, int count) {
  std::vector<testing::PlacedPair> pairs;
  while (static_cast<int>(pairs.size()) < count) {
    testing::PlacedPair pair = generator.Next();
    if (pair.kind != "translated by 1e6") pairs.push_back(pair);
  }
  return pairs;
}

TEST(ClosestFeaturesPeers, AgreesWithCgalExactPolytopeDistance) {
  testing::PairGenerator generator(/*seed=*/777);
  // Exact arithmetic on the same double inputs: only the walk's round-off separates the two.
  constexpr double kTolerance = 1e-12;
  double worst = 0.0;
  int separated = 0;
  for (const testing::PlacedPair& pair : PeerPairs(generator, 300)) {
    SCOPED_TRACE(pair.Describe());
    const ClosestFeatures r =
        FindClosestFeatures(*pair.a->tracked, pair.X_WA, *pair.b->tracked, pair.X_WB);
    const double exact =
        CgalDistance(*pair.a->polyhedron, *pair.b->polyhedron, pair.X_WA, pair.X_WB);
    // CGAL's distance of overlapping hulls is 0; ours is minus the depth.
    const double ours = std::max(r.distance, 0.0);
    EXPECT_NEAR(ours, exact, kTolerance * pair.Diameter());
    worst = std::max(worst, std::abs(ours - exact) / pair.Diameter());
    separated += exact > 0.0 ? 1 : 0;
  }
  std::printf("CGAL exact: 300 pairs (%d separated), max difference %.3g x diameter\n", separated,
              worst);
  EXPECT_GT(separated, 100);
}

TEST(ClosestFeaturesPeers, AgreesWithFclLibccdDistanceOnSeparatedPairs) {
  // Floating-point traps paused (docs/reliability.md): FCL and
  // libccd compute with infinities inside (the peers' code, not ours).
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  testing::PairGenerator generator(/*seed=*/778);
  // FCL's GJK (libccd) stops when an iteration improves the distance by less than
  // DistanceRequest::distance_tolerance (1e-6 by default), so its answer is within about that of
  // the true distance, from above; 1e-5 x diameter leaves room for its termination test.
  constexpr double kFclTolerance = 1e-5;
  fcl::DistanceRequestd request;
  request.gjk_solver_type = fcl::GST_LIBCCD;
  double worst = 0.0;
  int compared = 0;
  for (const testing::PlacedPair& pair : PeerPairs(generator, 400)) {
    SCOPED_TRACE(pair.Describe());
    const ClosestFeatures r =
        FindClosestFeatures(*pair.a->tracked, pair.X_WA, *pair.b->tracked, pair.X_WB);
    // FCL reports a collision (min_distance -1) for touching shapes: compare clear gaps only.
    if (r.status != ClosestFeatures::Status::kSeparated || r.distance < 1e-6 * pair.Diameter()) {
      continue;
    }
    fcl::CollisionObjectd a(FclConvex(*pair.a->polyhedron), FclPose(pair.X_WA));
    fcl::CollisionObjectd b(FclConvex(*pair.b->polyhedron), FclPose(pair.X_WB));
    fcl::DistanceResultd result;
    fcl::distance(&a, &b, request, result);
    EXPECT_NEAR(result.min_distance, r.distance, kFclTolerance * pair.Diameter());
    worst = std::max(worst, std::abs(result.min_distance - r.distance) / pair.Diameter());
    ++compared;
  }
  std::printf("FCL+libccd: %d separated pairs, max difference %.3g x diameter\n", compared, worst);
  EXPECT_GT(compared, 150);
}

}  // namespace
}  // namespace sparsedyn
