// SPDX-License-Identifier: MIT
// The World with rotating convex polyhedra (issue #4): exact contact times in scenes with an
// analytic answer, adversarial scenes time-stepped engines miss, conservation, no
// interpenetration, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/world.hpp"
#include "world/polyhedra_scene.hpp"

namespace sparsedyn {
namespace {

std::shared_ptr<const ConvexPolyhedron> Box(double hx, double hy, double hz) {
  return std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3(hx, hy, hz)).value());
}

struct Collisions {
  std::vector<CollisionEvent> list;
  void Attach(World& world) {
    world.OnCollision([this](const CollisionEvent& c) { list.push_back(c); });
  }
};

// The contact tolerance of a pair: contact is declared when the distance reaches it, so an
// exact contact time is the time the distance equals it.
double Tolerance(const World& world, BodyId a, BodyId b) {
  return world.Settings().contact_tolerance *
         (world.StateAt(a, world.Time()).radius + world.StateAt(b, world.Time()).radius);
}

BodyDef Body(std::shared_ptr<const ConvexPolyhedron> shape, const Vec3& p, const Vec3& v,
             double mass = 1.0) {
  BodyDef def;
  def.shape = std::move(shape);
  def.position = p;
  def.velocity = v;
  def.mass = mass;
  return def;
}

TEST(Polyhedra, FlushCubesCollideAtTheExactTimeAndSwapVelocitiesWithoutSpin) {
  World world;
  const auto cube = Box(1, 1, 1);
  const BodyId a = world.AddBody(Body(cube, Vec3(0, 0, 0), Vec3(1, 0, 0))).value();
  // On the centre line: the contact region's centroid is too, so no torque (off the line a
  // flush contact is indeterminate and the region's centroid takes the impulse).
  const BodyId b = world.AddBody(Body(cube, Vec3(5, 0, 0), Vec3(-1, 0, 0))).value();
  Collisions collisions;
  collisions.Attach(world);
  ASSERT_TRUE(world.AdvanceTo(3.0).ok());
  ASSERT_EQ(collisions.list.size(), 1u);
  // The gap of 3 closes at relative speed 2.
  EXPECT_NEAR(collisions.list[0].time, (3 - Tolerance(world, a, b)) / 2, 1e-13);
  EXPECT_NEAR(collisions.list[0].normal.x(), 1.0, 1e-12);
  const BodyState sa = world.StateAt(a, 3.0);
  const BodyState sb = world.StateAt(b, 3.0);
  EXPECT_NEAR(sa.velocity.x(), -1.0, 1e-12);
  EXPECT_NEAR(sb.velocity.x(), 1.0, 1e-12);
  EXPECT_LT(sa.angular_velocity.norm(), 1e-12) << "a flush face-face impact gives no spin";
  EXPECT_LT(sb.angular_velocity.norm(), 1e-12);
}

TEST(Polyhedra, SmallFastBodyAgainstThinPlateIsNotMissed) {
  // A 2 cm cube at 1000 m/s towards a 4 mm thick plate: at 60 Hz it would move 16.7 m a step.
  World world;
  const BodyId plate = world.AddBody(Body(Box(2, 2, 0.002), Vec3::Zero(), Vec3::Zero(), 1e6))
                           .value();
  const BodyId bullet =
      world.AddBody(Body(Box(0.01, 0.01, 0.01), Vec3(0.3, -0.2, 10), Vec3(0, 0, -1000), 0.01))
          .value();
  Collisions collisions;
  collisions.Attach(world);
  ASSERT_TRUE(world.AdvanceTo(0.05).ok());
  ASSERT_GE(collisions.list.size(), 1u);
  EXPECT_NEAR(collisions.list[0].time,
              (10 - 0.002 - 0.01 - Tolerance(world, plate, bullet)) / 1000, 1e-14);
  EXPECT_GT(world.StateAt(bullet, 0.05).velocity.z(), 0) << "it bounced";
  EXPECT_GT(world.StateAt(bullet, 0.05).position.z(), 0) << "it did not pass through";
  EXPECT_TRUE(world.StateAt(plate, 0.05).velocity.norm() < 1e-2);
}

TEST(Polyhedra, FastBodiesCrossingPathsCollideAtTheExactTime) {
  // Axis-aligned cubes of half side 1: they touch when |dx| <= 2 and |dy| <= 2 (|dz| = 0.5),
  // which first holds at t = 0.49 (dy) while dx = -1.
  World world;
  const auto cube = Box(1, 1, 1);
  const BodyId a = world.AddBody(Body(cube, Vec3(-50, 0, 0), Vec3(100, 0, 0))).value();
  const BodyId b = world.AddBody(Body(cube, Vec3(0, -51, 0.5), Vec3(0, 100, 0))).value();
  Collisions collisions;
  collisions.Attach(world);
  ASSERT_TRUE(world.AdvanceTo(1.0).ok());
  ASSERT_GE(collisions.list.size(), 1u);
  EXPECT_NEAR(collisions.list[0].time, 0.49 - Tolerance(world, a, b) / 100, 1e-13);
  EXPECT_NEAR(std::abs(collisions.list[0].normal.y()), 1.0, 1e-9);
}

// Cube A turned 45 degrees about y has an edge along y at x = sqrt 2 (z = 0); cube B turned 45
// degrees about z has an edge along z at x = x_B - sqrt 2. B passes along y with its edge a gap
// g beyond A's.
std::vector<CollisionEvent> GrazingEdgePass(double g, double* tolerance = nullptr) {
  World world;
  const auto cube = Box(1, 1, 1);
  const double r2 = std::sqrt(2.0);
  BodyDef a = Body(cube, Vec3::Zero(), Vec3::Zero());
  a.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()));
  BodyDef b = Body(cube, Vec3(2 * r2 + g, -5, 0.3), Vec3(0, 2, 0));
  b.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()));
  const BodyId id_a = world.AddBody(a).value();
  const BodyId id_b = world.AddBody(b).value();
  if (tolerance != nullptr) *tolerance = Tolerance(world, id_a, id_b);
  Collisions collisions;
  collisions.Attach(world);
  EXPECT_TRUE(world.AdvanceTo(6.0).ok());
  return collisions.list;
}

TEST(Polyhedra, GrazingEdgeEdgePassMissesByTenNanometres) {
  EXPECT_TRUE(GrazingEdgePass(1e-7).empty());
}

TEST(Polyhedra, GrazingEdgeEdgePassTouchingByTenNanometresCollidesAtTheExactTime) {
  double tolerance = 0;
  const std::vector<CollisionEvent> collisions = GrazingEdgePass(-1e-7, &tolerance);
  ASSERT_GE(collisions.size(), 1u);
  // B's leading face y = y_B + (x - x_edge) reaches A's edge end (sqrt 2, -1, 0) when
  // y_B = -1 - 1e-7, with y_B = -5 + 2 t; the face's normal (-1, 1, 0)/sqrt 2 closes at sqrt 2.
  EXPECT_NEAR(collisions[0].time, (4 - 1e-7) / 2 - tolerance / std::sqrt(2.0), 1e-12);
}

// The first time (bisection on a fine sampling) a cube vertex reaches the plate's face, for a
// plate of half thickness h spinning at w about x from horizontal: an oracle that knows only
// the geometry.
double SpinningPlateContact(const std::vector<Vec3>& vertices, double h, double w) {
  auto gap = [&](double t) {
    const Vec3 n(0, -std::sin(w * t), std::cos(w * t));  // the plate's +z face normal
    double nearest = kInfinity;
    for (const Vec3& v : vertices) nearest = std::min(nearest, std::abs(n.dot(v)) - h);
    return nearest;
  };
  const double step = 1e-6;
  double t = 0;
  while (gap(t + step) > 0) t += step;
  double lo = t, hi = t + step;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) > 0 ? lo : hi) = mid;
  }
  return hi;
}

TEST(Polyhedra, ThinPlateSpinningFastHitsAtTheTimeGeometryGives) {
  // A 2 x 2 plate, 2 mm thick, spinning at 100 rad/s about x; a 10 cm cube at rest 0.9 above
  // the axis. At 60 Hz the plate turns 1.7 rad a step and passes through the cube unseen.
  const double w = 100, h = 0.001;
  World world;
  BodyDef plate = Body(Box(1, 1, h), Vec3::Zero(), Vec3::Zero(), 1e3);
  plate.angular_velocity = Vec3(w, 0, 0);
  world.AddBody(plate).value();
  const Vec3 centre(0.02, 0, 0.9);
  world.AddBody(Body(Box(0.05, 0.05, 0.05), centre, Vec3::Zero(), 0.1)).value();
  Collisions collisions;
  collisions.Attach(world);
  ASSERT_TRUE(world.AdvanceTo(0.03).ok());
  ASSERT_GE(collisions.list.size(), 1u);
  std::vector<Vec3> vertices;
  for (int k = 0; k < 8; ++k) {
    vertices.push_back(centre + 0.05 * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
  }
  EXPECT_NEAR(collisions.list[0].time, SpinningPlateContact(vertices, h, w), 1e-9);
}

// --- many bodies ---------------------------------------------------------------------------

struct RunChecks {
  double energy_drift = 0;
  double worst_penetration = 0;
  std::uint64_t collisions = 0;
};

// Runs until `collisions` body-body collisions, checking Validate() (no interpenetration beyond
// the tolerance, every body inside the walls) at `samples` random times along the way.
RunChecks RunWithChecks(World& world, std::uint64_t collisions, int samples, double t_max) {
  const double energy = world.KineticEnergy();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> step(0.0, 2.0 * t_max / samples);
  double t = 0;
  int checked = 0;
  while (world.Stats().collisions < collisions && t < t_max) {
    t += step(rng);
    EXPECT_TRUE(world.AdvanceTo(t).ok());
    const Status valid = world.Validate();
    EXPECT_TRUE(valid.ok()) << valid.error().message;
    if (!valid.ok() || ++checked > 10 * samples) break;
  }
  RunChecks result;
  result.energy_drift = std::abs(world.KineticEnergy() - energy) / energy;
  result.worst_penetration = world.MaxPenetration();
  result.collisions = world.Stats().collisions;
  return result;
}

// An inelastic cube dropped tilted onto the floor bounces and rocks ever faster at speeds the
// collapse guard keeps elastic (resting contact of polyhedra is not modelled): the clock still
// moves, by ~1e-10 s an event, so the stall check alone would let AdvanceTo run for hours. It
// ends with the crawl error instead, naming the cause, with the clock at the last event.
TEST(PolyhedraWorld, CubeComingToRestOnTheFloorEndsWithACrawlErrorNotAHang) {
  WorldSettings settings;
  settings.container = Container::WalledBox(Vec3::Zero(), Vec3::Constant(10));
  settings.gravity = Vec3(0, 0, -9.81);
  settings.stall_event_limit = 1u << 14;
  World world(settings);
  BodyDef cube = Body(Box(0.5, 0.5, 0.5), {5, 5, 3}, Vec3::Zero());
  cube.restitution = 0.5;
  cube.orientation = Eigen::AngleAxisd(0.3, Vec3(1, 1, 0).normalized());
  ASSERT_TRUE(world.AddBody(cube));
  const Status status = world.AdvanceTo(5.0);
  ASSERT_FALSE(status);
  EXPECT_NE(status.error().message.find("event loop crawling"), std::string::npos)
      << status.error().message;
  EXPECT_NE(status.error().message.find("resting contact of polyhedra"), std::string::npos);
  EXPECT_GT(world.Time(), 1.0);  // it fell, bounced and came nearly to rest first
  EXPECT_LT(world.Time(), 5.0);
  EXPECT_GE(4 * world.Stats().collapse_guarded, 1u << 14);  // a quarter of a window
  EXPECT_TRUE(world.Validate());
}

// Without gravity too: an inelastic tetrahedron hits a polyhedron that the impact sets turning,
// and the turning presses them back together (|omega|^2 r at the contact) ever faster, ~1e-10 s
// a bounce. A fuzzed scene (tests/fuzz/regressions/scene/) that ran for days before the crawl
// check counted the turning: with the default window it now ends within a second of CPU, at
// the crawl's start (t ~ 0.4624 s), naming it, with the World still valid.
TEST(PolyhedraWorld, TurningPolyhedraPressedTogetherWithoutGravityEndWithACrawlError) {
  const std::filesystem::path source(SPARSEDYN_SOURCE_DIR);
  std::ifstream file(source /
                     "tests/fuzz/regressions/scene/turning_polyhedra_pressed_together_crawl.json");
  const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  // Its meshes are data/'s, as for every fuzzed scene.
  const Result<SceneDescription> scene = ParseScene(text, "crawl.json", source / "data");
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->settings.gravity, Vec3::Zero());
  Result<World> world = BuildWorld(*scene);
  ASSERT_TRUE(world) << world.error().message;
  const Status status = world->AdvanceTo(scene->duration);
  ASSERT_FALSE(status);
  EXPECT_NE(status.error().message.find("event loop crawling"), std::string::npos)
      << status.error().message;
  EXPECT_NE(status.error().message.find("turning bodies pressed together"), std::string::npos);
  EXPECT_GT(world->Time(), 0.4623);
  EXPECT_LT(world->Time(), 0.4630);
  EXPECT_LT(world->Stats().events, 4 * WorldSettings{}.stall_event_limit);
  EXPECT_TRUE(world->Validate());
}

// A scene whose meshes are data/'s, run to `until`.
World RunSceneText(const std::string& text, double until) {
  const std::filesystem::path source(SPARSEDYN_SOURCE_DIR);
  const Result<SceneDescription> scene = ParseScene(text, "glide.json", source / "data");
  EXPECT_TRUE(scene) << scene.error().message;
  Result<World> world = BuildWorld(*scene);
  EXPECT_TRUE(world) << world.error().message;
  const Status status = world->AdvanceTo(until);
  EXPECT_TRUE(status) << status.error().message;
  return std::move(*world);
}

// A cube (half-size 1) flush against the wall x = 4, gliding along it at 2 m/s.
std::string CubeFlushOnAWall(const std::string& angular_velocity) {
  return R"({"container": {"kind": "walled", "lo": [-4, -40, -4], "hi": [4, 40, 4]},
             "bodies": [{"shape": "cube.off", "position": [3, 0, 0], "velocity": [0, 2, 0],
                         "angular_velocity": )" +
         angular_velocity + "}]}";
}

// The cube flush against the wall x = 4, gliding along it and spinning about the
// wall's normal: no gap changes, so no event. Its band was looked at again every 5 ns (the
// full speed bounded the gap's rate): 10^8 events per second, a fuzzed scene.
TEST(PolyhedraWorld, CubeGlidingAndSpinningFlushAlongAWallHasNoEvents) {
  const World world = RunSceneText(CubeFlushOnAWall("[0.5, 0, 0]"), 10.0);
  EXPECT_LE(world.Stats().events, 2u);
  EXPECT_EQ(world.Stats().wall_collisions, 0u);
  const BodyState body = world.StateAt(world.Bodies().front(), world.Time());
  EXPECT_NEAR(body.position.y(), 20.0, 1e-12);
  EXPECT_EQ(body.position.x(), 3.0);
}

// The same cube turning slowly about an axis in the wall's plane: an edge comes into the wall
// and must meet it, not pass in (the turn across the wall is what the wait bounds).
TEST(PolyhedraWorld, CubeFlushOnAWallTurningIntoItMeetsTheWall) {
  const World world = RunSceneText(CubeFlushOnAWall("[0, 0, 0.01]"), 1.0);
  EXPECT_EQ(world.Stats().wall_collisions, 1u);
  EXPECT_LE(world.MaxPenetration(), 1e-9);
  EXPECT_LT(world.Stats().events, 100u);
}

// On a static slab's top face, sliding and spinning about the face's normal: no event either.
TEST(PolyhedraWorld, CubeGlidingFlushOnAStaticSlabHasNoEvents) {
  const World world = RunSceneText(
      R"({"container": {"kind": "open"},
          "bodies": [{"shape": {"generator": "box", "half_extents": [50, 50, 1]},
                      "position": [0, 0, -1], "static": true},
                     {"shape": "cube.off", "position": [0, 0, 1], "velocity": [1, 0.5, 0],
                      "angular_velocity": [0, 0, 2]}]})",
      10.0);
  EXPECT_LT(world.Stats().events, 10u);
  EXPECT_EQ(world.Stats().collisions, 0u);
  EXPECT_LE(world.MaxPenetration(), 1e-9);
}

TEST(PolyhedraWorld, ElasticBoxKeepsEnergyAndNeverInterpenetrates) {
  testing::PolyhedraSceneOptions options;
  options.n = 60;
  options.seed = 3;
  World world = testing::MakePolyhedraWorld(options);
  const RunChecks checks = RunWithChecks(world, 1000, 1000, 200.0);
  EXPECT_GE(checks.collisions, 1000u);
  EXPECT_LE(checks.energy_drift, 1e-9);
  EXPECT_LE(checks.worst_penetration, 1e-9 * 2);  // tolerance x (r_a + r_b), radii 1
  EXPECT_EQ(world.Stats().walk_cap_hits, 0u);
  EXPECT_GT(world.Stats().wall_collisions, 0u);
  // A collision supersedes both bodies' element predictions (actor-absent, §4.2); a body
  // always has one (at least its next cell crossing or wall), so each collision counts two.
  EXPECT_EQ(world.Stats().stale_actor_absent, 2 * world.Stats().collisions);
}

TEST(PolyhedraWorld, OpenSpaceConservesMomentumAndAngularMomentum) {
  testing::PolyhedraSceneOptions options;
  options.n = 27;
  options.walls = false;
  options.spacing = 2.2;
  options.seed = 5;
  World world = testing::MakePolyhedraWorld(options);
  const Vec3 p0 = world.Momentum();
  const Vec3 l0 = world.AngularMomentum();
  const double e0 = world.KineticEnergy();
  ASSERT_TRUE(world.AdvanceTo(20.0).ok());
  EXPECT_GE(world.Stats().collisions, 10u);
  EXPECT_LE((world.Momentum() - p0).norm(), 1e-12 * options.n);
  EXPECT_LE((world.AngularMomentum() - l0).norm(), 1e-11 * options.n * 10);
  EXPECT_LE(std::abs(world.KineticEnergy() - e0), 1e-12 * e0);
}

TEST(PolyhedraWorld, FullInertiaTensorKeepsMomentumAndStaysApart) {
  // Constant angular velocity with the full tensor: energy and angular momentum vary between
  // events (docs/decisions/0003-rotation-model.md); linear momentum and geometry do not.
  testing::PolyhedraSceneOptions options;
  options.n = 27;
  options.walls = false;
  options.spacing = 2.2;
  options.seed = 6;
  options.rotation_model = RotationModel::kFullTensor;
  World world = testing::MakePolyhedraWorld(options);
  const Vec3 p0 = world.Momentum();
  ASSERT_TRUE(world.AdvanceTo(20.0).ok());
  EXPECT_GE(world.Stats().collisions, 10u);
  EXPECT_LE((world.Momentum() - p0).norm(), 1e-12 * options.n);
  EXPECT_TRUE(world.Validate().ok());
}

TEST(PolyhedraWorld, FrictionAndRestitutionNeverAddEnergy) {
  testing::PolyhedraSceneOptions options;
  options.n = 40;
  options.seed = 8;
  options.restitution = 0.9;
  options.friction = 0.4;
  World world = testing::MakePolyhedraWorld(options);
  double energy = world.KineticEnergy();
  for (double t = 0.5; t <= 20; t += 0.5) {
    ASSERT_TRUE(world.AdvanceTo(t).ok());
    const double now = world.KineticEnergy();
    EXPECT_LE(now, energy * (1 + 1e-12)) << "t = " << t;
    energy = now;
  }
  EXPECT_GT(world.Stats().collisions, 20u);
  EXPECT_TRUE(world.Validate().ok());
}

TEST(PolyhedraWorld, AllPairsAndGridSeeTheSameCollisions) {
  testing::PolyhedraSceneOptions options;
  options.n = 27;
  options.seed = 9;
  std::vector<std::vector<CollisionEvent>> runs;
  for (const Broadphase broadphase : {Broadphase::kAllPairs, Broadphase::kGrid}) {
    options.broadphase = broadphase;
    World world = testing::MakePolyhedraWorld(options);
    Collisions collisions;
    collisions.Attach(world);
    ASSERT_TRUE(world.AdvanceTo(5.0).ok());
    runs.push_back(collisions.list);
  }
  ASSERT_GT(runs[0].size(), 10u);
  // Predictions start at different times in the two broad phases, so times agree to round-off
  // only; the sequence is compared up to the first divergence of chaotic dynamics.
  const std::size_t n = std::min<std::size_t>(10, runs[0].size());
  ASSERT_GE(runs[1].size(), n);
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_EQ(runs[0][k].a.index, runs[1][k].a.index) << k;
    EXPECT_EQ(runs[0][k].b.index, runs[1][k].b.index) << k;
    EXPECT_NEAR(runs[0][k].time, runs[1][k].time, 1e-9) << k;
  }
}

TEST(PolyhedraWorld, SameSeedSameCollisionsBitForBit) {
  auto run = [] {
    testing::PolyhedraSceneOptions options;
    options.n = 40;
    options.seed = 4;
    World world = testing::MakePolyhedraWorld(options);
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a over every segment's bytes
    world.OnSegment([&](const MotionSegment& s) {
      const double values[] = {s.t0,
                               s.position.x(),
                               s.position.y(),
                               s.position.z(),
                               s.velocity.x(),
                               s.velocity.y(),
                               s.velocity.z(),
                               s.orientation.w(),
                               s.orientation.x(),
                               s.angular_velocity.x(),
                               s.angular_velocity.y(),
                               s.angular_velocity.z()};
      const auto* bytes = reinterpret_cast<const unsigned char*>(values);
      for (std::size_t k = 0; k < sizeof(values); ++k) hash = (hash ^ bytes[k]) * 1099511628211ull;
    });
    EXPECT_TRUE(world.AdvanceTo(10.0).ok());
    EXPECT_GT(world.Stats().collisions, 20u);
    return hash;
  };
  EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace sparsedyn
