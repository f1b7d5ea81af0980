// SPDX-License-Identifier: MIT
// Drag on and beside moving polyhedra (issue #36 part 5): a polyhedron's contacts with walls,
// static bodies, spheres and other polyhedra are found on the true motions. Oracles: the closed
// form of linear drag and its contact times (a cube's face and vertex on the floor and on a
// static slab, a cube on a static sphere, two cubes head on, a sphere on a free cube), and a
// separating-axis test of every pair of boxes, written here, on densely sampled true states of
// tumbling cubes and spheres with quadratic drag (no overlap beyond the contact band, no energy
// gained).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"
#include "support/linear_drag_oracle.hpp"

namespace sparsedyn {
namespace {

using testing::CoastTime;
using testing::FallTime;

std::shared_ptr<const ConvexPolyhedron> Box(const Vec3& half_extents) {
  return std::make_shared<const ConvexPolyhedron>(MakeBox(half_extents).value());
}

struct Scenario {
  World world;
  std::vector<CollisionEvent> events;
};

std::unique_ptr<Scenario> MakeRun(const WorldSettings& settings) {
  auto run = std::make_unique<Scenario>(Scenario{World(settings), {}});
  run->world.OnCollision([r = run.get()](const CollisionEvent& e) { r->events.push_back(e); });
  return run;
}

WorldSettings FallSettings() {
  WorldSettings settings;
  settings.gravity = Vec3(0, 0, -9.81);
  settings.container = Container::WalledBox(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  return settings;
}

// A cube turned so that its vertex (-1, -1, -1) h points straight down.
Eigen::Quaterniond VertexDown() {
  return Eigen::Quaterniond::FromTwoVectors(Vec3(-1, -1, -1).normalized(), -Vec3::UnitZ());
}

TEST(DragPolyhedra, ACubeFallingOntoTheFloorMeetsItAtTheClosedFormTime) {
  const double c1 = 0.4, h = 0.5;
  for (const bool vertex : {false, true}) {
    SCOPED_TRACE(vertex ? "vertex down" : "face down");
    std::unique_ptr<Scenario> run = MakeRun(FallSettings());
    ASSERT_TRUE(run->world.AddBody(
        {.shape = Box(Vec3::Constant(h)),
         .position = {0, 0, 6},
         .orientation = vertex ? VertexDown() : Eigen::Quaterniond::Identity(),
         .drag = Drag{c1, 0}}));
    ASSERT_TRUE(run->world.AdvanceTo(1.5));
    ASSERT_FALSE(run->events.empty());
    const CollisionEvent& first = run->events.front();
    EXPECT_EQ(first.wall, 4);  // the floor, -z
    const double lowest = vertex ? h * std::sqrt(3.0) : h;
    const double expected = FallTime(6, -9.81, c1, lowest, 2);
    EXPECT_NEAR(first.time, expected, 1e-9);
    EXPECT_LE(first.time, expected + 1e-15);  // never late
    // Restitution 1 on the floor, the impulse through the centre: the speed just before, up.
    std::unique_ptr<Scenario> again = MakeRun(FallSettings());
    const BodyId twin = *again->world.AddBody(
        {.shape = Box(Vec3::Constant(h)),
         .position = {0, 0, 6},
         .orientation = vertex ? VertexDown() : Eigen::Quaterniond::Identity(),
         .drag = Drag{c1, 0}});
    ASSERT_TRUE(again->world.AdvanceTo(first.time));
    const BodyState after = again->world.StateAt(twin, first.time);
    const double before = 9.81 / c1 * -std::expm1(-c1 * first.time);
    EXPECT_NEAR(after.velocity.z(), before, 1e-8 * before);
    EXPECT_NEAR(after.angular_velocity.norm(), 0.0, 1e-9);
    EXPECT_TRUE(run->world.Validate());
  }
}

TEST(DragPolyhedra, ACubeFallingOntoAStaticSlabOrSphereMeetsItAtTheClosedFormTime) {
  const double c1 = 0.3, h = 0.5;
  const struct {
    const char* name;
    BodyDef fixed;
    double contact;  // the cube's centre height at contact
  } cases[] = {
      {"slab face", {.shape = Box(Vec3(3, 3, 0.5)), .position = {0.4, 0, 1}, .is_static = true},
       1.5 + h},
      {"sphere", {.radius = 1.0, .position = {0.2, -0.1, 1.5}, .is_static = true}, 2.5 + h},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::unique_ptr<Scenario> run = MakeRun(FallSettings());
    ASSERT_TRUE(run->world.AddBody(c.fixed));
    ASSERT_TRUE(run->world.AddBody(
        {.shape = Box(Vec3::Constant(h)), .position = {0, 0, 6}, .drag = Drag{c1, 0}}));
    ASSERT_TRUE(run->world.AdvanceTo(1.2));
    ASSERT_FALSE(run->events.empty());
    const double expected = FallTime(6, -9.81, c1, c.contact, 2);
    EXPECT_NEAR(run->events.front().time, expected, 1e-9);
    EXPECT_LE(run->events.front().time, expected + 1e-15);
    EXPECT_GE(run->world.Stats().static_collisions, 1u);
    EXPECT_TRUE(run->world.Validate());
  }
}

TEST(DragPolyhedra, TwoCubesHeadOnMeetAtTheRootOfTheClosedForm) {
  WorldSettings settings;
  settings.container = Container::WalledBox(Vec3::Constant(-10), Vec3::Constant(10));
  const double c1 = 0.5, v0 = 5.0, h = 0.5;
  for (const bool rotated : {false, true}) {
    // Turned about x (the line of approach) their faces still meet flat: the same time.
    SCOPED_TRACE(rotated ? "turned about x" : "axis-aligned");
    const Eigen::Quaterniond q(Eigen::AngleAxisd(rotated ? 0.3 : 0.0, Vec3::UnitX()));
    std::unique_ptr<Scenario> run = MakeRun(settings);
    const BodyId a = *run->world.AddBody({.shape = Box(Vec3::Constant(h)), .position = {-2, 0, 0},
                                          .orientation = q, .velocity = {v0, 0, 0},
                                          .drag = Drag{c1, 0}});
    const BodyId b = *run->world.AddBody({.shape = Box(Vec3::Constant(h)), .position = {2, 0, 0},
                                          .orientation = q, .velocity = {-v0, 0, 0},
                                          .drag = Drag{c1, 0}});
    ASSERT_TRUE(run->world.AdvanceTo(0.5));
    ASSERT_FALSE(run->events.empty());
    // Each covers half of the gap 4 - 2 h.
    const double expected = CoastTime(v0, c1, (4 - 2 * h) / 2);
    EXPECT_NEAR(run->events.front().time, expected, 1e-9);
    EXPECT_LE(run->events.front().time, expected + 1e-15);
    // Restitution 1, equal masses, head on: they swap velocities, v0 e^(-c1 t) each.
    const double t = 0.45, speed = v0 * std::exp(-c1 * t);
    EXPECT_NEAR(run->world.StateAt(a, t).velocity.x(), -speed, 1e-8 * v0);
    EXPECT_NEAR(run->world.StateAt(b, t).velocity.x(), speed, 1e-8 * v0);
    EXPECT_TRUE(run->world.Validate());
  }
}

TEST(DragPolyhedra, ASphereWithDragMeetsAFreeCubeAtTheClosedFormTime) {
  WorldSettings settings;
  settings.container = Container::WalledBox(Vec3::Constant(-10), Vec3::Constant(10));
  const double c1 = 0.4, v0 = 4.0, r = 0.25, h = 0.5;
  std::unique_ptr<Scenario> run = MakeRun(settings);
  ASSERT_TRUE(run->world.AddBody({.shape = Box(Vec3::Constant(h)), .drag = Drag{}}));
  ASSERT_TRUE(run->world.AddBody(
      {.radius = r, .position = {-3, 0.1, -0.2}, .velocity = {v0, 0, 0}, .drag = Drag{c1, 0}}));
  ASSERT_TRUE(run->world.AdvanceTo(1.0));
  ASSERT_FALSE(run->events.empty());
  const double expected = CoastTime(v0, c1, 3 - h - r);
  EXPECT_NEAR(run->events.front().time, expected, 1e-9);
  EXPECT_LE(run->events.front().time, expected + 1e-15);
  EXPECT_NEAR(std::abs(run->events.front().normal.x()), 1.0, 1e-9);
  EXPECT_TRUE(run->world.Validate());
}

// --- Dense sampling against a separating-axis test --------------------------------------------

struct Box3 {
  Vec3 centre;
  Eigen::Matrix3d axes;  // columns: the box's axes in the world
  Vec3 half;
};

// How deep two boxes overlap: the least overlap of their projections on the 15 axes of the
// separating-axis theorem (<= 0: apart; for boxes this is the penetration depth).
double BoxOverlap(const Box3& a, const Box3& b) {
  std::vector<Vec3> axes;
  for (int k = 0; k < 3; ++k) {
    axes.push_back(a.axes.col(k));
    axes.push_back(b.axes.col(k));
    for (int l = 0; l < 3; ++l) {
      const Vec3 c = a.axes.col(k).cross(b.axes.col(l));
      if (c.norm() > 1e-9) axes.push_back(c.normalized());
    }
  }
  double least = kInfinity;
  for (const Vec3& n : axes) {
    const double ra = (a.axes.transpose() * n).cwiseAbs().dot(a.half);
    const double rb = (b.axes.transpose() * n).cwiseAbs().dot(b.half);
    least = std::min(least, ra + rb - std::abs(n.dot(b.centre - a.centre)));
  }
  return least;
}

// How deep a sphere overlaps a box (<= 0: apart).
double SphereBoxOverlap(const Vec3& centre, double radius, const Box3& box) {
  const Vec3 local = box.axes.transpose() * (centre - box.centre);
  const Vec3 nearest = local.cwiseMax(-box.half).cwiseMin(box.half);
  return radius - (local - nearest).norm();
}

TEST(DragPolyhedra, TumblingCubesAndSpheresWithDragNeverOverlapAndNeverGainEnergy) {
  WorldSettings settings;
  settings.container = Container::WalledBox(Vec3::Constant(-2), Vec3::Constant(2));
  settings.drag = Drag{0.1, 0.1};
  World world(settings);
  const Vec3 slab_half(1.0, 1.0, 0.2);
  const Eigen::Quaterniond slab_turn(Eigen::AngleAxisd(0.4, Vec3(1, 2, 0).normalized()));
  ASSERT_TRUE(world.AddBody({.shape = Box(slab_half), .orientation = slab_turn,
                             .is_static = true}));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> place(-1.7, 1.7), speed(-4, 4), spin(-6, 6);
  const Vec3 cube_half = Vec3::Constant(0.22);
  const double r = 0.2;
  std::vector<BodyId> cubes, spheres;
  while (cubes.size() + spheres.size() < 36) {
    const bool cube = cubes.size() <= spheres.size();
    const Eigen::Quaterniond q = Eigen::Quaterniond::UnitRandom();
    BodyDef def{.radius = r,
                .position = {place(rng), place(rng), place(rng)},
                .orientation = q,
                .velocity = {speed(rng), speed(rng), speed(rng)},
                .restitution = 0.95,
                .friction = 0.3};
    if (cube) {
      def.shape = Box(cube_half);
      def.angular_velocity = Vec3(spin(rng), spin(rng), spin(rng));
    }
    Result<BodyId> body = world.AddBody(def);
    if (body) (cube ? cubes : spheres).push_back(*body);  // a place that overlaps is refused
  }
  const Box3 slab{Vec3::Zero(), slab_turn.toRotationMatrix(), slab_half};
  const double band = 1e-6;
  double energy = world.KineticEnergy();
  for (int k = 1; k <= 1500; ++k) {
    const double t = 1e-3 * k;
    ASSERT_TRUE(world.AdvanceTo(t)) << t;
    std::vector<Box3> boxes;
    for (const BodyId c : cubes) {
      const BodyState s = world.StateAt(c, t);
      boxes.push_back(Box3{s.position, s.orientation.toRotationMatrix(), cube_half});
    }
    std::vector<Vec3> balls;
    for (const BodyId s : spheres) balls.push_back(world.StateAt(s, t).position);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      ASSERT_LT(BoxOverlap(boxes[i], slab), band) << "cube " << i << " in the slab at " << t;
      for (std::size_t j = i + 1; j < boxes.size(); ++j) {
        ASSERT_LT(BoxOverlap(boxes[i], boxes[j]), band) << "cubes " << i << ", " << j << " at "
                                                        << t;
      }
      for (std::size_t j = 0; j < balls.size(); ++j) {
        ASSERT_LT(SphereBoxOverlap(balls[j], r, boxes[i]), band)
            << "sphere " << j << " in cube " << i << " at " << t;
      }
      // Inside the walls: every corner.
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 sign(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
        const Vec3 x = boxes[i].centre + boxes[i].axes * sign.cwiseProduct(cube_half);
        ASSERT_LT(x.cwiseAbs().maxCoeff(), 2.0 + band) << "cube " << i << " in a wall at " << t;
      }
    }
    for (std::size_t i = 0; i < balls.size(); ++i) {
      ASSERT_LT(SphereBoxOverlap(balls[i], r, slab), band) << "sphere " << i << " in the slab";
      for (std::size_t j = i + 1; j < balls.size(); ++j) {
        ASSERT_GT((balls[i] - balls[j]).norm() - 2 * r, -band) << "spheres at " << t;
      }
    }
    // Drag and restitution below 1 only take energy away.
    const double now = world.KineticEnergy();
    ASSERT_LE(now, energy * (1 + 1e-9)) << t;
    energy = now;
  }
  const Statistics& stats = world.Stats();
  std::printf("%u cubes, %u spheres: %llu collisions (%llu with the slab), %llu wall collisions, "
              "%llu drag steps\n",
              static_cast<unsigned>(cubes.size()), static_cast<unsigned>(spheres.size()),
              static_cast<unsigned long long>(stats.collisions),
              static_cast<unsigned long long>(stats.static_collisions),
              static_cast<unsigned long long>(stats.wall_collisions),
              static_cast<unsigned long long>(stats.drag_steps));
  EXPECT_GT(stats.collisions, 20u);
  EXPECT_GT(stats.wall_collisions, 10u);
  EXPECT_GE(stats.static_collisions, 1u);
  EXPECT_GT(stats.drag_steps, 0u);
  EXPECT_TRUE(world.Validate());
}

}  // namespace
}  // namespace sparsedyn
