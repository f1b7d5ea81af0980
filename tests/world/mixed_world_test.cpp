// SPDX-License-Identifier: MIT
// Mixed worlds (issue #36 part 1): spheres and convex polyhedra in one World. A sphere thrown at
// a free cube's face, edge and vertex meets it at the closed-form time and leaves with the
// closed-form impulse (with the cube's rotation); random mixed scenes keep energy, momentum and
// angular momentum (elastic, frictionless), or momentum and angular momentum with friction, and
// stay apart; bodies of both kinds are refused where they would overlap.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"
#include "world/polyhedra_scene.hpp"

namespace sparsedyn {
namespace {

struct Throw {
  const char* what;
  Vec3 direction;  // unit: the sphere moves along it at kSpeed
  Vec3 point;      // the cube's point it hits
};

constexpr double kSpeed = 2.0, kRadius = 0.25, kHalf = 0.5;

// A 1 m cube of mass M at the origin, at rest, and a sphere of mass m thrown at `point` from
// 2 m away along `direction`, restitution e.
TEST(MixedWorld, ASphereHitsACubeFaceEdgeAndVertexAsTheClosedFormSays) {
  const double m = 0.7, M = 2.5, e = 0.8;
  const std::vector<Throw> throws = {
      {"face", Vec3(1, 0, 0), Vec3(-kHalf, 0.1, -0.2)},
      {"edge", Vec3(1, 1, 0).normalized(), Vec3(-kHalf, -kHalf, 0.1)},
      {"vertex", Vec3(1, 1, 1).normalized(), Vec3::Constant(-kHalf)},
  };
  for (const Throw& shot : throws) {
    SCOPED_TRACE(shot.what);
    // The centre 2 m + the radius from the point, in the point's zone of the cube.
    const Vec3 start = shot.point - (2.0 + kRadius) * shot.direction;
    World world;
    BodyDef cube;
    cube.shape = std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3::Constant(kHalf)).value());
    cube.mass = M;
    cube.restitution = 1.0;
    const BodyId cube_id = world.AddBody(cube).value();
    BodyDef ball;
    ball.radius = kRadius;
    ball.position = start;
    ball.velocity = kSpeed * shot.direction;
    ball.mass = m;
    ball.restitution = e;
    const BodyId ball_id = world.AddBody(ball).value();
    std::vector<CollisionEvent> collisions;
    world.OnCollision([&](const CollisionEvent& c) { collisions.push_back(c); });
    ASSERT_TRUE(world.AdvanceTo(3.0));
    ASSERT_EQ(collisions.size(), 1u);

    // The time: the gap closes at kSpeed from 2 m; the contact is reported inside the band.
    const double band = world.Settings().contact_tolerance * (kRadius + cube.shape->bounding_radius());
    const double touch = 2.0 / kSpeed;
    EXPECT_LE(collisions[0].time, touch + 1e-12);
    EXPECT_GE(collisions[0].time, touch - band / kSpeed - 1e-12);

    // The impulse: n from the cube to the sphere, through the sphere's centre (no torque on it).
    const Vec3 n = -shot.direction;
    const Vec3 r = shot.point;  // from the cube's centre
    const double inertia = M / 6.0;  // a 1 m cube about any axis through its centre
    const Vec3 rn = r.cross(n);
    const double k = 1 / m + 1 / M + rn.squaredNorm() / inertia;
    const double j = (1 + e) * kSpeed / k;  // along n, on the sphere
    const Vec3 v_ball = kSpeed * shot.direction + (j / m) * n;
    const Vec3 v_cube = -(j / M) * n;
    const Vec3 w_cube = -(j / inertia) * rn;
    const BodyState b = world.StateAt(ball_id, 3.0), c = world.StateAt(cube_id, 3.0);
    EXPECT_LE((b.velocity - v_ball).norm(), 1e-9) << b.velocity.transpose();
    EXPECT_LE((c.velocity - v_cube).norm(), 1e-9) << c.velocity.transpose();
    EXPECT_LE((c.angular_velocity - w_cube).norm(), 1e-9) << c.angular_velocity.transpose();
    EXPECT_LE(b.angular_velocity.norm(), 1e-12) << "a frictionless push turns no sphere";
    EXPECT_LE((collisions[0].normal.normalized().cwiseAbs() - n.cwiseAbs()).norm(), 1e-9);
    EXPECT_TRUE(world.Validate());
  }
}

struct Conservation {
  double energy_drift;  // relative
  double momentum_drift;
  double angular_drift;
  std::map<int, int> collisions_by_kind;  // 0 spheres, 1 mixed, 2 polyhedra
};

Conservation RunMixed(const testing::PolyhedraSceneOptions& options, double until) {
  World world = testing::MakePolyhedraWorld(options);
  Conservation result{};
  world.OnCollision([&](const CollisionEvent& c) {
    if (!c.b.valid()) return;
    const int kind = !testing::IsSphere(options, static_cast<int>(c.a.index)) +
                     !testing::IsSphere(options, static_cast<int>(c.b.index));
    ++result.collisions_by_kind[kind];
  });
  const double e0 = world.KineticEnergy();
  const Vec3 p0 = world.Momentum(), l0 = world.AngularMomentum();
  for (int step = 1; step <= 10; ++step) {
    EXPECT_TRUE(world.AdvanceTo(until * step / 10));
    EXPECT_TRUE(world.Validate()) << "at t = " << world.Time();
    const double e = world.KineticEnergy();
    if (options.restitution == 1.0 && options.friction == 0.0) {
      result.energy_drift = std::max(result.energy_drift, std::abs(e - e0) / e0);
    } else {
      EXPECT_LE(e, e0 * (1 + 1e-12)) << "energy gained by t = " << world.Time();
    }
    result.momentum_drift = std::max(result.momentum_drift, (world.Momentum() - p0).norm());
    result.angular_drift = std::max(result.angular_drift, (world.AngularMomentum() - l0).norm());
  }
  return result;
}

TEST(MixedWorld, ElasticFrictionlessKeepsEnergyMomentumAndAngularMomentum) {
  testing::PolyhedraSceneOptions options;
  options.n = 40;
  options.walls = false;
  options.spacing = 2.2;
  options.seed = 9;
  options.sphere_every = 2;
  const Conservation c = RunMixed(options, 20.0);
  EXPECT_GE(c.collisions_by_kind.count(1) ? c.collisions_by_kind.at(1) : 0, 5);
  EXPECT_GE(c.collisions_by_kind.count(0) ? c.collisions_by_kind.at(0) : 0, 1);
  EXPECT_GE(c.collisions_by_kind.count(2) ? c.collisions_by_kind.at(2) : 0, 1);
  EXPECT_LE(c.energy_drift, 1e-12);
  EXPECT_LE(c.momentum_drift, 1e-12 * options.n);
  EXPECT_LE(c.angular_drift, 1e-11 * options.n * 10);
}

TEST(MixedWorld, FrictionAndRestitutionKeepMomentumAndAngularMomentumAndLoseEnergy) {
  testing::PolyhedraSceneOptions options;
  options.n = 40;
  options.walls = false;
  options.spacing = 2.2;
  options.seed = 9;
  options.sphere_every = 2;
  options.restitution = 0.9;
  options.friction = 0.5;
  const Conservation c = RunMixed(options, 20.0);
  EXPECT_GE(c.collisions_by_kind.count(1) ? c.collisions_by_kind.at(1) : 0, 5);
  EXPECT_LE(c.momentum_drift, 1e-12 * options.n);
  EXPECT_LE(c.angular_drift, 1e-11 * options.n * 10);
}

TEST(MixedWorld, AWalledMixedBoxStaysApartAndInside) {
  testing::PolyhedraSceneOptions options;
  options.n = 64;
  options.spacing = 2.3;
  options.seed = 4;
  options.sphere_every = 2;
  options.spin = 2.0;
  const Conservation c = RunMixed(options, 30.0);
  EXPECT_GE(c.collisions_by_kind.count(1) ? c.collisions_by_kind.at(1) : 0, 20);
  EXPECT_LE(c.energy_drift, 1e-9);
}

TEST(MixedWorld, OverlapsOfEitherKindAreRefusedByName) {
  World world;
  BodyDef cube;
  cube.shape = std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3::Constant(kHalf)).value());
  ASSERT_TRUE(world.AddBody(cube));
  // A sphere inside the cube's bounding sphere but clear of the cube itself: accepted.
  BodyDef clear;
  clear.radius = 0.2;
  clear.position = Vec3(0.75, 0, 0);
  EXPECT_TRUE(world.AddBody(clear));
  // A sphere that reaches into the face: refused, naming the cube.
  BodyDef into;
  into.radius = 0.2;
  into.position = Vec3(0, 0.65, 0);
  const Result<BodyId> refused = world.AddBody(into);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("body 0"), std::string::npos) << refused.error().message;
  // A polyhedron placed over the accepted sphere: refused, naming it.
  BodyDef over = cube;
  over.position = Vec3(1.4, 0, 0);
  const Result<BodyId> over_sphere = world.AddBody(over);
  ASSERT_FALSE(over_sphere);
  EXPECT_NE(over_sphere.error().message.find("body 1"), std::string::npos)
      << over_sphere.error().message;
  BodyDef beside = cube;
  beside.position = Vec3(2.0, 0, 0);  // 0.05 m clear of the sphere at x = 0.95
  EXPECT_TRUE(world.AddBody(beside));
  EXPECT_TRUE(world.Validate());
}

}  // namespace
}  // namespace sparsedyn
