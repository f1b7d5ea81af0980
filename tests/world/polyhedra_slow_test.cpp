// SPDX-License-Identifier: MIT
// Long-run invariants of the polyhedral World (issue #4): 200 rotating polyhedra in a walled
// box, restitution 1, friction 0, 10^4 collisions, checked at 10^4 random times.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sparsedyn/world.hpp"
#include "world/polyhedra_scene.hpp"

namespace sparsedyn {
namespace {

TEST(PolyhedraWorldSlow, TenThousandCollisionsKeepEnergyAndNeverInterpenetrate) {
  testing::PolyhedraSceneOptions options;
  options.n = 200;
  options.spacing = 2.4;
  options.seed = 21;
  World world = testing::MakePolyhedraWorld(options);
  const double energy = world.KineticEnergy();
  std::mt19937_64 rng(3);
  std::exponential_distribution<double> gap(1.0 / 2e-3);
  double t = 0;
  int samples = 0;
  while (world.Stats().collisions < 10000 && t < 1e4) {
    t += gap(rng);
    ASSERT_TRUE(world.AdvanceTo(t).ok());
    const Status valid = world.Validate();
    ASSERT_TRUE(valid.ok()) << valid.error().message;
    ++samples;
  }
  EXPECT_GE(world.Stats().collisions, 10000u);
  EXPECT_GE(samples, 10000);
  EXPECT_LE(std::abs(world.KineticEnergy() - energy), 1e-9 * energy);
  EXPECT_LE(world.MaxPenetration(), 2e-9);
  EXPECT_EQ(world.Stats().walk_cap_hits, 0u);
  RecordProperty("collisions", static_cast<int>(world.Stats().collisions));
  RecordProperty("samples", samples);
}

}  // namespace
}  // namespace sparsedyn
