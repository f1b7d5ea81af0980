// SPDX-License-Identifier: MIT
// Two-body cases through the whole World: event times, velocities after impact, walls, gravity.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

constexpr double kTimeTolerance = 1e-12;

struct Recorder {
  std::vector<CollisionEvent> events;
  void Attach(World& world) {
    world.OnCollision([this](const CollisionEvent& e) { events.push_back(e); });
  }
};

TEST(WorldTwoBody, HeadOnEqualMassesExchangeVelocitiesAtContactTime) {
  World world;
  Recorder recorder;
  recorder.Attach(world);
  const BodyId a = *world.AddBody({.radius = 1, .position = {0, 0, 0}, .velocity = {2, 0, 0}});
  const BodyId b = *world.AddBody({.radius = 1, .position = {10, 0, 0}, .velocity = {-2, 0, 0}});
  ASSERT_TRUE(world.AdvanceTo(5.0));
  ASSERT_EQ(recorder.events.size(), 1u);
  EXPECT_NEAR(recorder.events[0].time, 2.0, kTimeTolerance);
  EXPECT_LE(recorder.events[0].time, 2.0);
  EXPECT_NEAR(recorder.events[0].impulse, 4.0, 1e-12);  // m * dv = 1 * 4
  EXPECT_TRUE(world.StateAt(a, 5.0).velocity.isApprox(Vec3(-2, 0, 0), 1e-14));
  EXPECT_TRUE(world.StateAt(b, 5.0).velocity.isApprox(Vec3(2, 0, 0), 1e-14));
  EXPECT_NEAR(world.StateAt(a, 5.0).position.x(), 4.0 - 2.0 * 3.0, 1e-12);
}

TEST(WorldTwoBody, UnequalMassesConserveMomentumAndEnergy) {
  World world;
  const BodyId a =
      *world.AddBody({.radius = 0.5, .position = {0, 0, 0}, .velocity = {1, 0.3, 0}, .mass = 3.0});
  const BodyId b = *world.AddBody(
      {.radius = 0.7, .position = {4, 0.5, 0.1}, .velocity = {-1, 0, 0}, .mass = 0.5});
  const double energy = world.KineticEnergy();
  const Vec3 momentum = world.Momentum();
  ASSERT_TRUE(world.AdvanceTo(10.0));
  EXPECT_EQ(world.Stats().collisions, 1u);
  EXPECT_NEAR(world.KineticEnergy(), energy, 1e-14 * energy);
  EXPECT_TRUE(world.Momentum().isApprox(momentum, 1e-14));
  (void)a;
  (void)b;
}

TEST(WorldTwoBody, InelasticRestitutionScalesNormalRelativeVelocity) {
  World world;
  const BodyId a = *world.AddBody(
      {.radius = 1, .position = {0, 0, 0}, .velocity = {1, 0, 0}, .restitution = 0.5});
  const BodyId b = *world.AddBody({.radius = 1, .position = {3, 0, 0}, .restitution = 1.0});
  ASSERT_TRUE(world.AdvanceTo(2.0));
  const double separation_speed =
      world.StateAt(b, 2).velocity.x() - world.StateAt(a, 2).velocity.x();
  EXPECT_NEAR(separation_speed, 0.5, 1e-14);  // e = 0.5 * 1.0
}

TEST(WorldTwoBody, MissingSpheresNeverCollide) {
  World world;
  (void)*world.AddBody({.radius = 1, .position = {0, 0, 0}, .velocity = {1, 0, 0}});
  (void)*world.AddBody({.radius = 1, .position = {10, 2.5, 0}, .velocity = {-1, 0, 0}});
  ASSERT_TRUE(world.AdvanceTo(100.0));
  EXPECT_EQ(world.Stats().collisions, 0u);
}

TEST(WorldTwoBody, BallBouncesOnFloorUnderGravityAtAnalyticTimes) {
  // Floor z = 0 of a walled box; ball radius 0.5 dropped from z = 5.5 (fall height 5) under
  // g = 10: first impact at t = 1, then elastic bounces every 2 s.
  WorldSettings settings;
  settings.container = Container::WalledBox({-10, -10, 0}, {10, 10, 100});
  settings.gravity = {0, 0, -10};
  World world(settings);
  Recorder recorder;
  recorder.Attach(world);
  const BodyId ball = *world.AddBody({.radius = 0.5, .position = {0, 0, 5.5}});
  ASSERT_TRUE(world.AdvanceTo(6.5));
  ASSERT_EQ(recorder.events.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(recorder.events[k].time, 1.0 + 2.0 * k, 1e-11);
    EXPECT_EQ(recorder.events[k].wall, 4);  // the -z wall
  }
  EXPECT_NEAR(world.StateAt(ball, 6.5).position.z(), 0.5 + 10 * 0.5 - 5 * 0.25, 1e-10);
}

TEST(WorldTwoBody, ThrustingBodyCatchesRestingOne) {
  World world;
  Recorder recorder;
  recorder.Attach(world);
  (void)*world.AddBody(
      {.radius = 1, .position = {0, 0, 0}, .velocity = {1, 0, 0}, .thrust = {2, 0, 0}});
  (void)*world.AddBody({.radius = 1, .position = {10, 0, 0}});
  ASSERT_TRUE(world.AdvanceTo(3.0));
  ASSERT_GE(recorder.events.size(), 1u);
  EXPECT_NEAR(recorder.events[0].time, (-1 + std::sqrt(33.0)) / 2, 1e-12);
}

// The world starts with straight lines only (its fast paths); a body with a thrust of its own
// added afterwards must be predicted, and collide, on its parabola. In open space (AllPairs)
// and in a periodic box (the Grid, the gas's paths).
class ThrustAddedWhileRunning : public ::testing::TestWithParam<Container> {};

TEST_P(ThrustAddedWhileRunning, CatchesRestingBodyOnItsParabola) {
  WorldSettings settings;
  settings.container = GetParam();
  World world(settings);
  Recorder recorder;
  recorder.Attach(world);
  (void)*world.AddBody({.radius = 1, .position = {10, 0, 0}});
  (void)*world.AddBody({.radius = 1, .position = {0, 20, 0}, .velocity = {0.5, 0, 0}});
  ASSERT_TRUE(world.AdvanceTo(1.0));
  (void)*world.AddBody(
      {.radius = 1, .position = {0, 0, 0}, .velocity = {1, 0, 0}, .thrust = {2, 0, 0}});
  ASSERT_TRUE(world.AdvanceTo(4.0));
  ASSERT_GE(recorder.events.size(), 1u);
  EXPECT_NEAR(recorder.events[0].time, 1.0 + (-1 + std::sqrt(33.0)) / 2, 1e-12);
  EXPECT_TRUE(world.Validate());
}

INSTANTIATE_TEST_SUITE_P(WorldTwoBody, ThrustAddedWhileRunning,
                         ::testing::Values(Container::Open(),
                                           Container::PeriodicBox({-15, -15, -15}, {25, 25, 25})),
                         [](const ::testing::TestParamInfo<Container>& param_info) {
                           return param_info.param.kind == Container::Kind::kOpen ? "Open"
                                                                                  : "Periodic";
                         });

TEST(WorldTwoBody, EnvelopedBodiesEngageBeforeTheyCollide) {
  World world;
  Recorder recorder;
  recorder.Attach(world);
  const Envelope skin{.e0 = 0.5, .e1 = 0.1, .e2 = 0};
  (void)*world.AddBody(
      {.radius = 1, .position = {0, 0, 0}, .velocity = {1, 0, 0}, .envelope = skin});
  (void)*world.AddBody({.radius = 1, .position = {10, 0, 0}, .velocity = {-1, 0, 0}});
  ASSERT_TRUE(world.AdvanceTo(10.0));
  EXPECT_EQ(world.Stats().engagements_started, 1u);
  EXPECT_EQ(world.Stats().engagements_ended, 1u);
  ASSERT_EQ(recorder.events.size(), 1u);
  EXPECT_NEAR(recorder.events[0].time, 4.0, 1e-12);  // the bodies themselves: gap 8 at 2 m/s
}

TEST(WorldTwoBody, StaleTargetMakesActorPredictAgain) {
  // c aims at b, but a strikes b first: c's meeting is target-absent when it comes up.
  World world;
  (void)*world.AddBody({.radius = 0.5, .position = {-3, 0, 0}, .velocity = {2, 0, 0}});  // a
  (void)*world.AddBody({.radius = 0.5, .position = {0, 0, 0}});                          // b
  (void)*world.AddBody({.radius = 0.5, .position = {0, 5, 0}, .velocity = {0, -1, 0}});  // c
  ASSERT_TRUE(world.AdvanceTo(20.0));
  EXPECT_GE(world.Stats().stale_target_absent, 1u);
  EXPECT_TRUE(world.Validate());
}

}  // namespace
}  // namespace sparsedyn
