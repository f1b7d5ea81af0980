// SPDX-License-Identifier: MIT
// Grid: neighbour visits against brute force, and renumbering (Permute) keeps every element in
// its cell with the same neighbours.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "broadphase/grid.hpp"

namespace sparsedyn {
namespace {

// Pairs (e, j) with j in the 27 cells around e, found through the grid, in original numbering.
std::set<std::pair<std::uint32_t, std::uint32_t>> NeighbourPairs(
    const Grid& grid, std::uint32_t n, const std::vector<std::uint32_t>& original_of) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t e = 0; e < n; ++e) {
    grid.ForEachNeighbor(e, [&](std::uint32_t j, const Vec3&) {
      pairs.emplace(original_of[e], original_of[j]);
    });
  }
  return pairs;
}

TEST(Grid, NeighboursMatchBruteForceAndSurvivePermutation) {
  for (const bool periodic : {false, true}) {
    Grid::Config config;
    config.hi = Vec3(10, 7, 5);
    config.periodic = periodic;
    config.min_cell_size = 1.0;
    config.target_cell_size = 1.0;
    const std::uint32_t n = 400;
    Grid grid(config, n);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> p(n);
    for (std::uint32_t e = 0; e < n; ++e) {
      p[e] = Vec3(10 * u(rng), 7 * u(rng), 5 * u(rng));
      grid.Insert(e, p[e]);
    }
    // Brute force: j is a neighbour of e iff their cells differ by at most 1 on every axis
    // (cyclically in a periodic grid).
    const std::array<int, 3> dims = grid.Dimensions();
    auto cell = [&](const Vec3& q, int k) {
      return std::min(dims[k] - 1, static_cast<int>(q[k] / grid.CellSize(k)));
    };
    std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
    for (std::uint32_t e = 0; e < n; ++e) {
      for (std::uint32_t j = 0; j < n; ++j) {
        if (j == e) continue;
        bool near = true;
        for (int k = 0; k < 3; ++k) {
          int d = std::abs(cell(p[e], k) - cell(p[j], k));
          if (periodic) d = std::min(d, dims[k] - d);
          near = near && d <= 1;
        }
        if (near) expected.emplace(e, j);
      }
    }
    std::vector<std::uint32_t> identity(n);
    for (std::uint32_t e = 0; e < n; ++e) identity[e] = e;
    EXPECT_EQ(NeighbourPairs(grid, n, identity), expected) << "periodic " << periodic;

    // Renumber along the Morton curve, as World::Reorder does.
    std::vector<std::uint32_t> old_of_new = identity;
    std::stable_sort(old_of_new.begin(), old_of_new.end(), [&](std::uint32_t a, std::uint32_t b) {
      return grid.MortonKey(grid.CellOf(a)) < grid.MortonKey(grid.CellOf(b));
    });
    std::vector<std::uint32_t> old_cells(n);
    for (std::uint32_t e = 0; e < n; ++e) old_cells[e] = grid.CellOf(e);
    grid.Permute(old_of_new);
    for (std::uint32_t e = 0; e < n; ++e) EXPECT_EQ(grid.CellOf(e), old_cells[old_of_new[e]]);
    EXPECT_EQ(NeighbourPairs(grid, n, old_of_new), expected) << "periodic " << periodic;
  }
}

TEST(Grid, MortonKeyInterleavesCoordinateBits) {
  Grid::Config config;
  config.hi = Vec3(8, 8, 8);
  Grid grid(config, 1);
  // Cell (x, y, z) = (1, 0, 0) -> 1, (0, 1, 0) -> 2, (0, 0, 1) -> 4, (3, 3, 3) -> 63.
  grid.Insert(0, Vec3(1.5, 0.5, 0.5));
  EXPECT_EQ(grid.MortonKey(grid.CellOf(0)), 1u);
  grid.Remove(0);
  grid.Insert(0, Vec3(0.5, 1.5, 0.5));
  EXPECT_EQ(grid.MortonKey(grid.CellOf(0)), 2u);
  grid.Remove(0);
  grid.Insert(0, Vec3(0.5, 0.5, 1.5));
  EXPECT_EQ(grid.MortonKey(grid.CellOf(0)), 4u);
  grid.Remove(0);
  grid.Insert(0, Vec3(3.5, 3.5, 3.5));
  EXPECT_EQ(grid.MortonKey(grid.CellOf(0)), 63u);
}

}  // namespace
}  // namespace sparsedyn
