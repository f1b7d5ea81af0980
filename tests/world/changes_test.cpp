// SPDX-License-Identifier: MIT
// Changes between AdvanceTo calls (#36 part 4): removing, kicking, setting velocities, poses
// and thrusts, adding any body while running. Each refused change leaves the state hash as it
// was; each accepted one, then running on, gives the events of a World built afresh at that
// time from the same state (WorldSettings::start_time); a kick follows the closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "scenes/random.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"
#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

// How far the collision times of the changed World and the fresh one may differ: both are exact
// simulations of the same state; they differ only in how round-off falls (segment starts).
constexpr double kSameTime = 1e-9;
constexpr int kComparedCollisions = 60;

// A gas of spheres of a few sizes in a walled box, with its body definitions kept per slot.
struct Scene {
  WorldSettings settings;
  std::vector<BodyDef> defs;  // by slot; a removed body's entry stays (unused)
};

Scene MakeScene(std::uint64_t seed, int n = 60, double side = 12.0) {
  Scene scene;
  scene.settings.container = Container::WalledBox(Vec3::Zero(), Vec3::Constant(side));
  scenes::Random random(seed);
  const int per_axis = static_cast<int>(std::ceil(std::cbrt(n)));
  const double spacing = side / per_axis;
  for (int i = 0; i < n; ++i) {
    BodyDef def;
    def.radius = 0.3 + 0.25 * random.Uniform();
    def.mass = 0.5 + random.Uniform();
    def.position = Vec3(i % per_axis + 0.5, i / per_axis % per_axis + 0.5,
                        i / (per_axis * per_axis) + 0.5) * spacing;
    def.velocity = Vec3(random.Normal(), random.Normal(), random.Normal());
    scene.defs.push_back(def);
  }
  return scene;
}

World Build(const Scene& scene) {
  World world(scene.settings);
  for (const BodyDef& def : scene.defs) EXPECT_TRUE(world.AddBody(def));
  return world;
}

// A World made afresh at the other's clock from its state: every body's state now, with the
// rest of its definition.
World Fresh(const World& world, const Scene& scene) {
  WorldSettings settings = scene.settings;
  settings.start_time = world.Time();
  World fresh(settings);
  for (const BodyId id : world.Bodies()) {
    BodyDef def = scene.defs[id.index];
    const BodyState s = world.StateAt(id, world.Time());
    def.position = s.position;
    def.velocity = s.velocity;
    def.orientation = s.orientation;
    def.angular_velocity = s.angular_velocity;
    EXPECT_TRUE(fresh.AddBody(def)) << "slot " << id.index;
  }
  return fresh;
}

// The first collisions of a World from now, as (time, the pair's lower slot, the other slot or
// -1 - wall): which body of a pair is `a` depends on which one's prediction found the meeting.
struct Contact {
  double time;
  std::uint32_t a;
  std::int64_t b;
};
std::vector<Contact> FirstCollisions(World& world, const std::vector<std::uint32_t>& slot_of,
                                     double until) {
  std::vector<Contact> contacts;
  world.OnCollision([&](const CollisionEvent& e) {
    if (contacts.size() >= kComparedCollisions) return;
    const std::uint32_t a = slot_of[e.a.index];
    if (!e.b.valid()) {
      contacts.push_back({e.time, a, -1 - e.wall});
      return;
    }
    const std::uint32_t b = slot_of[e.b.index];
    contacts.push_back({e.time, std::min(a, b), std::int64_t{std::max(a, b)}});
  });
  EXPECT_TRUE(world.AdvanceTo(until));
  world.OnCollision(nullptr);
  return contacts;
}

// Runs the changed World and a fresh one from the same state; both must meet the same pairs in
// the same order at the same times. The fresh World numbers its bodies 0, 1, ... in the slot
// order of the changed one.
void ExpectSameFuture(World& changed, const Scene& scene, double until) {
  World fresh = Fresh(changed, scene);
  std::vector<std::uint32_t> identity(changed.SlotCount());
  std::vector<std::uint32_t> slot_of_fresh;
  for (std::uint32_t s = 0; s < identity.size(); ++s) identity[s] = s;
  for (const BodyId id : changed.Bodies()) slot_of_fresh.push_back(id.index);
  const std::vector<Contact> a = FirstCollisions(changed, identity, until);
  const std::vector<Contact> b = FirstCollisions(fresh, slot_of_fresh, until);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GE(a.size(), 20u) << "too few collisions to compare";
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE("collision " + std::to_string(k));
    EXPECT_EQ(a[k].a, b[k].a);
    EXPECT_EQ(a[k].b, b[k].b);
    EXPECT_NEAR(a[k].time, b[k].time, kSameTime * std::max(1.0, std::abs(a[k].time)));
  }
}

TEST(WorldChanges, RemovedHandleIsRefusedAndItsSlotTakenUnderANewGeneration) {
  Scene scene = MakeScene(3);
  World world = Build(scene);
  ASSERT_TRUE(world.AdvanceTo(1.0));
  const BodyId gone = world.IdOf(7);
  ASSERT_TRUE(world.RemoveBody(gone));
  EXPECT_FALSE(world.IsValid(gone));
  EXPECT_EQ(world.BodyCount(), scene.defs.size() - 1);
  EXPECT_EQ(world.SlotCount(), scene.defs.size());
  EXPECT_FALSE(world.IdOf(7).valid());
  for (const auto& [name, status] :
       std::vector<std::pair<std::string, Status>>{{"RemoveBody", world.RemoveBody(gone)},
                                                    {"SetVelocity", world.SetVelocity(gone, {})},
                                                    {"SetPose", world.SetPose(gone, {6, 6, 6}, Eigen::Quaterniond::Identity())},
                                                    {"ApplyImpulse", world.ApplyImpulse(gone, {}, {})}}) {
    ASSERT_FALSE(status) << name;
    EXPECT_EQ(status.error().message,
              name + ": body 7 (generation 0) is not in the World (removed, or never added)");
  }
  // No collision involves the removed body, and the others run on without overlaps.
  world.OnCollision([&](const CollisionEvent& e) {
    EXPECT_NE(e.a.index, 7u);
    EXPECT_NE(e.b.index, 7u);
  });
  ASSERT_TRUE(world.AdvanceTo(3.0));
  world.OnCollision(nullptr);
  EXPECT_TRUE(world.Validate());
  // A new body takes the slot, with the next generation; the old handle stays refused.
  BodyDef def = scene.defs[7];
  def.position = world.StateAt(world.IdOf(0), 3.0).position;  // certainly occupied: refused
  EXPECT_FALSE(world.AddBody(def));
  Result<BodyId> added = Error{"no free place"};
  for (double z = 0.6; z < 11.5 && !added; z += 0.2) {
    def.position = {0.6, 0.6, z};
    added = world.AddBody(def);
  }
  ASSERT_TRUE(added);
  EXPECT_EQ(added->index, 7u);
  EXPECT_EQ(added->generation, 1u);
  EXPECT_FALSE(world.IsValid(gone));
  EXPECT_TRUE(world.IsValid(*added));
  ASSERT_TRUE(world.AdvanceTo(5.0));
  EXPECT_TRUE(world.Validate());
}

TEST(WorldChanges, EveryRefusedChangeLeavesTheStateHashUnchanged) {
  Scene scene = MakeScene(5);
  World world = Build(scene);
  ASSERT_TRUE(world.AdvanceTo(0.7));
  const std::uint64_t hash = world.StateHash();
  const double nan = std::nan("");
  const BodyId a = world.IdOf(2), b = world.IdOf(3);
  const Vec3 b_position = world.StateAt(b, world.Time()).position;
  const std::vector<std::pair<std::string, std::function<Status()>>> refused = {
      {"a removed body", [&] { return world.SetVelocity(BodyId{99, 0}, {1, 0, 0}); }},
      {"a stale generation", [&] { return world.SetVelocity(BodyId{2, 1}, {1, 0, 0}); }},
      {"a NaN velocity", [&] { return world.SetVelocity(a, {nan, 0, 0}); }},
      {"an infinite spin", [&] { return world.SetAngularVelocity(a, {0, kInfinity, 0}); }},
      {"a NaN impulse", [&] { return world.ApplyImpulse(a, {0, nan, 0}, {1, 1, 1}); }},
      {"an infinite point", [&] { return world.ApplyImpulse(a, {1, 0, 0}, {kInfinity, 0, 0}); }},
      {"a pose on another body", [&] { return world.SetPose(a, b_position, {1, 0, 0, 0}); }},
      {"a pose outside the box", [&] { return world.SetPose(a, {-5, 6, 6}, {1, 0, 0, 0}); }},
      {"a pose across a wall", [&] { return world.SetPose(a, {0.1, 6, 6}, {1, 0, 0, 0}); }},
      {"a non-unit orientation", [&] { return world.SetPose(a, {6, 6, 6}, {2, 0, 0, 0}); }},
      {"a NaN thrust", [&] { return world.SetThrust(a, {nan, 0, 0}); }},
      {"a change before the clock",
       [&] { return world.SetThrust(a, {}, {{0.5, Vec3(1, 0, 0)}}); }},
      {"changes going back",
       [&] { return world.SetThrust(a, {}, {{2.0, Vec3(1, 0, 0)}, {1.5, Vec3(0, 1, 0)}}); }},
      {"a body overlapping another",
       [&] {
         Result<BodyId> added = world.AddBody({.radius = 0.3, .position = b_position});
         return added ? Status::Ok() : Status(added.error());
       }},
  };
  for (const auto& [what, change] : refused) {
    Status status = Status::Ok();
    {
      const sparsedyn::testing::FloatingPointTrapsPaused paused;  // NaN and infinity on purpose
      status = change();
    }
    EXPECT_FALSE(status) << what;
    if (!status) {
      EXPECT_FALSE(status.error().message.empty()) << what;
    }
    EXPECT_EQ(world.StateHash(), hash) << what << " changed the World";
  }
  EXPECT_EQ(world.BodyCount(), scene.defs.size());
}

TEST(WorldChanges, AKickAtAPointChangesVelocityAndSpinAsTheClosedFormSays) {
  // A box (half extents 1, 0.5, 0.25; mass 2) at rest, its own inertia tensor: an impulse J at
  // a point p gives dv = J / m and dw = I^-1 ((p - c) x J), I = m / 3 diag(b^2 + c^2, ...).
  WorldSettings settings;
  settings.rotation_model = RotationModel::kFullTensor;
  World world(settings);
  auto box = std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3(1, 0.5, 0.25)).value());
  const BodyId id = *world.AddBody({.shape = box, .position = {1, 2, 3}, .mass = 2.0});
  ASSERT_TRUE(world.AdvanceTo(0.5));
  const Vec3 impulse(0.3, -1.0, 0.7), point(1.9, 2.4, 2.8);
  ASSERT_TRUE(world.ApplyImpulse(id, impulse, point));
  const BodyState s = world.StateAt(id, world.Time());
  const double m = 2.0;
  const Vec3 inertia = m / 3.0 * Vec3(0.25 + 0.0625, 1.0 + 0.0625, 1.0 + 0.25);
  const Vec3 expected_w = ((point - Vec3(1, 2, 3)).cross(impulse)).cwiseQuotient(inertia);
  EXPECT_TRUE(s.velocity.isApprox(impulse / m, 1e-14));
  EXPECT_LT((s.angular_velocity - expected_w).norm(), 1e-13 * expected_w.norm());
  // A sphere, kicked off its centre, spins: I = 2/5 m r^2.
  World spheres;
  const BodyId ball = *spheres.AddBody({.radius = 0.5, .mass = 4.0});
  ASSERT_TRUE(spheres.ApplyImpulse(ball, {0, 0, 2}, {0.5, 0, 0}));
  const BodyState b = spheres.StateAt(ball, 0.0);
  EXPECT_TRUE(b.velocity.isApprox(Vec3(0, 0, 0.5), 1e-15));
  EXPECT_TRUE(b.angular_velocity.isApprox(Vec3(0, -1.0 / (0.4 * 4.0 * 0.25), 0), 1e-14));
}

TEST(WorldChanges, AKickInAPeriodicBoxTakesTheLeverArmOfTheNearestImage) {
  // The ball crosses the +x face at t = 0.5; at t = 2 StateAt reports it wrapped to x = 1.5. A
  // kick half a radius off that centre spins it as one off the unwrapped centre would:
  // dw = (0.5, 0, 0) x (0, 0, 2) / (2/5 m r^2), not the lever arm of a box length.
  WorldSettings settings;
  settings.container = Container::PeriodicBox(Vec3::Zero(), Vec3::Constant(10));
  World world(settings);
  const BodyId ball =
      *world.AddBody({.radius = 0.5, .position = {9.5, 5, 5}, .velocity = {1, 0, 0}, .mass = 4.0});
  ASSERT_TRUE(world.AdvanceTo(2.0));
  const Vec3 centre = world.StateAt(ball, 2.0).position;
  ASSERT_NEAR(centre.x(), 1.5, 1e-12);
  for (const Vec3& image : {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(-10, 0, 0)}) {
    SCOPED_TRACE("point image " + std::to_string(image.x()));
    const Vec3 before = world.StateAt(ball, 2.0).angular_velocity;
    ASSERT_TRUE(world.ApplyImpulse(ball, {0, 0, 2}, centre + image + Vec3(0.5, 0, 0)));
    const Vec3 spin = world.StateAt(ball, 2.0).angular_velocity - before;
    EXPECT_TRUE(spin.isApprox(Vec3(0, -1.0 / (0.4 * 4.0 * 0.25), 0), 1e-12)) << spin.transpose();
  }
}

TEST(WorldChanges, AVelocityChangeThenRunningOnIsAFreshWorldsFuture) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Scene scene = MakeScene(seed);
    World world = Build(scene);
    ASSERT_TRUE(world.AdvanceTo(1.3));
    ASSERT_TRUE(world.SetVelocity(world.IdOf(4), {3, -2, 0.5}));
    ASSERT_TRUE(world.ApplyImpulse(world.IdOf(9), {1, 1, 0}, world.StateAt(world.IdOf(9), 1.3).position));
    ExpectSameFuture(world, scene, 4.0);
  }
}

TEST(WorldChanges, RemovalsTeleportsAndAdditionsThenRunningOnAreAFreshWorldsFuture) {
  for (std::uint64_t seed = 11; seed <= 13; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Scene scene = MakeScene(seed);
    World world = Build(scene);
    ASSERT_TRUE(world.AdvanceTo(0.9));
    ASSERT_TRUE(world.RemoveBody(world.IdOf(5)));
    ASSERT_TRUE(world.RemoveBody(world.IdOf(0)));
    // A teleport to a free place, and a new body there too.
    bool moved = false, added = false;
    for (double x = 0.6; x < 11.5 && !(moved && added); x += 0.37) {
      if (!moved) {
        moved = static_cast<bool>(
            world.SetPose(world.IdOf(8), {x, 11.3, 6}, Eigen::Quaterniond::Identity()));
      }
      if (moved && !added) {
        BodyDef def{.radius = 0.4, .position = {x, 0.7, 0.7}, .velocity = {0, 2, 2}};
        if (Result<BodyId> id = world.AddBody(def)) {
          scene.defs.resize(std::max<std::size_t>(scene.defs.size(), id->index + 1));
          scene.defs[id->index] = def;
          added = true;
        }
      }
    }
    ASSERT_TRUE(moved && added);
    ExpectSameFuture(world, scene, 4.0);
  }
}

TEST(WorldChanges, PolyhedraCanBeAddedKickedAndTeleportedWhileRunning) {
  WorldSettings settings;
  settings.container = Container::WalledBox(Vec3::Zero(), Vec3::Constant(10));
  World world(settings);
  auto cube = std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3(0.4, 0.4, 0.4)).value());
  for (int i = 0; i < 8; ++i) {
    ASSERT_TRUE(world.AddBody({.shape = cube,
                               .position = {2.0 + 2.0 * (i % 4), 3.0 + 3.0 * (i / 4), 5},
                               .velocity = {std::cos(i), std::sin(i), 0.3},
                               .angular_velocity = {0.2, 0.1 * i, 0.3}}));
  }
  ASSERT_TRUE(world.AdvanceTo(1.0));
  const std::uint64_t collisions = world.Stats().collisions + world.Stats().wall_collisions;
  // Onto another body: refused by name; into free space: taken.
  EXPECT_FALSE(world.AddBody({.shape = cube, .position = world.StateAt(world.IdOf(2), 1.0).position}));
  ASSERT_TRUE(world.AddBody({.shape = cube, .position = {5, 8.5, 8.5}, .velocity = {0, -3, -3}}));
  ASSERT_TRUE(world.ApplyImpulse(world.IdOf(1), {2, 0, 0}, world.StateAt(world.IdOf(1), 1.0).position + Vec3(0, 0.4, 0)));
  ASSERT_TRUE(world.SetPose(world.IdOf(3), {8.5, 8.5, 1.5}, Eigen::Quaterniond(0.8, 0.6, 0, 0)));
  ASSERT_TRUE(world.AdvanceTo(8.0));
  EXPECT_GT(world.Stats().collisions + world.Stats().wall_collisions, collisions);
  EXPECT_TRUE(world.Validate());
  EXPECT_LT(world.MaxPenetration(), 1e-6);
}

TEST(ThrustSchedule, EachChangeIsAnEventAndThePathFollowsThePiecewiseClosedForm) {
  World world;
  const std::vector<ThrustChange> schedule = {{1.0, Vec3(2, 0, 0)}, {2.5, Vec3(0, -1, 0)},
                                              {4.0, Vec3(0, 0, 0)}};
  const BodyId id = *world.AddBody({.velocity = {0, 1, 0}, .thrust = {0, 0, 1},
                                    .thrust_schedule = schedule});
  ASSERT_TRUE(world.AdvanceTo(6.0));
  EXPECT_EQ(world.Stats().events_by_kind[5], 3u);  // body_timer
  // Integrated by hand, piece by piece.
  Vec3 p = Vec3::Zero(), v(0, 1, 0), a(0, 0, 1);
  double t = 0;
  for (const ThrustChange& change : schedule) {
    const double dt = change.time - t;
    p += v * dt + 0.5 * a * dt * dt;
    v += a * dt;
    a = change.thrust;
    t = change.time;
  }
  p += v * (6.0 - t) + 0.5 * a * (6.0 - t) * (6.0 - t);
  v += a * (6.0 - t);
  const BodyState s = world.StateAt(id, 6.0);
  EXPECT_LT((s.position - p).norm(), 1e-12);
  EXPECT_LT((s.velocity - v).norm(), 1e-12);
}

TEST(ThrustSchedule, ARocketThatFiresLaterMeetsItsTargetAtTheClosedFormTime) {
  // Two spheres of radius 0.5 at rest 5 m apart; from t = 2 the first accelerates at 2 m/s^2
  // towards the second: they touch when (t - 2)^2 = 4, at t = 4 exactly.
  World world;
  std::vector<CollisionEvent> seen;
  world.OnCollision([&](const CollisionEvent& e) { seen.push_back(e); });
  ASSERT_TRUE(world.AddBody({.position = {0, 0, 0}, .thrust_schedule = {{2.0, Vec3(2, 0, 0)}}}));
  ASSERT_TRUE(world.AddBody({.position = {5, 0, 0}}));
  ASSERT_TRUE(world.AdvanceTo(5.0));
  ASSERT_GE(seen.size(), 1u);
  EXPECT_NEAR(seen[0].time, 4.0, 1e-12);
  EXPECT_LE(seen[0].time, 4.0);
}

TEST(ThrustSchedule, SetThrustChangesTheAccelerationFromNowAndReplacesTheSchedule) {
  World world;
  const BodyId id =
      *world.AddBody({.thrust_schedule = {{1.0, Vec3(1, 0, 0)}, {3.0, Vec3(0, 0, 0)}}});
  ASSERT_TRUE(world.AdvanceTo(2.0));  // moving under (1, 0, 0) for 1 s: x = 0.5, v = 1
  ASSERT_TRUE(world.SetThrust(id, Vec3(0, 2, 0), {{4.0, Vec3(0, 0, 0)}}));
  ASSERT_TRUE(world.AdvanceTo(5.0));
  const BodyState s = world.StateAt(id, 5.0);
  // x: 0.5 + 1 * 3 = 3.5 (no thrust along x after 2); y: 2 * 2^2 / 2 + 4 * 1 = 8.
  EXPECT_LT((s.position - Vec3(3.5, 8.0, 0)).norm(), 1e-12);
  EXPECT_LT((s.velocity - Vec3(1, 4, 0)).norm(), 1e-12);
}

}  // namespace
}  // namespace sparsedyn
