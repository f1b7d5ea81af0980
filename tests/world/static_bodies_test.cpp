// SPDX-License-Identifier: MIT
// Static bodies (issue #36 part 3): fixed, of infinite mass, any shape. A sphere thrown at a
// static cube's face, edge and vertex, and at a static sphere, reflects as v' = v - (1 + e)(v.n)n
// at the closed-form time; a cube moving into a static sphere gets the closed-form impulse and
// spin; a cube dropped flat on a floor slab 200 times its size bounces back at sqrt(2 g h);
// pebbles on a 100 m slab keep their energy and never sink in; statics may touch at the start,
// are refused where they overlap, cannot be moved, and can be removed.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

std::shared_ptr<const ConvexPolyhedron> Box(const Vec3& half) {
  return std::make_shared<const ConvexPolyhedron>(MakeBox(half).value());
}

BodyDef Static(BodyDef def) {
  def.is_static = true;
  return def;
}

struct Shot {
  const char* what;
  Vec3 direction;  // unit, the sphere's motion
  Vec3 point;      // where it hits the cube
};

TEST(StaticBodies, ASphereReflectsOffAStaticCubeFaceEdgeAndVertex) {
  const double speed = 2.0, radius = 0.25, e = 0.7;
  const std::vector<Shot> shots = {
      {"face", Vec3(1, 0, 0), Vec3(-0.5, 0.1, -0.2)},
      {"edge", Vec3(1, 1, 0).normalized(), Vec3(-0.5, -0.5, 0.1)},
      {"vertex", Vec3(1, 1, 1).normalized(), Vec3::Constant(-0.5)},
      {"face, slanting", Vec3(1, 0.3, 0).normalized(), Vec3(-0.5, 0.0, 0.0)},
  };
  for (const Shot& shot : shots) {
    SCOPED_TRACE(shot.what);
    World world;
    BodyDef cube;
    cube.shape = Box(Vec3::Constant(0.5));
    const BodyId cube_id = world.AddBody(Static(cube)).value();
    BodyDef ball;
    ball.radius = radius;
    // The face's normal is -x for every shot here but the edge and vertex ones.
    const Vec3 n = shot.what[0] == 'f' ? Vec3(-1, 0, 0) : -shot.direction;
    const double approach = -shot.direction.dot(n);  // cos of the angle to the normal
    ball.position = shot.point + radius * n - (2.0 / approach) * shot.direction;
    ball.velocity = speed * shot.direction;
    ball.restitution = e;
    const BodyId ball_id = world.AddBody(ball).value();
    std::vector<CollisionEvent> hits;
    world.OnCollision([&](const CollisionEvent& c) { hits.push_back(c); });
    ASSERT_TRUE(world.AdvanceTo(4.0));
    ASSERT_EQ(hits.size(), 1u);
    const double touch = 2.0 / approach / speed;
    const double band = world.Settings().contact_tolerance * 2 * radius / (speed * approach);
    EXPECT_LE(hits[0].time, touch + 1e-12);
    EXPECT_GE(hits[0].time, touch - band - 1e-12);
    const Vec3 v = speed * shot.direction;
    const Vec3 reflected = v - (1 + e) * v.dot(n) * n;
    EXPECT_LE((world.StateAt(ball_id, 4.0).velocity - reflected).norm(), 1e-9);
    const BodyState still = world.StateAt(cube_id, 4.0);
    EXPECT_EQ(still.position, Vec3::Zero());
    EXPECT_EQ(still.velocity, Vec3::Zero());
    EXPECT_EQ(world.Stats().static_collisions, 1u);
    EXPECT_TRUE(world.Validate());
  }
}

TEST(StaticBodies, ASphereReflectsOffAStaticSphere) {
  World world;
  BodyDef post;
  post.radius = 0.5;
  world.AddBody(Static(post)).value();
  BodyDef ball;
  ball.radius = 0.3;
  const Vec3 n = Vec3(-1, 0.4, 0.2).normalized();  // from the post's centre at contact
  const Vec3 v(3, 0, 0);
  // At t = 1 the ball touches the post with its centre at 0.8 n.
  ball.position = 0.8 * n - v;
  ball.velocity = v;
  const BodyId id = world.AddBody(ball).value();
  ASSERT_TRUE(world.AdvanceTo(2.0));
  ASSERT_EQ(world.Stats().collisions, 1u);
  EXPECT_LE((world.StateAt(id, 2.0).velocity - (v - 2 * v.dot(n) * n)).norm(), 1e-9);
}

TEST(StaticBodies, ACubeHittingAStaticSphereGetsTheClosedFormImpulseAndSpin) {
  World world;
  BodyDef post;
  post.radius = 0.25;
  post.position = Vec3(1.0, 0.2, 0.1);  // the cube's +x face meets it at (0.75, 0.2, 0.1)
  world.AddBody(Static(post)).value();
  BodyDef cube;
  cube.shape = Box(Vec3::Constant(0.25));
  cube.mass = 2.0;
  cube.position = Vec3(-1.5, 0, 0);
  cube.velocity = Vec3(1, 0, 0);
  cube.restitution = 0.5;
  const BodyId id = world.AddBody(cube).value();
  // The face reaches the sphere at t = 2; just after (the spinning cube may swing into it again
  // later).
  ASSERT_TRUE(world.AdvanceTo(2.001));
  ASSERT_EQ(world.Stats().collisions, 1u);
  // j = (1 + e) u / (1/m + |r x n|^2 / I), n = -x on the cube, r from its centre.
  const Vec3 n(-1, 0, 0), r(0.25, 0.2, 0.1);
  const double m = 2.0, inertia = m * (0.5 * 0.5 + 0.5 * 0.5) / 12;
  const Vec3 rn = r.cross(n);
  const double j = 1.5 * 1.0 / (1 / m + rn.squaredNorm() / inertia);
  const BodyState s = world.StateAt(id, 2.001);
  EXPECT_LE((s.velocity - (Vec3(1, 0, 0) + (j / m) * n)).norm(), 1e-9) << s.velocity.transpose();
  EXPECT_LE((s.angular_velocity - (j / inertia) * rn).norm(), 1e-9)
      << s.angular_velocity.transpose();
}

TEST(StaticBodies, ACubeDroppedFlatOnAFloorSlabBouncesBack) {
  WorldSettings settings;
  settings.gravity = Vec3(0, 0, -9.81);
  World world(settings);
  BodyDef floor;
  floor.shape = Box(Vec3(50, 50, 0.5));  // 100 m wide, its top at z = 0
  floor.position = Vec3(0, 0, -0.5);
  world.AddBody(Static(floor)).value();
  BodyDef cube;
  cube.shape = Box(Vec3::Constant(0.25));
  const double h = 1.0;
  cube.position = Vec3(3, -2, 0.25 + h);
  const BodyId id = world.AddBody(cube).value();
  const double fall = std::sqrt(2 * h / 9.81);
  ASSERT_TRUE(world.AdvanceTo(1.5 * fall));
  EXPECT_EQ(world.Stats().collisions, 1u);
  // Bounced at t = fall with the speed it arrived with: now at h - g (t - fall)^2 / 2 below
  // the top of its flight... going up at sqrt(2 g h) - g (t - fall).
  const BodyState s = world.StateAt(id, 1.5 * fall);
  EXPECT_NEAR(s.velocity.z(), std::sqrt(2 * 9.81 * h) - 9.81 * 0.5 * fall, 1e-7);
  EXPECT_LE(s.angular_velocity.norm(), 1e-9) << "a flat landing turns nothing";
  EXPECT_LE(std::abs(s.velocity.x()) + std::abs(s.velocity.y()), 1e-12);
  ASSERT_TRUE(world.AdvanceTo(4.5 * fall));
  EXPECT_EQ(world.Stats().collisions, 2u);
  EXPECT_TRUE(world.Validate());
}

TEST(StaticBodies, PebblesOnAHundredMetreSlabKeepTheirEnergyAndNeverSinkIn) {
  WorldSettings settings;
  settings.gravity = Vec3(0, 0, -9.81);
  World world(settings);
  BodyDef floor;
  floor.shape = Box(Vec3(50, 50, 0.5));
  floor.position = Vec3(0, 0, -0.5);
  floor.friction = 0.5;
  world.AddBody(Static(floor)).value();
  std::vector<BodyId> pebbles;
  for (int k = 0; k < 200; ++k) {
    BodyDef pebble;
    pebble.radius = 0.01;
    pebble.position = Vec3(0.05 * (k % 20), 0.05 * (k / 20), 0.1 + 0.013 * (k % 7));
    pebble.velocity = Vec3(0.1 * std::sin(k), 0.1 * std::cos(3 * k), 0.2 * std::sin(7 * k));
    pebble.angular_velocity = Vec3(0, 0, 0);
    if (k % 3 == 0) pebble.shape = Box(Vec3(0.006, 0.005, 0.004));  // polyhedral pebbles too
    pebbles.push_back(world.AddBody(pebble).value());
  }
  const auto energy = [&] {
    double potential = 0;
    for (const BodyId id : pebbles) {
      const BodyState s = world.StateAt(id, world.Time());
      potential += s.mass * 9.81 * s.position.z();
    }
    return world.KineticEnergy() + potential;
  };
  const double e0 = energy();
  for (int step = 1; step <= 5; ++step) {
    ASSERT_TRUE(world.AdvanceTo(0.2 * step));
    EXPECT_TRUE(world.Validate()) << "at t = " << world.Time();
    EXPECT_NEAR(energy(), e0, 1e-9 * std::abs(e0) + 1e-12);
  }
  EXPECT_GE(world.Stats().static_collisions, 200u);
  EXPECT_LE(world.MaxPenetration(), 1e-9 * 0.02 * 2);
}

TEST(StaticBodies, IsStaticAndIsPolyhedronTellEachBodysKind) {
  // Moving and static spheres and polyhedra and a god cube, added before and after the start
  // and after a removal that frees a slot (the kinds follow the handles, not the internal
  // order); a removed handle is none of them.
  World world;
  const BodyId slab = world.AddBody(Static({.shape = Box(Vec3(5, 5, 0.5))})).value();
  const BodyId ball = world.AddBody({.radius = 0.5, .position = {0, 0, 2}}).value();
  const BodyId pillar = world.AddBody(Static({.radius = 0.5, .position = {3, 0, 1.5}})).value();
  const BodyId cube =
      world.AddBody({.shape = Box(Vec3(0.5, 0.5, 0.5)), .position = {-3, 0, 2}}).value();
  ASSERT_TRUE(world.AdvanceTo(0.5));
  ASSERT_TRUE(world.RemoveBody(ball));
  const BodyId late = world.AddBody({.radius = 0.25, .position = {0, 3, 3}}).value();
  EXPECT_EQ(late.index, ball.index);
  BodyDef hand{.shape = Box(Vec3(0.5, 0.5, 0.5)), .position = {0, -3, 3}};
  hand.god = GodDef{1.0, {{.time = 1.0, .position = {0, -3, 4}}}};
  const BodyId god = world.AddBody(hand).value();
  const struct {
    BodyId id;
    bool is_static, is_god, is_polyhedron;
  } expected[] = {{slab, true, false, true},  {pillar, true, false, false},
                  {cube, false, false, true}, {late, false, false, false},
                  {god, false, true, true},   {ball, false, false, false}};
  for (const auto& e : expected) {
    SCOPED_TRACE("slot " + std::to_string(e.id.index) + " generation " +
                 std::to_string(e.id.generation));
    EXPECT_EQ(world.IsStatic(e.id), e.is_static);
    EXPECT_EQ(world.IsGod(e.id), e.is_god);
    EXPECT_EQ(world.IsPolyhedron(e.id), e.is_polyhedron);
  }
}

TEST(StaticBodies, MayTouchAtTheStartButNotOverlapAndNeverMove) {
  World world;
  BodyDef slab;
  slab.shape = Box(Vec3(5, 5, 0.5));
  slab.position = Vec3(0, 0, -0.5);
  const BodyId slab_id = world.AddBody(Static(slab)).value();
  BodyDef resting;
  resting.radius = 0.5;
  resting.position = Vec3(0, 0, 0.5);  // touching the top exactly
  resting.velocity = Vec3(1, 0, 0.5);
  const BodyId ball = world.AddBody(resting).value();
  BodyDef sunk = resting;
  sunk.position = Vec3(2, 0, 0.4);
  const Result<BodyId> refused = world.AddBody(sunk);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("overlaps static body 0"), std::string::npos)
      << refused.error().message;
  BodyDef moving_static = Static(resting);
  moving_static.position = Vec3(3, 3, 3);
  const Result<BodyId> moving = world.AddBody(moving_static);
  ASSERT_FALSE(moving);
  EXPECT_NE(moving.error().message.find("no velocity"), std::string::npos);
  BodyDef over = Static(slab);
  over.position = Vec3(1, 0, -0.7);
  EXPECT_FALSE(world.AddBody(over));
  const std::uint64_t hash = world.StateHash();
  const Status kick = world.SetVelocity(slab_id, Vec3(1, 0, 0));
  ASSERT_FALSE(kick);
  EXPECT_NE(kick.error().message.find("is static"), std::string::npos);
  EXPECT_FALSE(world.ApplyImpulse(slab_id, Vec3(1, 0, 0), Vec3::Zero()));
  EXPECT_FALSE(world.SetPose(slab_id, Vec3(0, 0, -3), Eigen::Quaterniond::Identity()));
  EXPECT_EQ(world.StateHash(), hash);
  ASSERT_TRUE(world.AdvanceTo(1.0));
  EXPECT_GT(world.StateAt(ball, 1.0).velocity.z(), 0.0) << "it moves off the slab";
  // Removed, the slab no longer stops the ball coming down.
  ASSERT_TRUE(world.SetVelocity(ball, Vec3(0, 0, -1)));
  ASSERT_TRUE(world.RemoveBody(slab_id));
  EXPECT_FALSE(world.IsValid(slab_id));
  ASSERT_TRUE(world.AdvanceTo(3.0));
  EXPECT_LT(world.StateAt(ball, 3.0).position.z(), 0.0);
  EXPECT_EQ(world.BodyCount(), 1u);

  WorldSettings periodic;
  periodic.container = Container::PeriodicBox(Vec3::Zero(), Vec3::Constant(10));
  World torus(periodic);
  BodyDef post;
  post.position = Vec3::Constant(5);
  const Result<BodyId> in_torus = torus.AddBody(Static(post));
  ASSERT_FALSE(in_torus);
  EXPECT_NE(in_torus.error().message.find("periodic"), std::string::npos);
}

TEST(StaticBodies, ASlabWiderThanTheWalledBoxIsTheFloor) {
  // A 100 m slab in a 4 m box: it reaches beyond the walls, and a ball dropped from 1 m above
  // its top bounces off it at sqrt(2 g h), never reaching the wall below it.
  WorldSettings settings;
  settings.container = Container::WalledBox(Vec3(-2, -2, 0), Vec3(2, 2, 4));
  settings.gravity = Vec3(0, 0, -9.81);
  World world(settings);
  BodyDef slab;
  slab.shape = Box(Vec3(50, 50, 0.5));
  slab.position = Vec3(0, 0, 0.5);
  ASSERT_TRUE(world.AddBody(Static(slab)));
  BodyDef ball;
  ball.radius = 0.25;
  ball.position = Vec3(0.3, 0.1, 2.25);
  const BodyId id = world.AddBody(ball).value();
  std::vector<CollisionEvent> hits;
  world.OnCollision([&](const CollisionEvent& c) { hits.push_back(c); });
  const double fall = std::sqrt(2 * 1.0 / 9.81);
  ASSERT_TRUE(world.AdvanceTo(fall + 0.01));
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_EQ(hits[0].wall, -1) << "the slab, not the wall";
  EXPECT_NEAR(hits[0].time, fall, 1e-8);
  EXPECT_NEAR(world.StateAt(id, hits[0].time).velocity.z(), 9.81 * fall, 1e-7);
  EXPECT_TRUE(world.Validate());
}

}  // namespace
}  // namespace sparsedyn
