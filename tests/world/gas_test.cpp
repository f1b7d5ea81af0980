// SPDX-License-Identifier: MIT
// Many-body checks on the gas preset: conservation, no overlap, no stale event taken as live,
// broad phases agree, determinism.
#include "scenes/gas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

// Gap (negative = overlap) of two bodies at time t, minimum image in the periodic box.
double GapAt(const World& world, BodyId a, BodyId b, double t, double side) {
  Vec3 d = world.StateAt(b, t).position - world.StateAt(a, t).position;
  for (int k = 0; k < 3; ++k) d[k] -= side * std::round(d[k] / side);
  return d.norm() - world.StateAt(a, t).radius - world.StateAt(b, t).radius;
}

TEST(Gas, ElasticGasConservesEnergyAndMomentumOverHundredThousandCollisions) {
  scenes::GasOptions options;
  options.n = 1000;
  options.packing = 0.10;
  options.seed = 11;
  World world = *scenes::MakeGas(options);
  const double side = scenes::GasBoxSide(options);
  const double energy = world.KineticEnergy();
  const Vec3 momentum = world.Momentum();
  double momentum_scale = 0;  // sum of |m v|: the scale of momentum round-off
  for (std::uint32_t i = 0; i < options.n; ++i) {
    momentum_scale += world.StateAt(world.IdOf(i), 0).velocity.norm();
  }

  // Every collision reported must be between bodies that touch at that moment: a stale event
  // processed as live would collide bodies that are apart.
  double worst_gap = 0;
  std::uint64_t apart = 0;
  world.OnCollision([&](const CollisionEvent& e) {
    const double gap = GapAt(world, e.a, e.b, e.time, side);
    worst_gap = std::max(worst_gap, std::abs(gap));
    if (gap > 1e-9) ++apart;
  });
  double t = 0;
  while (world.Stats().collisions < 100000) {
    t += 5;
    ASSERT_TRUE(world.AdvanceTo(t));
  }
  EXPECT_EQ(apart, 0u);
  EXPECT_LT(worst_gap, 1e-9);
  EXPECT_LT(world.MaxPenetration(), 1e-9);
  EXPECT_LT(std::abs(world.KineticEnergy() - energy) / energy, 1e-10);
  EXPECT_LT((world.Momentum() - momentum).norm() / momentum_scale, 1e-10);
  EXPECT_TRUE(world.Validate());
  std::printf("collisions %llu, energy drift %.3g, deepest overlap %.3g, stale %llu + %llu\n",
              static_cast<unsigned long long>(world.Stats().collisions),
              std::abs(world.KineticEnergy() - energy) / energy, world.MaxPenetration(),
              static_cast<unsigned long long>(world.Stats().stale_target_absent),
              static_cast<unsigned long long>(world.Stats().stale_actor_absent));
}

// Beyond 40,000 elements the World fetches the data of the coming events ahead (FetchAhead):
// fetches only, so the run must keep every invariant; the sanitizer build checks that every
// fetch's index stays in bounds. Two runs must agree to the bit.
TEST(Gas, LargeGasFetchedAheadKeepsItsInvariantsAndIsDeterministic) {
  auto run = [](std::vector<double>& state) {
    scenes::GasOptions options;
    options.n = 50000;
    options.seed = 17;
    World world = *scenes::MakeGas(options);
    const double side = scenes::GasBoxSide(options);
    const double energy = world.KineticEnergy();
    std::uint64_t apart = 0;
    world.OnCollision([&](const CollisionEvent& e) {
      if (GapAt(world, e.a, e.b, e.time, side) > 1e-9) ++apart;
    });
    EXPECT_TRUE(world.AdvanceTo(0.5));  // about 0.2 collisions per particle
    EXPECT_GT(world.Stats().collisions, 5000u);
    EXPECT_EQ(apart, 0u);
    EXPECT_LT(world.MaxPenetration(), 1e-9);
    EXPECT_LT(std::abs(world.KineticEnergy() - energy) / energy, 1e-10);
    EXPECT_TRUE(world.Validate());
    for (std::uint32_t i = 0; i < world.BodyCount(); i += 97) {
      const BodyState b = world.StateAt(world.IdOf(i), 0.5);
      state.insert(state.end(), {b.position.x(), b.position.y(), b.position.z(), b.velocity.x()});
    }
    state.push_back(static_cast<double>(world.Stats().events));
  };
  std::vector<double> first, second;
  run(first);
  run(second);
  ASSERT_EQ(first.size(), second.size());
  EXPECT_EQ(0, std::memcmp(first.data(), second.data(), first.size() * sizeof(double)));
}

struct Collision {
  double time;
  std::uint32_t a, b;
  int wall;
};

std::vector<Collision> CollisionSequence(Broadphase broadphase, bool periodic, std::size_t count) {
  scenes::GasOptions options;
  options.n = 300;
  options.packing = 0.10;
  options.seed = 5;
  options.periodic = periodic;
  WorldSettings settings;
  settings.broadphase = broadphase;
  World world = *scenes::MakeGas(options, settings);
  std::vector<Collision> out;
  world.OnCollision([&](const CollisionEvent& e) {
    // Order the pair so that the report does not depend on which element was the actor.
    const std::uint32_t lo = e.b.valid() ? std::min(e.a.index, e.b.index) : e.a.index;
    const std::uint32_t hi = e.b.valid() ? std::max(e.a.index, e.b.index) : kNoIndex;
    out.push_back({e.time, lo, hi, e.wall});
  });
  double t = 0;
  while (out.size() < count) {
    t += 1;
    EXPECT_TRUE(world.AdvanceTo(t));
  }
  out.resize(count);
  return out;
}

void ExpectSameSequence(bool periodic) {
  // Each meeting time is computed from the two paths alone (not from the time of prediction),
  // so in a walled box the two broad phases agree to the bit. In a periodic box one broad phase
  // may predict a pair before a wrap and the other after it (p0 - L rounds differently), so
  // times agree to round-off only, and chaos makes such runs part after ~1700 collisions here.
  // TODO(#2): keep unwrapped positions with integer image counts to make periodic runs exact.
  const std::size_t kCollisions = periodic ? 1500 : 5000;
  const double time_tolerance = periodic ? 1e-9 : 0.0;
  const std::vector<Collision> all_pairs =
      CollisionSequence(Broadphase::kAllPairs, periodic, kCollisions);
  const std::vector<Collision> grid = CollisionSequence(Broadphase::kGrid, periodic, kCollisions);
  for (std::size_t k = 0; k < kCollisions; ++k) {
    SCOPED_TRACE(::testing::Message() << "collision " << k);
    ASSERT_EQ(all_pairs[k].a, grid[k].a);
    ASSERT_EQ(all_pairs[k].b, grid[k].b);
    ASSERT_EQ(all_pairs[k].wall, grid[k].wall);
    ASSERT_NEAR(all_pairs[k].time, grid[k].time, time_tolerance);
  }
}

TEST(Gas, AllPairsAndGridGiveTheSameCollisionsInPeriodicBox) { ExpectSameSequence(true); }
TEST(Gas, AllPairsAndGridGiveTheSameCollisionsInWalledBox) { ExpectSameSequence(false); }

TEST(Gas, SameSeedGivesBitIdenticalRuns) {
  auto run = [] {
    scenes::GasOptions options;
    options.n = 500;
    options.seed = 3;
    World world = *scenes::MakeGas(options);
    EXPECT_TRUE(world.AdvanceTo(20));
    std::vector<double> state;
    for (std::uint32_t i = 0; i < world.BodyCount(); ++i) {
      const BodyState s = world.StateAt(world.IdOf(i), 20);
      state.insert(state.end(), {s.position.x(), s.position.y(), s.position.z(), s.velocity.x(),
                                 s.velocity.y(), s.velocity.z()});
    }
    state.push_back(static_cast<double>(world.Stats().events));
    state.push_back(static_cast<double>(world.Stats().collisions));
    return state;
  };
  const std::vector<double> first = run();
  const std::vector<double> second = run();
  ASSERT_EQ(first.size(), second.size());
  EXPECT_EQ(0, std::memcmp(first.data(), second.data(), first.size() * sizeof(double)));
}

TEST(Gas, PhaseTimesAreMeasuredOnlyWhenProfiling) {
  scenes::GasOptions options;
  options.n = 500;
  for (const bool profile : {false, true}) {
    WorldSettings settings;
    settings.profile_phases = profile;
    World world = *scenes::MakeGas(options, settings);
    ASSERT_TRUE(world.AdvanceTo(10));
    const Statistics& stats = world.Stats();
    ASSERT_GT(stats.collisions, 100u);
    if (profile) {
      EXPECT_GT(stats.seconds_sparse, 0.0);
      EXPECT_GT(stats.seconds_queue, 0.0);
      EXPECT_GT(stats.seconds_response, 0.0);
    } else {
      EXPECT_EQ(stats.seconds_sparse + stats.seconds_queue + stats.seconds_response, 0.0);
    }
  }
}

TEST(Gas, InelasticGasCoolsWithoutStallingThanksToTheCollapseGuard) {
  scenes::GasOptions options;
  options.n = 400;
  options.packing = 0.2;
  options.restitution = 0.8;
  World world = *scenes::MakeGas(options);
  const double energy = world.KineticEnergy();
  ASSERT_TRUE(world.AdvanceTo(50));
  EXPECT_LT(world.KineticEnergy(), 0.5 * energy);
  EXPECT_LT(world.MaxPenetration(), 1e-9);
}

}  // namespace
}  // namespace sparsedyn
