// SPDX-License-Identifier: MIT
// The hard-sphere gas against kinetic theory: the equilibrium collision rate per particle is
// Gamma = sqrt(2) pi sigma^2 n cbar g(sigma) (Enskog), with cbar = sqrt(8 kT / (pi m)) and the
// Carnahan-Starling contact value g = (1 - eta/2) / (1 - eta)^3.
#include <gtest/gtest.h>

#include <cmath>

#include "scenes/gas.hpp"

namespace sparsedyn {
namespace {

// The bound on the deviation from theory; the run is sized so that the statistical
// error of the measured rate (~1/sqrt(collisions), doubled for correlations) is below 0.5%.
constexpr double kRelativeTolerance = 0.02;
constexpr std::uint64_t kMeasuredCollisions = 400000;  // 2/sqrt(4e5) = 0.32%
constexpr double kEquilibrationCollisionsPerParticle = 20;

void CheckCollisionRate(double packing) {
  scenes::GasOptions options;
  options.n = 2000;
  options.packing = packing;
  options.seed = 2026;
  World world = *scenes::MakeGas(options);
  const double side = scenes::GasBoxSide(options);
  const double sigma = 2 * options.radius;
  const double density = options.n / (side * side * side);
  const double g = (1 - packing / 2) / std::pow(1 - packing, 3);
  // kT from the kinetic energy with 3N - 3 degrees of freedom (the total momentum is zero).
  const double kT = 2 * world.KineticEnergy() / (3.0 * options.n - 3.0);
  const double cbar = std::sqrt(8 * kT / (M_PI * options.mass));
  const double gamma = std::sqrt(2.0) * M_PI * sigma * sigma * density * cbar * g;

  // Equilibrate (the lattice start at high packing needs it), then count.
  const double t_equilibrate = kEquilibrationCollisionsPerParticle / gamma;
  ASSERT_TRUE(world.AdvanceTo(t_equilibrate));
  const std::uint64_t before = world.Stats().collisions;
  const double t_measure = 2.0 * kMeasuredCollisions / (options.n * gamma);
  ASSERT_TRUE(world.AdvanceTo(t_equilibrate + t_measure));
  const double collisions = static_cast<double>(world.Stats().collisions - before);
  const double measured = 2 * collisions / (options.n * t_measure);
  std::printf("packing %.2f: measured %.5f, Enskog-CS %.5f per particle per unit time (%+.2f%%)\n",
              packing, measured, gamma, 100 * (measured / gamma - 1));
  EXPECT_NEAR(measured / gamma, 1.0, kRelativeTolerance);
  EXPECT_LT(world.MaxPenetration(), 1e-9);
}

TEST(KineticTheory, CollisionRateMatchesEnskogAtPacking005) { CheckCollisionRate(0.05); }
TEST(KineticTheory, CollisionRateMatchesEnskogAtPacking010) { CheckCollisionRate(0.10); }
TEST(KineticTheory, CollisionRateMatchesEnskogAtPacking030) { CheckCollisionRate(0.30); }

}  // namespace
}  // namespace sparsedyn
