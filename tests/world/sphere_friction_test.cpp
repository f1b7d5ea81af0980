// SPDX-License-Identifier: MIT
// Spheres that rub (friction > 0): rotation is tracked and the impulse acts at the contact
// point with the spins of solid spheres (I = 2/5 m r^2), against closed forms and invariants.
#include <gtest/gtest.h>

#include <cmath>

#include "scenes/random.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

// A sphere without spin hits the floor obliquely (speed u along x, w down), elastic normal
// part. Rough enough, the contact point stops slipping: v_x' = 5/7 u and w_y' = v_x' / r (the
// classic result for a solid sphere). Smooth, it slips throughout: the tangential impulse is
// mu times the normal one, m (1 + e) w, so v_x' = u - mu (1 + e) w and w_y' = 5 mu (1 + e) w /
// (2 r).
TEST(SphereFriction, ABallHittingTheFloorSticksOrSlipsAsTheClosedFormSays) {
  const double r = 0.5, m = 2.0, u = 3.0, w = 1.0;
  for (const double mu : {5.0, 0.1}) {
    SCOPED_TRACE("mu " + std::to_string(mu));
    WorldSettings settings;
    settings.container = Container::WalledBox(Vec3::Zero(), Vec3::Constant(10));
    World world(settings);
    const BodyId ball = *world.AddBody(
        {.radius = r, .position = {2, 5, 1.5}, .velocity = {u, 0, -w}, .mass = m, .friction = mu});
    ASSERT_TRUE(world.AdvanceTo(1.5));  // the bounce is at t = 1
    EXPECT_EQ(world.Stats().wall_collisions, 1u);
    const BodyState s = world.StateAt(ball, 1.5);
    const bool sticks = mu == 5.0;
    const double vx = sticks ? 5.0 / 7.0 * u : u - mu * 2.0 * w;
    const double wy = sticks ? vx / r : 5.0 * mu * 2.0 * w / (2.0 * r);
    EXPECT_NEAR(s.velocity.x(), vx, 1e-12);
    EXPECT_NEAR(s.velocity.z(), w, 1e-12);
    EXPECT_NEAR(s.angular_velocity.y(), wy, 1e-12);
    EXPECT_NEAR(s.angular_velocity.x(), 0.0, 1e-12);
  }
}

// A gas of rubbing spheres in open space: momentum and angular momentum (orbits and spins) are
// kept to round-off, and the energy never rises.
TEST(SphereFriction, RubbingSpheresKeepMomentaAndNeverGainEnergy) {
  World world;
  scenes::Random random(17);
  for (int i = 0; i < 27; ++i) {
    const Vec3 at(i % 3, i / 3 % 3, i / 9);
    ASSERT_TRUE(world.AddBody({.radius = 0.3 + 0.1 * random.Uniform(),
                               .position = 1.5 * at,
                               .velocity = 0.5 * Vec3(1, 1, 1) - at * 0.5 +
                                           0.3 * Vec3(random.Normal(), random.Normal(), 0),
                               .angular_velocity = Vec3(random.Normal(), 0, random.Normal()),
                               .mass = 0.5 + random.Uniform(),
                               .friction = 0.2 + 0.5 * random.Uniform()}));
  }
  const Vec3 momentum = world.Momentum(), angular = world.AngularMomentum();
  double energy = world.KineticEnergy();
  for (double t = 0.5; t <= 6.0; t += 0.5) {
    ASSERT_TRUE(world.AdvanceTo(t));
    EXPECT_LE(world.KineticEnergy(), energy * (1 + 1e-14));
    energy = world.KineticEnergy();
  }
  EXPECT_GT(world.Stats().collisions, 20u);
  EXPECT_LT((world.Momentum() - momentum).norm(), 1e-12);
  EXPECT_LT((world.AngularMomentum() - angular).norm(), 1e-11);
}

}  // namespace
}  // namespace sparsedyn
