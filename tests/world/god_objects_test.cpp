// SPDX-License-Identifier: MIT
// God objects (issue #36 part 7, App. H.3): bodies driven along a track with bounded
// acceleration, of infinite mass to every other body. Checked against closed forms and against
// their own plan (GodPlan, tested against brute force in tests/dynamics/god_plan_test.cpp): a
// rest-to-rest move takes the bang-bang minimum time 2 sqrt(d/A); a god moving at u sends a
// sphere at rest off at (1 + e) u (a wall moving at u); collisions never change its path; it
// sweeps through a gas without any overlap beyond the tolerance at any sampled time; two god
// objects and a god and a static pass through each other; pushing changes are refused with the
// state unchanged; a new track and a teleport are followed.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "dynamics/god_plan.hpp"
#include "events/event.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

BodyDef God(const Vec3& position, double max_acceleration, std::vector<GodTarget> track,
            const Vec3& velocity = Vec3::Zero()) {
  BodyDef def;
  def.position = position;
  def.velocity = velocity;
  def.god = GodDef{max_acceleration, std::move(track)};
  return def;
}

// A god object at constant velocity u along x from x0 (its track: the same line, far ahead).
BodyDef Coasting(double x0, double u, double radius = 0.5) {
  BodyDef def = God(Vec3(x0, 0, 0), 1.0, {GodTarget{100.0, Vec3(x0 + 100 * u, 0, 0), Vec3(u, 0, 0)}},
                    Vec3(u, 0, 0));
  def.radius = radius;
  return def;
}

TEST(GodObjects, RestToRestTakesTheBangBangMinimumTime) {
  // Asked to be 1 m away at once, it lags and arrives at 2 sqrt(d / A), accelerating at A for
  // the first half and braking for the second.
  const double d = 1.0, a = 2.0, arrival = 2 * std::sqrt(d / a);
  World world;
  const BodyId god = world.AddBody(God(Vec3::Zero(), a, {GodTarget{0.1, Vec3(d, 0, 0)}})).value();
  for (const double t : {0.3, arrival / 2, 1.0, arrival, 3.0}) {
    ASSERT_TRUE(world.AdvanceTo(t));
    const BodyState state = world.StateAt(god, t);
    const double x = t <= arrival / 2 ? 0.5 * a * t * t
                     : t <= arrival   ? d - 0.5 * a * (arrival - t) * (arrival - t)
                                      : d;
    const double v = t <= arrival / 2 ? a * t : t <= arrival ? a * (arrival - t) : 0.0;
    EXPECT_NEAR(state.position.x(), x, 1e-12) << "t = " << t;
    EXPECT_NEAR(state.velocity.x(), v, 1e-12) << "t = " << t;
    EXPECT_EQ(state.position.y(), 0.0);
    EXPECT_LE(state.acceleration.norm(), a * (1 + 1e-13));
    EXPECT_EQ(state.mass, kInfinity);
  }
  EXPECT_EQ(world.Stats().events_by_kind[static_cast<std::size_t>(EventKind::kBodyTimer)], 2u)
      << "two piece switches: the brake and the hold";
}

TEST(GodObjects, PushesASphereAsAMovingWallAndIsPushedByNone) {
  for (const double e : {1.0, 0.5}) {
    SCOPED_TRACE(e);
    const double u = 1.0;
    World world;
    const BodyId god = world.AddBody(Coasting(0.0, u)).value();
    BodyDef ball;
    ball.radius = 0.5;
    ball.position = Vec3(3, 0, 0);
    ball.restitution = e;
    ball.mass = 1e6;  // heavy: a god does not care
    const BodyId ball_id = world.AddBody(ball).value();
    std::vector<CollisionEvent> hits;
    world.OnCollision([&](const CollisionEvent& c) { hits.push_back(c); });
    ASSERT_TRUE(world.AdvanceTo(5.0));
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].time, 2.0, 1e-8);  // the gap of 2 m closed at 1 m/s
    EXPECT_NEAR(world.StateAt(ball_id, 5.0).velocity.x(), (1 + e) * u, 1e-12);
    const BodyState pusher = world.StateAt(god, 5.0);
    EXPECT_EQ(pusher.velocity, Vec3(u, 0, 0));
    EXPECT_NEAR(pusher.position.x(), 5.0 * u, 1e-12);
    // Energy and momentum are those of the bodies that can be pushed.
    EXPECT_NEAR(world.KineticEnergy(), 0.5 * 1e6 * (1 + e) * (1 + e) * u * u, 1e-6);
    EXPECT_NEAR(world.Momentum().x(), 1e6 * (1 + e) * u, 1e-6);
  }
}

TEST(GodObjects, ACubePushesACubeFaceOn) {
  auto cube = std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3::Constant(0.5)).value());
  World world;
  BodyDef pusher = Coasting(0.0, 2.0);
  pusher.shape = cube;
  world.AddBody(pusher).value();
  BodyDef free;
  free.shape = cube;
  free.position = Vec3(3, 0, 0);
  const BodyId free_id = world.AddBody(free).value();
  std::vector<CollisionEvent> hits;
  world.OnCollision([&](const CollisionEvent& c) { hits.push_back(c); });
  ASSERT_TRUE(world.AdvanceTo(3.0));
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].time, 1.0, 1e-8);
  const BodyState after = world.StateAt(free_id, 3.0);
  EXPECT_NEAR(after.velocity.x(), 4.0, 1e-9);
  EXPECT_LE(after.angular_velocity.norm(), 1e-9);
}

// A god sphere sweeping a walled box full of gas along a track of waypoints.
struct Sweep {
  World world{WorldSettings{Container::WalledBox(Vec3::Zero(), Vec3::Constant(10))}};
  BodyId god;
  std::vector<GodTarget> track;

  explicit Sweep(double restitution) {
    for (int k = 1; k <= 8; ++k) {
      // Far enough from the walls (1.2 m at the closest) that no ball is caught between.
      const double y = k % 2 == 0 ? 2.5 : 7.5;
      track.push_back(GodTarget{1.5 * k, Vec3(2 + 0.75 * k, y, 5), std::nullopt});
    }
    BodyDef hand = God(Vec3(2, 5, 5), 20.0, track);
    hand.radius = 0.8;
    god = world.AddBody(hand).value();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> place(0.3, 9.7), speed(-1, 1);
    int added = 0;
    while (added < 150) {
      BodyDef ball;
      ball.radius = 0.2;
      ball.position = Vec3(place(rng), place(rng), place(rng));
      ball.velocity = Vec3(speed(rng), speed(rng), speed(rng));
      ball.restitution = restitution;
      if (world.AddBody(ball)) ++added;
    }
  }
};

// The hand's switch at t = 5.25 falls on y = 5, a grid cell boundary: the switch and the cell
// crossing are due at the same instant, and the switch must not be lost behind the crossing.
TEST(GodObjects, SweepsThroughAGasWithoutPenetratingAndFollowsItsPlan) {
  // Elastic: an accelerating hand pushing an inelastic ball ahead of it brings it to rest on
  // the hand, a resting contact (issue #37), which the collapse guard and the crawl check end.
  {
    Sweep sweep(1.0);
    const GodPlan plan(0.0, Vec3(2, 5, 5), Vec3::Zero(), sweep.track, 20.0);
    std::uint64_t god_hits = 0;
    sweep.world.OnCollision([&](const CollisionEvent& c) {
      if (c.a == sweep.god || c.b == sweep.god) ++god_hits;
    });
    for (double t = 0.01; t <= 14.0; t += 0.01) {
      ASSERT_TRUE(sweep.world.AdvanceTo(t));
      ASSERT_TRUE(sweep.world.Validate()) << "t = " << t;
      const BodyState hand = sweep.world.StateAt(sweep.god, t);
      ASSERT_LE((hand.position - plan.StateAt(t).position).norm(), 1e-9) << "t = " << t;
    }
    EXPECT_GT(god_hits, 10u) << "the hand met the gas";
    EXPECT_LE(sweep.world.MaxPenetration(), 1e-9 * 2.0);
  }
}

TEST(GodObjects, GodObjectsAndStaticsPassThroughEachOther) {
  World world(WorldSettings{Container::WalledBox(Vec3::Constant(-10), Vec3::Constant(10))});
  const BodyId a = world.AddBody(Coasting(-4.0, 1.0)).value();
  const BodyId b = world.AddBody(Coasting(4.0, -1.0)).value();
  BodyDef slab;
  slab.shape = std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3(0.1, 3, 3)).value());
  slab.position = Vec3(0, 3.9, 0);  // across the path of a god at y = 4
  slab.is_static = true;
  world.AddBody(slab).value();
  BodyDef third = Coasting(-4.0, 1.0);
  third.position.y() = 4.0;
  third.god->track.front().position.y() = 4.0;
  const BodyId c = world.AddBody(third).value();
  std::uint64_t collisions = 0;
  world.OnCollision([&](const CollisionEvent&) { ++collisions; });
  for (double t = 0.5; t <= 9.0; t += 0.5) {
    ASSERT_TRUE(world.AdvanceTo(t));
    ASSERT_TRUE(world.Validate());
  }
  EXPECT_EQ(collisions, 0u);
  EXPECT_NEAR(world.StateAt(a, 9.0).position.x(), 5.0, 1e-12);
  EXPECT_NEAR(world.StateAt(b, 9.0).position.x(), -5.0, 1e-12);
  EXPECT_NEAR(world.StateAt(c, 9.0).position.x(), 5.0, 1e-12);
  EXPECT_GE(world.Stats().engagements_started, 1u) << "a and b overlapped on the way";
}

TEST(GodObjects, PushingChangesAreRefusedAndChangeNothing) {
  World world;
  const BodyId god = world.AddBody(Coasting(0.0, 1.0)).value();
  BodyDef ball;
  ball.position = Vec3(3, 0, 0);
  const BodyId ball_id = world.AddBody(ball).value();
  ASSERT_TRUE(world.AdvanceTo(0.5));
  const std::uint64_t hash = world.StateHash();
  const auto refused = [&](const Status& status, const char* what) {
    ASSERT_FALSE(status) << what;
    EXPECT_NE(status.error().message.find("is a god object"), std::string::npos)
        << status.error().message;
    EXPECT_EQ(world.StateHash(), hash) << what;
  };
  refused(world.SetVelocity(god, Vec3(1, 0, 0)), "SetVelocity");
  refused(world.SetAngularVelocity(god, Vec3(1, 0, 0)), "SetAngularVelocity");
  refused(world.ApplyImpulse(god, Vec3(1, 0, 0), Vec3::Zero()), "ApplyImpulse");
  refused(world.SetThrust(god, Vec3(1, 0, 0)), "SetThrust");
  const Status not_god = world.SetGodTrack(ball_id, GodDef{1.0, {}});
  ASSERT_FALSE(not_god);
  EXPECT_NE(not_god.error().message.find("is not a god object"), std::string::npos);
  for (const GodDef& bad :
       {GodDef{0.0, {}}, GodDef{-1.0, {}}, GodDef{std::nan(""), {}},
        GodDef{1.0, {GodTarget{0.2, Vec3::Zero(), std::nullopt}}},
        GodDef{1.0, {GodTarget{2.0, Vec3(std::nan(""), 0, 0), std::nullopt}}},
        GodDef{1.0, {GodTarget{2.0, Vec3::Zero(), std::nullopt},
                     GodTarget{1.0, Vec3::Zero(), std::nullopt}}}}) {
    const Status status = world.SetGodTrack(god, bad);
    ASSERT_FALSE(status);
    EXPECT_NE(status.error().message.find("god."), std::string::npos) << status.error().message;
    EXPECT_EQ(world.StateHash(), hash);
  }
  EXPECT_TRUE(world.IsGod(god));
  EXPECT_FALSE(world.IsGod(ball_id));
  EXPECT_FALSE(world.IsStatic(god));
}

TEST(GodObjects, BadDefinitionsAreRefusedByName) {
  struct Case {
    const char* what;
    BodyDef def;
    const char* names;
  };
  const auto god = [](double a, std::vector<GodTarget> track) {
    return God(Vec3::Zero(), a, std::move(track));
  };
  BodyDef spinning = god(1.0, {});
  spinning.angular_velocity = Vec3(0, 0, 1);
  BodyDef thrusting = god(1.0, {});
  thrusting.thrust = Vec3(0, 0, 1);
  BodyDef fixed = god(1.0, {});
  fixed.is_static = true;
  BodyDef enveloped = god(1.0, {});
  enveloped.envelope.e1 = 0.1;
  const std::vector<Case> cases = {
      {"A = 0", god(0.0, {}), "god.max_acceleration"},
      {"A = inf", god(kInfinity, {}), "god.max_acceleration"},
      {"A absurd", god(1e200, {}), "god.max_acceleration"},
      {"time NaN", god(1.0, {GodTarget{std::nan(""), Vec3::Zero(), std::nullopt}}),
       "god.track[0].time"},
      {"times back", god(1.0, {GodTarget{2.0, Vec3::Zero(), std::nullopt},
                               GodTarget{2.0, Vec3::Ones(), std::nullopt}}),
       "god.track[1].time"},
      {"velocity Inf", god(1.0, {GodTarget{2.0, Vec3::Zero(), Vec3(kInfinity, 0, 0)}}),
       "god.track[0].velocity"},
      {"position absurd", god(1.0, {GodTarget{2.0, Vec3(1e200, 0, 0), std::nullopt}}),
       "god.track[0]"},
      {"spin", spinning, "angular_velocity"},
      {"thrust", thrusting, "thrust"},
      {"static", fixed, "cannot be static"},
      {"envelope", enveloped, "envelope"},
  };
  for (const Case& c : cases) {
    World world;
    const Result<BodyId> added = world.AddBody(c.def);
    ASSERT_FALSE(added) << c.what;
    EXPECT_NE(added.error().message.find(c.names), std::string::npos)
        << c.what << ": " << added.error().message;
    EXPECT_EQ(world.BodyCount(), 0u);
  }
  World periodic(WorldSettings{Container::PeriodicBox(Vec3::Constant(-5), Vec3::Constant(5))});
  const Result<BodyId> added = periodic.AddBody(god(1.0, {}));
  ASSERT_FALSE(added);
  EXPECT_NE(added.error().message.find("periodic"), std::string::npos);
  // A track that starts before the clock.
  WorldSettings later;
  later.start_time = 5.0;
  World started(later);
  const Result<BodyId> early = started.AddBody(god(1.0, {GodTarget{4.0, Vec3::Ones(), std::nullopt}}));
  ASSERT_FALSE(early);
  EXPECT_NE(early.error().message.find("before the World's clock"), std::string::npos);
}

TEST(GodObjects, FollowsANewTrackAndATeleport) {
  World world;
  const BodyId god = world.AddBody(God(Vec3::Zero(), 2.0, {GodTarget{2.0, Vec3(4, 0, 0)}})).value();
  ASSERT_TRUE(world.AdvanceTo(1.0));
  ASSERT_EQ(world.GodTrackOf(god)->track.size(), 1u) << "the target is still ahead";
  // A new track from where it is: rest to rest 2 m along y, by t = 1 + 2 sqrt(2 / 2).
  const Vec3 here = world.StateAt(god, 1.0).position;
  const Vec3 v_here = world.StateAt(god, 1.0).velocity;
  ASSERT_TRUE(world.SetGodTrack(god, GodDef{2.0, {GodTarget{1.0, here + Vec3(0, 2, 0), Vec3::Zero()}}}));
  const GodPlan plan(1.0, here, v_here, std::vector<GodTarget>{GodTarget{1.0, here + Vec3(0, 2, 0), Vec3::Zero()}},
                     2.0);
  ASSERT_TRUE(world.AdvanceTo(plan.EndTime() + 1.0));
  EXPECT_LE((world.StateAt(god, world.Time()).position - (here + Vec3(0, 2, 0))).norm(), 1e-9);
  EXPECT_EQ(world.StateAt(god, world.Time()).velocity.norm(), 0.0);
  EXPECT_TRUE(world.GodTrackOf(god)->track.empty());
  // A teleport, then a target again: it goes on from the new place.
  ASSERT_TRUE(world.SetGodTrack(god, GodDef{2.0, {GodTarget{world.Time() + 10, Vec3(0, 0, 7), Vec3::Zero()}}}));
  ASSERT_TRUE(world.SetPose(god, Vec3(0, 0, 5), Eigen::Quaterniond::Identity()));
  EXPECT_EQ(world.StateAt(god, world.Time()).position, Vec3(0, 0, 5));
  ASSERT_TRUE(world.AdvanceTo(world.Time() + 10));
  EXPECT_LE((world.StateAt(god, world.Time()).position - Vec3(0, 0, 7)).norm(), 1e-9);
}

}  // namespace
}  // namespace sparsedyn
