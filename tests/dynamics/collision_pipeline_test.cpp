// SPDX-License-Identifier: MIT
// The two steps together, as the World uses them: random hulls moved into touching, their
// contact from the closest features, then the impulse. Checks the physics of the whole.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <random>

#include "dynamics/rigid_collision.hpp"
#include "rigid_test_bodies.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {
namespace {

using namespace test;  // NOLINT(google-build-using-namespace): test helpers

constexpr double kTolerance = 1e-9;  // contact tolerance of these unit-size scenes

Body ShapeBody(const ConvexPolyhedron& shape, const Pose& X, std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  const Eigen::Matrix3d r = X.rotation.toRotationMatrix();
  Body body =
      MakeBody(shape.volume(), r * shape.inertia() * r.transpose(), X.ToWorld(shape.centroid()));
  body.state.velocity = Vec3(g(rng), g(rng), g(rng));
  body.state.angular_velocity = Vec3(g(rng), g(rng), g(rng));
  return body;
}

TEST(CollisionPipeline, TouchingHullsCollideElasticallyAndSeparateEverywhere) {
  std::mt19937_64 rng(31337);
  int collisions = 0, regions = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // Boxes (flush contacts likely) or random hulls (point contacts).
    const bool boxes = trial % 2 == 0;
    const auto make = [&] {
      return boxes ? MakeBox(Vec3(0.5, 0.7, 0.3))
                   : RandomConvexPolyhedron(20 + static_cast<int>(rng() % 40), rng());
    };
    const auto hull_a = make(), hull_b = make();
    ASSERT_TRUE(hull_a && hull_b);
    const TrackedPolyhedron a(std::make_shared<const ConvexPolyhedron>(*hull_a));
    const TrackedPolyhedron b(std::make_shared<const ConvexPolyhedron>(*hull_b));
    const Eigen::Quaterniond q = RandomRotation(rng);
    const Pose X_WA{q, Vec3::Zero()};
    // Boxes share their orientation, so faces meet flat; hulls are turned at random.
    Pose X_WB{boxes ? q : RandomRotation(rng), q * Vec3(0.3, -0.2, 2.0)};
    const ClosestFeatures apart = FindClosestFeatures(a, X_WA, b, X_WB);
    X_WB.translation -= apart.distance * apart.normal;
    const ClosestFeatures touching = FindClosestFeatures(a, X_WA, b, X_WB);
    const ContactGeometry contact =
        ContactFromFeatures(a.polyhedron(), X_WA, b.polyhedron(), X_WB, touching, kTolerance);

    Body ba = ShapeBody(a.polyhedron(), X_WA, rng), bb = ShapeBody(b.polyhedron(), X_WB, rng);
    const double energy = Energy(ba) + Energy(bb);
    const Vec3 momentum = Momentum(ba) + Momentum(bb);
    const Vec3 angular = AngularMomentum(ba) + AngularMomentum(bb);
    const RigidImpulseResult r = ApplyRigidImpulse(ba.state, bb.state, contact, {});
    SCOPED_TRACE(trial);
    collisions += r.rounds > 0;
    regions += r.rounds > 0 && contact.points.size() > 1;
    EXPECT_NEAR(Energy(ba) + Energy(bb), energy, 1e-12 * energy);
    EXPECT_LT((Momentum(ba) + Momentum(bb) - momentum).norm(), 1e-12 * (1 + momentum.norm()));
    EXPECT_LT((AngularMomentum(ba) + AngularMomentum(bb) - angular).norm(),
              1e-12 * (1 + angular.norm()));
    for (const Vec3& p : contact.points) {
      EXPECT_GE(NormalVelocity(ba, bb, p, contact.normal), -1e-9);
    }
  }
  EXPECT_GT(collisions, 100);
  EXPECT_GT(regions, 30);
}

}  // namespace
}  // namespace sparsedyn
