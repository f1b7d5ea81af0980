// SPDX-License-Identifier: MIT
// The gas preset's random placement against brute force: replaying the same random draws and
// testing each candidate against every sphere placed so far gives the same positions, periodic
// and walled, dense and dilute; a very dilute gas no longer allocates a cell per diameter cubed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "scenes/gas.hpp"
#include "scenes/random.hpp"

namespace sparsedyn::scenes {
namespace {

// Random sequential placement by brute force, drawing exactly as the preset does (three
// uniforms per attempt, z first) and accepting a candidate no closer than one diameter to any sphere;
// nullopt where the preset gives up for the lattice (after 200 attempts per sphere).
std::optional<std::vector<Vec3>> PlaceByBruteForce(const GasOptions& o) {
  const double side = GasBoxSide(o);
  const double diameter = 2 * o.radius;
  const double lo = o.periodic ? 0.0 : o.radius;
  const double hi = o.periodic ? side : side - o.radius;
  Random random(o.seed);
  std::vector<Vec3> placed;
  std::uint64_t attempts = 0;
  while (placed.size() < o.n) {
    if (++attempts > 200ull * o.n) return std::nullopt;
    // In the preset's order (DrawVector: z, y, x), not the compiler's order of arguments.
    const Vec3 p = DrawVector([&] { return random.Uniform(lo, hi); });
    bool free = true;
    for (const Vec3& q : placed) {
      Vec3 d = q - p;
      if (o.periodic) {
        for (int k = 0; k < 3; ++k) d[k] -= side * std::round(d[k] / side);
      }
      if (d.squaredNorm() < diameter * diameter) {
        free = false;
        break;
      }
    }
    if (free) placed.push_back(p);
  }
  return placed;
}

// True when the random placement succeeded (and was compared).
bool ExpectBruteForcePositions(const GasOptions& options) {
  Result<std::vector<BodyDef>> bodies = MakeGasBodies(options);
  EXPECT_TRUE(bodies) << bodies.error().message;
  const std::optional<std::vector<Vec3>> expected = PlaceByBruteForce(options);
  if (!bodies || !expected) return false;
  EXPECT_EQ(bodies->size(), expected->size());
  for (std::size_t i = 0; i < expected->size(); ++i) {
    EXPECT_EQ((*bodies)[i].position, (*expected)[i]) << "body " << i;
    if ((*bodies)[i].position != (*expected)[i]) break;
  }
  return true;
}

TEST(GasPlacement, RandomPlacementIsTheBruteForceOneDrawForDraw) {
  int compared = 0;
  for (const bool periodic : {true, false}) {
    for (const double packing : {0.25, 0.05, 1e-3}) {
      for (const std::uint32_t n : {1u, 7u, 2000u}) {
        SCOPED_TRACE(testing::Message()
                     << "periodic " << periodic << ", packing " << packing << ", n " << n);
        compared += ExpectBruteForcePositions(
            {.n = n, .packing = packing, .seed = 11, .periodic = periodic});
      }
    }
  }
  // Only a few walls-and-dense cases may jam into the lattice fallback.
  EXPECT_GE(compared, 16);
}

TEST(GasPlacement, AVeryDiluteGasIsPlacedWithoutACellPerDiameterCubed) {
  // At packing 1e-7 the box holds ~1.6e10 diameters cubed for 3000 spheres: one cell per
  // diameter would need ~390 GB of cell heads; the capped cell list needs ~6000.
  EXPECT_TRUE(ExpectBruteForcePositions({.n = 3000, .packing = 1e-7, .seed = 4}));
}

}  // namespace
}  // namespace sparsedyn::scenes
