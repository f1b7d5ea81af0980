// SPDX-License-Identifier: MIT
// Drag beside static bodies and god objects (issue #36 parts 3, 5 and 7): a sphere with drag
// meets a static sphere or polyhedron on its true motion. Oracles: the closed form of linear
// drag and its contact times by bisection in long double (on a static sphere, a box's face and
// a box's edge), and dense sampling of the true states for grains settling on a table and a
// god object sweeping through them (no penetration beyond the contact band).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"
#include "support/linear_drag_oracle.hpp"

namespace sparsedyn {
namespace {

using testing::FallTime;

std::shared_ptr<const ConvexPolyhedron> Box(const Vec3& half_extents) {
  return std::make_shared<const ConvexPolyhedron>(MakeBox(half_extents).value());
}

struct Drop {
  World world;
  std::vector<CollisionEvent> events;
  BodyId ball;
};

// A sphere of radius 0.25 with linear drag c1 falling from rest at (x, 0, 6) onto `floor`.
std::unique_ptr<Drop> DropOnto(const BodyDef& floor, double x, double c1) {
  WorldSettings settings;
  settings.gravity = Vec3(0, 0, -9.81);
  auto drop = std::make_unique<Drop>(Drop{World(settings), {}, {}});
  drop->world.OnCollision([d = drop.get()](const CollisionEvent& e) { d->events.push_back(e); });
  EXPECT_TRUE(drop->world.AddBody(floor));
  drop->ball =
      *drop->world.AddBody({.radius = 0.25, .position = {x, 0, 6}, .drag = Drag{c1, 0}});
  return drop;
}

TEST(DragStatic, FallingOntoAStaticSphereMeetsItAtTheClosedFormTime) {
  const double c1 = 0.5;
  std::unique_ptr<Drop> drop =
      DropOnto({.radius = 1.0, .position = {0, 0, 1}, .is_static = true}, 0.0, c1);
  ASSERT_TRUE(drop->world.AdvanceTo(2.0));
  ASSERT_FALSE(drop->events.empty());
  // The centre 1 + 0.25 above the static's centre at height 1: at height 2.25.
  const double expected = FallTime(6, -9.81, c1, 2.25, 2);
  EXPECT_NEAR(drop->events[0].time, expected, 1e-9);
  EXPECT_LE(drop->events[0].time, expected + 1e-15);  // never late
  EXPECT_EQ(drop->world.Stats().static_collisions, drop->events.size());
  EXPECT_TRUE(drop->world.Validate());
  // Restitution 1 against an infinite mass: the true speed just after is the speed just before,
  // (g / c1) (1 - e^(-c1 t)). The same World run to the collision's time shows it.
  const double t = drop->events[0].time;
  std::unique_ptr<Drop> again =
      DropOnto({.radius = 1.0, .position = {0, 0, 1}, .is_static = true}, 0.0, c1);
  ASSERT_TRUE(again->world.AdvanceTo(t));
  ASSERT_EQ(again->events.size(), 1u);
  const BodyState after = again->world.StateAt(again->ball, t);
  const double before = 9.81 / c1 * -std::expm1(-c1 * t);
  EXPECT_NEAR(after.velocity.z(), before, 1e-9 * before);
  EXPECT_NEAR(after.velocity.head<2>().norm(), 0.0, 1e-12);
}

TEST(DragStatic, FallingOntoAStaticBoxFaceAndEdgeMeetsItAtTheClosedFormTimes) {
  const double c1 = 0.3;
  // A static box of half extents (2, 2, 0.5) with its top face at z = 1.
  const BodyDef table{.shape = Box(Vec3(2, 2, 0.5)), .position = {0, 0, 0.5}, .is_static = true};
  {
    SCOPED_TRACE("face");
    std::unique_ptr<Drop> drop = DropOnto(table, 0.7, c1);
    ASSERT_TRUE(drop->world.AdvanceTo(2.0));
    ASSERT_FALSE(drop->events.empty());
    const double expected = FallTime(6, -9.81, c1, 1.25, 2);
    EXPECT_NEAR(drop->events[0].time, expected, 1e-9);
    EXPECT_LE(drop->events[0].time, expected + 1e-15);
    EXPECT_NEAR(drop->events[0].normal.z(), 1.0, 1e-9);
  }
  {
    SCOPED_TRACE("edge");
    // 0.15 beyond the edge x = 2: the centre touches the edge at 1 + sqrt(0.25^2 - 0.15^2).
    std::unique_ptr<Drop> drop = DropOnto(table, 2.15, c1);
    ASSERT_TRUE(drop->world.AdvanceTo(2.0));
    ASSERT_FALSE(drop->events.empty());
    const double expected = FallTime(6, -9.81, c1, 1.2L, 2);
    EXPECT_NEAR(drop->events[0].time, expected, 1e-9);
    EXPECT_LE(drop->events[0].time, expected + 1e-15);
    EXPECT_NEAR(drop->events[0].normal.x(), 0.6, 1e-6);
    EXPECT_NEAR(drop->events[0].normal.z(), 0.8, 1e-6);
  }
}

// Grains with linear and quadratic drag in a walled box over a static table and a static
// ball, and, when `god`, a god sphere sweeping through them: advanced in small steps, every
// grain's true state is outside every static (and the god object) to within the band.
void SettleAndSample(bool god) {
  WorldSettings settings;
  settings.gravity = Vec3(0, 0, -9.81);
  settings.container = Container::WalledBox(Vec3(-3, -3, 0), Vec3(3, 3, 6));
  settings.drag = Drag{0.4, 0.3};
  World world(settings);
  std::uint64_t hand_hits = 0;
  BodyId hand;
  world.OnCollision([&](const CollisionEvent& e) {
    if (e.a == hand || e.b == hand) ++hand_hits;
  });
  const double table_top = 1.0, ball_radius = 0.6;
  const Vec3 ball(1.2, 0.8, table_top + ball_radius + 0.1);  // the table is tilted
  ASSERT_TRUE(world.AddBody({.shape = Box(Vec3(2.5, 2.5, 0.25)), .position = {0, 0, 0.75},
                             .orientation = Eigen::Quaterniond(
                                 Eigen::AngleAxisd(0.05, Vec3::UnitX())),
                             .is_static = true}));
  ASSERT_TRUE(world.AddBody({.radius = ball_radius, .position = ball, .is_static = true}));
  const double hand_radius = 0.6;
  if (god) {
    hand = *world.AddBody({.radius = hand_radius,
                           .position = {-2.4, -2.4, 3.0},
                           .god = GodDef{20.0, {GodTarget{0.6, {2.4, 2.4, 3.0}, Vec3::Zero()},
                                                GodTarget{1.2, {-2.4, 2.4, 2.2}, Vec3::Zero()}}}});
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> xy(-2.2, 2.2), z(3.6, 5.6), speed(-2, 2);
  std::vector<BodyId> grains;
  const double r = 0.1;
  while (grains.size() < 60) {
    Result<BodyId> grain = world.AddBody({.radius = r,
                                          .position = {xy(rng), xy(rng), z(rng)},
                                          .velocity = {speed(rng), speed(rng), speed(rng)},
                                          .restitution = 0.9});
    if (grain) grains.push_back(*grain);  // a place that overlaps another is refused
  }
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.05, Vec3::UnitX()));
  const double band = 1e-6;
  for (int k = 1; k <= 1500; ++k) {
    const double t = 1e-3 * k;
    ASSERT_TRUE(world.AdvanceTo(t)) << t;
    const Vec3 hand_at = god ? world.StateAt(hand, t).position : Vec3::Zero();
    for (const BodyId g : grains) {
      const Vec3 p = world.StateAt(g, t).position;
      // In the table's frame the slab is |z - 0.75| <= 0.25 (where |x|, |y| <= 2.5).
      const Vec3 local = tilt.conjugate() * (p - Vec3(0, 0, 0.75));
      if (std::abs(local.x()) < 2.5 && std::abs(local.y()) < 2.5) {
        ASSERT_GT(std::abs(local.z()) - 0.25 - r, -band) << "grain in the table at " << t;
      }
      ASSERT_GT((p - ball).norm() - ball_radius - r, -band) << "grain in the ball at " << t;
      if (god) {
        ASSERT_GT((p - hand_at).norm() - hand_radius - r, -band) << "grain in the hand at " << t;
      }
    }
  }
  const Statistics& stats = world.Stats();
  EXPECT_GT(stats.static_collisions, 10u);
  EXPECT_GT(stats.drag_steps, 0u);
  if (god) {
    EXPECT_GE(hand_hits, 5u);
  }
  EXPECT_TRUE(world.Validate());
}

TEST(DragStatic, GrainsWithDragSettleOnAStaticTableNeverInsideIt) { SettleAndSample(false); }

TEST(DragStatic, AGodSphereSweepsThroughGrainsWithDragNeverInsideThem) { SettleAndSample(true); }

}  // namespace
}  // namespace sparsedyn
