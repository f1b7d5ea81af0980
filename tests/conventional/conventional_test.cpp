// SPDX-License-Identifier: MIT
// The conventional time-stepped method (src/conventional/): collision times against analytic
// ones, the aliasing it is known for, conservation, agreement with the event-driven World, and
// refused input.
#include "sparsedyn/conventional.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "conventional/overlap_certificate.hpp"
#include "conventional/sweep_and_prune.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

std::shared_ptr<const ConvexPolyhedron> Box(double hx, double hy, double hz) {
  return std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3(hx, hy, hz)).value());
}

BodyDef Body(std::shared_ptr<const ConvexPolyhedron> shape, const Vec3& position,
             const Vec3& velocity, double mass = 1.0) {
  BodyDef def;
  def.shape = std::move(shape);
  def.position = position;
  def.velocity = velocity;
  def.mass = mass;
  return def;
}

// --- the broad phase against all pairs -----------------------------------------------------

TEST(SweepAndPrune, FindsExactlyTheOverlappingBoxesOfAllPairsOverManySteps) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> centres(200);
  std::vector<Vec3> velocities(200);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    centres[i] = 20.0 * Vec3(unit(rng), unit(rng), unit(rng));
    velocities[i] = Vec3(unit(rng), unit(rng), unit(rng)) - Vec3::Constant(0.5);
  }
  SweepAndPrune sweep;
  for (int step = 0; step < 20; ++step) {
    std::vector<Aabb> boxes;
    for (std::size_t i = 0; i < centres.size(); ++i) {
      centres[i] += velocities[i];
      boxes.push_back(Aabb{centres[i] - Vec3::Constant(1.0), centres[i] + Vec3::Constant(1.0)});
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
    for (std::uint32_t a = 0; a < boxes.size(); ++a) {
      for (std::uint32_t b = a + 1; b < boxes.size(); ++b) {
        const Vec3 d = (centres[b] - centres[a]).cwiseAbs();
        if (d.maxCoeff() <= 2.0) expected.insert({a, b});
      }
    }
    sweep.Update(boxes);
    std::set<std::pair<std::uint32_t, std::uint32_t>> got;
    sweep.ForEachOverlap([&](std::uint32_t a, std::uint32_t b) {
      EXPECT_LT(a, b);
      EXPECT_TRUE(got.insert({a, b}).second) << "pair reported twice";
    });
    EXPECT_EQ(got, expected) << "step " << step;
  }
}

// --- the bisection's overlap certificate against closest features ----------------------------

TEST(OverlapCertificate, NeverClaimsASeparatedPairAndCertifiesDeepOverlaps) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::shared_ptr<const ConvexPolyhedron>> shapes;
  for (int faces : {4, 12, 40, 150}) {
    ConvexPolyhedron p =
        RandomConvexPolyhedron(faces, 5u + static_cast<std::uint64_t>(faces)).value().Recentered();
    shapes.push_back(std::make_shared<const ConvexPolyhedron>(p.Scaled(1.0 / p.bounding_radius())));
  }
  shapes.push_back(Box(1.0, 0.2, 0.05));
  int deep = 0;
  int deep_certified = 0;
  int certified = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto& a = shapes[static_cast<std::size_t>(trial) % shapes.size()];
    const auto& b = shapes[static_cast<std::size_t>(trial / 5) % shapes.size()];
    auto random_pose = [&](double spread) {
      return Pose{Eigen::Quaterniond(unit(rng), unit(rng), unit(rng), unit(rng)).normalized(),
                  spread * Vec3(unit(rng), unit(rng), unit(rng))};
    };
    const Pose X_WA = random_pose(0.0);
    const Pose X_WB = random_pose(1.5);
    const bool claim = CertainlyOverlap(*a, X_WA, *b, X_WB);
    const ClosestFeatures f =
        FindClosestFeatures(TrackedPolyhedron(a), X_WA, TrackedPolyhedron(b), X_WB);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", distance " + std::to_string(f.distance));
    if (claim) {
      ++certified;
      EXPECT_LE(f.distance, 1e-12);  // the oracle: never a separated pair
    }
    if (f.distance < -1e-3) {
      ++deep;
      deep_certified += claim ? 1 : 0;
    }
  }
  EXPECT_GT(certified, 300);
  // A fallback is allowed (degenerate searches) but must be rare, or it saves nothing.
  EXPECT_GE(deep_certified, deep * 99 / 100) << deep_certified << " of " << deep;
}

// --- collision times and response --------------------------------------------------------------

// Two unit cubes (half side 0.5) 2 apart closing at 2 m/s touch at t = 1 exactly; the step does
// not divide 1, so the collision falls inside a step and must be bisected.
class HeadOnCubes : public ::testing::TestWithParam<int> {};

TEST_P(HeadOnCubes, CollisionLocatedWithinTheBisectionResolutionAndVelocitiesSwapped) {
  const int digits = GetParam();
  const ConventionalSettings conventional{.dt = 0.03, .digits = digits};
  ConventionalWorld world(WorldSettings{}, conventional);
  const auto cube = Box(0.5, 0.5, 0.5);
  ASSERT_TRUE(world.AddBody(Body(cube, Vec3(0, 0, 0), Vec3(1, 0, 0))).ok());
  ASSERT_TRUE(world.AddBody(Body(cube, Vec3(3, 0, 0), Vec3(-1, 0, 0))).ok());
  std::vector<CollisionEvent> events;
  world.OnCollision([&](const CollisionEvent& e) { events.push_back(e); });
  ASSERT_TRUE(world.AdvanceTo(1.5).ok());

  ASSERT_EQ(events.size(), 1u);
  // The cubes count as touching once their gap is within the contact tolerance (relative to
  // the summed bounding radii): at 1 - tolerance / closing speed.
  const double tolerance = WorldSettings{}.contact_tolerance * 2.0 * std::sqrt(0.75);
  const double exact = 1.0 - tolerance / 2.0;
  const double resolution = conventional.dt * std::pow(10.0, -digits);
  EXPECT_LE(std::abs(events[0].time - exact), resolution);
  // Located at the touching end of the final interval: never before the contact.
  EXPECT_GE(events[0].time, exact - 1e-15);
  EXPECT_NEAR(events[0].normal.x(), 1.0, 1e-9);
  // Equal masses, elastic, head-on: the velocities are exchanged.
  EXPECT_NEAR(world.StateAt(BodyId{0, 0}, 1.5).velocity.x(), -1.0, 1e-9);
  EXPECT_NEAR(world.StateAt(BodyId{1, 0}, 1.5).velocity.x(), 1.0, 1e-9);
  EXPECT_LT(world.StateAt(BodyId{0, 0}, 1.5).angular_velocity.norm(), 1e-9);
  EXPECT_EQ(world.StateAt(BodyId{0, 0}, 1.5).version, 1u);
  EXPECT_EQ(world.Stats().steps, 50u);
  EXPECT_EQ(world.Stats().collisions, 1u);
  // Bisection of one step down to dt 10^-A2 takes about A2 lg 10 halvings.
  EXPECT_GE(world.Stats().bisection_evaluations, static_cast<std::uint64_t>(3.3 * digits));
  EXPECT_LE(world.Stats().bisection_evaluations, static_cast<std::uint64_t>(3.4 * digits) + 3);
}

INSTANTIATE_TEST_SUITE_P(Digits, HeadOnCubes, ::testing::Values(1, 3, 6, 9));

// --- aliasing: what the method misses ------------------------------------------------------------

struct PlateRun {
  std::vector<CollisionEvent> events;
  double final_x = 0;  // the bullet's centre at the end
};

// A 0.2 m bullet at 50 m/s against a 0.1 m plate: they overlap only for
// t in [2.85/50, 3.15/50] = [0.057, 0.063] s.
PlateRun ShootThroughPlate(double dt) {
  ConventionalWorld world(WorldSettings{}, ConventionalSettings{.dt = dt, .digits = 4});
  EXPECT_TRUE(world.AddBody(Body(Box(0.05, 2, 2), Vec3(0, 0, 0), Vec3::Zero(), 1e6)).ok());
  EXPECT_TRUE(world.AddBody(Body(Box(0.1, 0.1, 0.1), Vec3(-3, 0, 0), Vec3(50, 0, 0))).ok());
  PlateRun run;
  world.OnCollision([&](const CollisionEvent& e) { run.events.push_back(e); });
  EXPECT_TRUE(world.AdvanceTo(0.2).ok());
  run.final_x = world.StateAt(BodyId{1, 0}, 0.2).position.x();
  return run;
}

TEST(Aliasing, FastBulletPassesThroughAThinPlateWithALargeStep) {
  // Steps end at 0.05 and 0.1: neither falls inside the 6 ms overlap, so nothing is seen.
  const PlateRun run = ShootThroughPlate(0.05);
  EXPECT_TRUE(run.events.empty());
  EXPECT_GT(run.final_x, 0.15);  // beyond the plate: tunnelled
}

TEST(Aliasing, SmallStepFindsTheHitAtItsExactTime) {
  const double dt = 1e-3;
  const PlateRun run = ShootThroughPlate(dt);
  ASSERT_EQ(run.events.size(), 1u);
  EXPECT_NEAR(run.events[0].time, 2.85 / 50, dt * 1e-4 + 1e-12);
  EXPECT_LT(run.final_x, -0.15);  // bounced back
}

TEST(Aliasing, TheEventDrivenWorldSeesTheHitTheLargeStepMisses) {
  World world;
  ASSERT_TRUE(world.AddBody(Body(Box(0.05, 2, 2), Vec3(0, 0, 0), Vec3::Zero(), 1e6)).ok());
  ASSERT_TRUE(world.AddBody(Body(Box(0.1, 0.1, 0.1), Vec3(-3, 0, 0), Vec3(50, 0, 0))).ok());
  std::vector<CollisionEvent> events;
  world.OnCollision([&](const CollisionEvent& e) { events.push_back(e); });
  ASSERT_TRUE(world.AdvanceTo(0.2).ok());
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0].time, 2.85 / 50, 1e-9);
}

// --- conservation ---------------------------------------------------------------------------

struct SceneOptions {
  int n = 30;
  double spacing = 2.6;
  std::uint64_t seed = 7;
};

// Random convex polyhedra of bounding radius 1 on a jittered lattice in a walled box, random
// orientations, velocities and spins: the same definitions feed both methods.
std::vector<BodyDef> LatticeBodies(const SceneOptions& o, Container& box) {
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(o.n))));
  box = Container::WalledBox(Vec3::Zero(), Vec3::Constant(side * o.spacing));
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::shared_ptr<const ConvexPolyhedron>> pool;
  for (int faces : {24, 40, 80}) {
    ConvexPolyhedron p = RandomConvexPolyhedron(faces, o.seed + static_cast<std::uint64_t>(faces))
                             .value()
                             .Recentered();
    pool.push_back(std::make_shared<const ConvexPolyhedron>(p.Scaled(1.0 / p.bounding_radius())));
  }
  std::vector<BodyDef> defs;
  for (int i = 0; i < o.n; ++i) {
    const Vec3 cell(i % side, (i / side) % side, i / (side * side));
    BodyDef def =
        Body(pool[static_cast<std::size_t>(i) % pool.size()],
             (cell + Vec3::Constant(0.5)) * o.spacing + 0.2 * Vec3(unit(rng), unit(rng), unit(rng)),
             2.0 * Vec3(unit(rng), unit(rng), unit(rng)), 1.0 + 0.5 * unit(rng));
    def.orientation = Eigen::Quaterniond(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    def.angular_velocity = Vec3(unit(rng), unit(rng), unit(rng));
    defs.push_back(def);
  }
  return defs;
}

TEST(Conservation, ElasticFrictionlessBoxKeepsItsEnergy) {
  Container box;
  const std::vector<BodyDef> defs = LatticeBodies(SceneOptions{}, box);
  WorldSettings settings;
  settings.container = box;
  ConventionalWorld world(settings, ConventionalSettings{.dt = 2e-3, .digits = 4});
  for (const BodyDef& def : defs) ASSERT_TRUE(world.AddBody(def).ok());
  const double initial = world.KineticEnergy();
  ASSERT_TRUE(world.AdvanceTo(4.0).ok());
  const ConventionalStatistics& s = world.Stats();
  EXPECT_GT(s.collisions, 5u);
  EXPECT_GT(s.wall_collisions, 5u);
  EXPECT_EQ(s.walk_cap_hits, 0u);
  // Between collisions the spherical-top motion is exact; a frictionless elastic impulse
  // conserves energy wherever the contact is, so locating it to A2 digits moves the bounce but
  // not the energy: only round-off (1e-12 per collision, generously) remains.
  const double bound = 1e-12 * static_cast<double>(s.collisions + s.wall_collisions + 1);
  EXPECT_NEAR(world.KineticEnergy(), initial, bound * initial);
  // Bisection stops within dt 10^-A2 of the contact: overlaps at step ends stay far below a
  // full step's travel (speeds ~3.5 m/s plus spin, 7 mm per step), and the located ones are
  // resolved.
  EXPECT_LT(s.max_penetration, 0.05);
}

TEST(Determinism, SameBodiesGiveBitIdenticalRuns) {
  auto run = [] {
    Container box;
    const std::vector<BodyDef> defs = LatticeBodies(SceneOptions{.n = 20, .seed = 11}, box);
    WorldSettings settings;
    settings.container = box;
    ConventionalWorld world(settings, ConventionalSettings{.dt = 5e-3, .digits = 5});
    for (const BodyDef& def : defs) EXPECT_TRUE(world.AddBody(def).ok());
    std::vector<double> trace;
    world.OnCollision([&](const CollisionEvent& e) { trace.push_back(e.time); });
    EXPECT_TRUE(world.AdvanceTo(2.0).ok());
    for (std::uint32_t i = 0; i < world.BodyCount(); ++i) {
      const BodyState s = world.StateAt(BodyId{i, 0}, 2.0);
      trace.insert(trace.end(), {s.position.x(), s.velocity.y(), s.orientation.w()});
    }
    return trace;
  };
  const std::vector<double> first = run();
  EXPECT_GT(first.size(), 60u);  // some collisions happened
  EXPECT_EQ(first, run());
}

TEST(Conservation, InelasticCollisionsLoseEnergy) {
  Container box;
  std::vector<BodyDef> defs = LatticeBodies(SceneOptions{.n = 8}, box);
  WorldSettings settings;
  settings.container = box;
  ConventionalWorld world(settings, ConventionalSettings{.dt = 2e-3, .digits = 4});
  for (BodyDef& def : defs) {
    def.restitution = 0.5;
    ASSERT_TRUE(world.AddBody(def).ok());
  }
  const double initial = world.KineticEnergy();
  ASSERT_TRUE(world.AdvanceTo(3.0).ok());
  ASSERT_GT(world.Stats().collisions + world.Stats().wall_collisions, 0u);
  EXPECT_LT(world.KineticEnergy(), 0.99 * initial);
}

// --- agreement with the event-driven World ------------------------------------------------------

// The World (main + toi 7e61e39 + dyn 8d53bfb) stalls in open space within ~1 s for most seeds
// of this scene (seed 3: at t = 0.4917, after a clean collision of bodies 18 and 22 at 0.4899);
// seed 8 runs until 1.66, so the open comparison stops before.
constexpr std::uint64_t kOpenSeed = 8;
constexpr double kOpenUntil = 1.6;
constexpr std::size_t kOpenCompared = 12;
constexpr double kWalledUntil = 4.0;
constexpr std::size_t kWalledCompared = 12;

struct Hit {
  double time;
  std::uint32_t a;
  std::uint32_t b;  // kNoIndex for a wall
  int wall;
};

Hit ToHit(const CollisionEvent& e) {
  std::uint32_t a = e.a.index;
  std::uint32_t b = e.b.valid() ? e.b.index : kNoIndex;
  if (b != kNoIndex && b < a) std::swap(a, b);
  return Hit{e.time, a, b, e.wall};
}

// Runs both methods on `defs` until `until` and compares their first `compared` collisions.
void ExpectSameFirstCollisions(const WorldSettings& settings, const std::vector<BodyDef>& defs,
                               double until, std::size_t compared) {
  World reference(settings);
  const ConventionalSettings conventional{.dt = 1e-3, .digits = 6};
  ConventionalWorld stepped(settings, conventional);
  for (const BodyDef& def : defs) {
    ASSERT_TRUE(reference.AddBody(def).ok());
    ASSERT_TRUE(stepped.AddBody(def).ok());
  }
  std::vector<Hit> exact;
  std::vector<Hit> located;
  reference.OnCollision([&](const CollisionEvent& e) { exact.push_back(ToHit(e)); });
  stepped.OnCollision([&](const CollisionEvent& e) { located.push_back(ToHit(e)); });
  const Status reference_status = reference.AdvanceTo(until);
  ASSERT_TRUE(reference_status.ok()) << reference_status.error().message;
  ASSERT_TRUE(stepped.AdvanceTo(until).ok());

  ASSERT_GE(exact.size(), compared) << "the scene should collide more within " << until << " s";
  ASSERT_GE(located.size(), compared);
  // Each located time is within dt 10^-A2 of its exact time; the errors of earlier collisions
  // shift later ones by the same order (speeds ~ 1), hence the allowance growing with k.
  const double resolution = conventional.dt * std::pow(10.0, -conventional.digits);
  for (std::size_t k = 0; k < compared; ++k) {
    SCOPED_TRACE("collision " + std::to_string(k));
    EXPECT_EQ(located[k].a, exact[k].a);
    EXPECT_EQ(located[k].b, exact[k].b);
    EXPECT_EQ(located[k].wall, exact[k].wall);
    EXPECT_NEAR(located[k].time, exact[k].time, 10.0 * resolution * static_cast<double>(k + 1));
  }
}

TEST(AgreesWithWorld, FirstCollisionsInOpenSpace) {
  Container box;
  const std::vector<BodyDef> defs = LatticeBodies(SceneOptions{.n = 27, .seed = kOpenSeed}, box);
  ExpectSameFirstCollisions(WorldSettings{}, defs, kOpenUntil, kOpenCompared);
}

TEST(AgreesWithWorld, FirstCollisionsInAWalledBox) {
  Container box;
  const std::vector<BodyDef> defs = LatticeBodies(SceneOptions{.n = 8, .seed = 3}, box);
  WorldSettings settings;
  settings.container = box;
  settings.broadphase = Broadphase::kAllPairs;
  ExpectSameFirstCollisions(settings, defs, kWalledUntil, kWalledCompared);
}

// --- refused input --------------------------------------------------------------------------

TEST(BadInput, SettingsOutsideTheirRangeAreRefused) {
  const WorldSettings ok_settings;
  EXPECT_TRUE(ConventionalWorld::CheckSettings(ok_settings, {.dt = 0.01, .digits = 4}).ok());
  for (double dt : {0.0, -1.0, std::nan(""), kInfinity}) {
    const Status s = ConventionalWorld::CheckSettings(ok_settings, {.dt = dt, .digits = 4});
    ASSERT_FALSE(s.ok()) << dt;
    EXPECT_NE(s.error().message.find("dt"), std::string::npos);
  }
  EXPECT_FALSE(ConventionalWorld::CheckSettings(ok_settings, {.dt = 0.01, .digits = -1}).ok());
  EXPECT_FALSE(ConventionalWorld::CheckSettings(ok_settings, {.dt = 0.01, .digits = 16}).ok());
  WorldSettings periodic;
  periodic.container = Container::PeriodicBox(Vec3::Zero(), Vec3::Constant(10));
  EXPECT_FALSE(ConventionalWorld::CheckSettings(periodic, {.dt = 0.01, .digits = 4}).ok());
}

TEST(BadInput, SpheresOverlapsOutsidersAndLateBodiesAreRefused) {
  WorldSettings settings;
  settings.container = Container::WalledBox(Vec3::Zero(), Vec3::Constant(10));
  ConventionalWorld world(settings, ConventionalSettings{});
  BodyDef sphere;
  sphere.position = Vec3::Constant(5);
  EXPECT_FALSE(world.AddBody(sphere).ok());  // no shape: spheres are not simulated
  const auto cube = Box(0.5, 0.5, 0.5);
  ASSERT_TRUE(world.AddBody(Body(cube, Vec3::Constant(5), Vec3::Zero())).ok());
  EXPECT_FALSE(world.AddBody(Body(cube, Vec3(5.9, 5, 5), Vec3::Zero())).ok());      // overlaps
  EXPECT_FALSE(world.AddBody(Body(cube, Vec3(9.8, 5, 5), Vec3::Zero())).ok());      // beyond x wall
  EXPECT_FALSE(world.AddBody(Body(cube, Vec3(2, 2, 2), Vec3::Zero(), -1.0)).ok());  // mass
  // A static body would be moved like any other: refused by name.
  BodyDef floor = Body(cube, Vec3(2, 2, 2), Vec3::Zero());
  floor.is_static = true;
  const Result<BodyId> refused = world.AddBody(floor);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("no static bodies"), std::string::npos);
  // So would a god object: refused by name too.
  BodyDef hand = Body(cube, Vec3(2, 2, 2), Vec3::Zero());
  hand.god = GodDef{.max_acceleration = 1.0, .track = {}};
  const Result<BodyId> no_god = world.AddBody(hand);
  ASSERT_FALSE(no_god.ok());
  EXPECT_NE(no_god.error().message.find("no god objects"), std::string::npos);
  EXPECT_EQ(world.BodyCount(), 1u);
  ASSERT_TRUE(world.AdvanceTo(0.1).ok());
  EXPECT_FALSE(world.AddBody(Body(cube, Vec3(2, 2, 2), Vec3::Zero())).ok());  // after the start
}

// --- the command line -------------------------------------------------------------------------

struct CliOutput {
  int status;
  std::string out;  // stdout and stderr
};

CliOutput RunCli(const std::string& arguments) {
  const std::string command = std::string(SPARSEDYN_CLI_PATH) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

const std::string kScene = std::string(SPARSEDYN_SOURCE_DIR) + "/data/scenes/polyhedra_100.json";

TEST(Cli, ConventionalRunPrintsTheContractKeysAndItsOwn) {
  const CliOutput r =
      RunCli("run " + kScene + " --method conventional --dt 0.01 --digits 3 --until 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"bodies", "simulated_time", "wall_seconds", "events", "events_by_kind", "stale_events",
        "meetings", "collisions", "kinetic_energy_initial", "kinetic_energy_final",
        "momentum_initial", "momentum_final", "max_penetration", "method", "dt", "steps"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["method"], "conventional");
  EXPECT_EQ(j["dt"], 0.01);
  EXPECT_EQ(j["steps"], 50);
  EXPECT_EQ(j["bodies"], 100);
  EXPECT_EQ(j["bodies_by_kind"],
            nlohmann::json({{"spheres", 0}, {"polyhedra", 100}, {"static", 0}, {"god", 0}}));
  EXPECT_EQ(j["simulated_time"], 0.5);
}

TEST(Cli, BadMethodOptionsAreClearErrors) {
  struct Case {
    std::string arguments;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"run " + kScene + " --method conventional", "needs --dt"},
      {"run " + kScene + " --method conventional --dt 0", "dt > 0"},
      {"run " + kScene + " --method conventional --dt -0.5", "dt > 0"},
      {"run " + kScene + " --method bogus --dt 0.1", "bogus"},
      {"run " + kScene + " --dt 0.1", "apply to --method conventional"},
      {"run " + kScene + " --method conventional --dt 0.1 --digits 20", "digits"},
      {"run " + kScene + " --digits 3", "apply to --method conventional"},
      {"run --preset gas --n 10 --method conventional --dt 0.1", "periodic"},
  };
  for (const Case& c : cases) {
    const CliOutput r = RunCli(c.arguments);
    EXPECT_NE(r.status, 0) << c.arguments;
    EXPECT_NE(r.out.find(c.says), std::string::npos) << c.arguments << "\n" << r.out;
  }
}

}  // namespace
}  // namespace sparsedyn
