// SPDX-License-Identifier: MIT
// Grid: neighbour visits against brute force (with their periodic image shifts, around every
// cell and after every crossing), renumbering (Permute) keeps every element in its cell with the
// same neighbours, and links kept in the owner's records act as the grid's own.
#include "broadphase/grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

// Pairs (e, j) with j in the 27 cells around e, found through the grid, in original numbering.
std::set<std::pair<std::uint32_t, std::uint32_t>> NeighbourPairs(
    const Grid& grid, std::uint32_t n, const std::vector<std::uint32_t>& original_of) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t e = 0; e < n; ++e) {
    grid.ForEachNeighbor(
        e, [&](std::uint32_t j, const Vec3&) { pairs.emplace(original_of[e], original_of[j]); });
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

// The links kept in the owner's records (UseLinks, as the World keeps them beside each path
// start) against the grid's own: the same cells and neighbours through inserts, removals from
// every place of a list (head, middle, end: the lists are singly linked), moves across every
// side and a renumbering in which the owner moves its records first; the rest of each record
// is never written.
TEST(Grid, LinksInTheOwnersRecordsActAsItsOwn) {
  struct alignas(64) Record {
    std::array<std::uint8_t, 56> payload;
    GridLinks links;
  };
  Grid::Config config;
  config.hi = Vec3(6, 5, 4);
  config.periodic = true;
  const std::uint32_t n = 300;  // ~2.5 per cell: lists of every length
  Grid own(config, n), shared(config, n);
  std::vector<Record> records(n);
  for (std::uint32_t e = 0; e < n; ++e) records[e].payload.fill(static_cast<std::uint8_t>(e));
  shared.UseLinks(&records[0].links, 6, n);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::uint32_t e = 0; e < n; ++e) {
    const Vec3 p(6 * u(rng), 5 * u(rng), 4 * u(rng));
    own.Insert(e, p);
    shared.Insert(e, p);
  }
  std::vector<std::uint32_t> identity(n);
  for (std::uint32_t e = 0; e < n; ++e) identity[e] = e;
  const auto expect_same = [&](const std::vector<std::uint32_t>& original_of) {
    for (std::uint32_t e = 0; e < n; ++e) {
      ASSERT_EQ(shared.CellOf(e), own.CellOf(e)) << e;
      ASSERT_EQ(records[e].links.cell, own.CellOf(e)) << e;  // the links live in the records
    }
    EXPECT_EQ(NeighbourPairs(shared, n, original_of), NeighbourPairs(own, n, identity));
  };
  expect_same(identity);
  std::uniform_int_distribution<std::uint32_t> pick(0, n - 1);
  for (int step = 0; step < 3000; ++step) {
    const std::uint32_t e = pick(rng);
    if (step % 10 == 0) {  // out and back in elsewhere
      const Vec3 p(6 * u(rng), 5 * u(rng), 4 * u(rng));
      own.Remove(e);
      shared.Remove(e);
      own.Insert(e, p);
      shared.Insert(e, p);
      continue;
    }
    const int axis = step % 3;
    const int direction = (step / 3) % 2 == 0 ? 1 : -1;
    Vec3 own_shift, shared_shift;
    const Grid::Place a = own.Move(e, axis, direction, own_shift);
    const Grid::Place b = shared.Move(e, axis, direction, shared_shift);
    ASSERT_EQ(a.cell, b.cell);
    ASSERT_EQ(own_shift, shared_shift);
  }
  expect_same(identity);

  // Renumbered: the owner moves its records (links included), then the grid relinks.
  std::vector<std::uint32_t> old_of_new = identity;
  std::shuffle(old_of_new.begin(), old_of_new.end(), rng);
  std::vector<Record> moved(n);
  for (std::uint32_t e = 0; e < n; ++e) moved[e] = records[old_of_new[e]];
  records.swap(moved);
  shared.UseLinks(&records[0].links, 6, n);
  shared.Permute(old_of_new);
  for (std::uint32_t e = 0; e < n; ++e) {
    ASSERT_EQ(shared.CellOf(e), own.CellOf(old_of_new[e])) << e;
    for (const std::uint8_t byte : records[e].payload) {
      ASSERT_EQ(byte, static_cast<std::uint8_t>(old_of_new[e]));
    }
  }
  EXPECT_EQ(NeighbourPairs(shared, n, old_of_new), NeighbourPairs(own, n, identity));
}

// Brute force for a visit around cell `c`: every j != e whose cell, shifted by whole periods,
// is c + u for some u with u[k] in `offsets[k]`; the value is the image shift that takes j's
// position there. A cell matched twice would be a visit that double counts: none with >= 3
// cells per axis.
using Visits = std::map<std::uint32_t, Vec3>;
Visits ExpectedVisits(const Grid& grid, const Grid::Config& config, const std::vector<Vec3>& p,
                      std::uint32_t e, const std::array<int, 3>& c,
                      const std::array<std::vector<int>, 3>& offsets) {
  const std::array<int, 3> dims = grid.Dimensions();
  const Vec3 length = config.hi - config.lo;
  Visits expected;
  for (std::uint32_t j = 0; j < p.size(); ++j) {
    if (j == e) continue;
    Vec3 shift = Vec3::Zero();
    bool near = true;
    for (int k = 0; k < 3 && near; ++k) {
      const int cj = std::min(dims[k] - 1, static_cast<int>(p[j][k] / grid.CellSize(k)));
      int matches = 0;
      for (const int u : offsets[static_cast<std::size_t>(k)]) {
        const int target = c[k] + u;  // unwrapped
        if (!config.periodic && (target < 0 || target >= dims[k])) continue;
        const int wraps = target < 0 ? -1 : (target >= dims[k] ? 1 : 0);
        if (target - wraps * dims[k] != cj) continue;
        ++matches;
        shift[k] = wraps * length[k];
      }
      EXPECT_LE(matches, 1);
      near = matches == 1;
    }
    if (near) expected.emplace(j, shift);
  }
  return expected;
}

TEST(Grid, VisitsAroundACellAndAfterACrossingMatchBruteForceWithShifts) {
  for (const bool periodic : {false, true}) {
    Grid::Config config;
    config.hi = Vec3(10, 7, 5);  // 10 x 7 x 5 cells: interior cells and every kind of edge
    config.periodic = periodic;
    const std::uint32_t n = 300;
    Grid grid(config, n);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> p(n);
    for (std::uint32_t e = 0; e < n; ++e) {
      p[e] = Vec3(10 * u(rng), 7 * u(rng), 5 * u(rng));
      grid.Insert(e, p[e]);
    }
    const std::array<int, 3> dims = grid.Dimensions();
    const std::vector<int> around = {-1, 0, 1};
    int interior_moves = 0, edge_moves = 0;
    for (std::uint32_t e = 0; e < n; ++e) {
      std::array<int, 3> c{};
      for (int k = 0; k < 3; ++k) {
        c[k] = std::min(dims[k] - 1, static_cast<int>(p[e][k] / grid.CellSize(k)));
      }
      Visits visited;
      grid.ForEachNeighbor(e, grid.PlaceOf(e), [&](std::uint32_t j, const Vec3& shift) {
        EXPECT_TRUE(visited.emplace(j, shift).second) << "visited twice: " << j;
      });
      EXPECT_EQ(visited, ExpectedVisits(grid, config, p, e, c, {around, around, around}))
          << "around element " << e << " periodic " << periodic;

      for (int axis = 0; axis < 3; ++axis) {
        for (const int direction : {-1, 1}) {
          std::array<int, 3> moved = c;
          moved[axis] += direction;
          if (!periodic && (moved[axis] < 0 || moved[axis] >= dims[axis])) continue;
          moved[axis] = (moved[axis] + dims[axis]) % dims[axis];
          Vec3 shift;
          const Grid::Place place = grid.Move(e, axis, direction, shift);
          EXPECT_EQ(place.at, moved);
          EXPECT_EQ(place.cell, grid.CellOf(e));
          const bool interior = moved[0] > 0 && moved[0] < dims[0] - 1 && moved[1] > 0 &&
                                moved[1] < dims[1] - 1 && moved[2] > 0 && moved[2] < dims[2] - 1;
          (interior ? interior_moves : edge_moves) += 1;
          std::array<std::vector<int>, 3> offsets = {around, around, around};
          offsets[static_cast<std::size_t>(axis)] = {direction};
          Visits fresh;
          grid.ForEachNewNeighbor(e, place, axis, direction,
                                  [&](std::uint32_t j, const Vec3& image) {
                                    EXPECT_TRUE(fresh.emplace(j, image).second) << j;
                                  });
          EXPECT_EQ(fresh, ExpectedVisits(grid, config, p, e, moved, offsets))
              << "element " << e << " moved along " << axis << " by " << direction << " periodic "
              << periodic;
          Vec3 back;
          grid.Move(e, axis, -direction, back);
          EXPECT_EQ(grid.PlaceOf(e).at, c);
        }
      }
    }
    EXPECT_GT(interior_moves, 100);
    EXPECT_GT(edge_moves, 100);
  }
}

// The gathered visits (the batch form, interior cells only) visit the same elements as the
// plain visits, plus the element itself around its own cell, each once; cells with long lists
// (5000 elements in 504 cells, ~270 around a cell) are followed to their ends.
TEST(Grid, GatheredVisitsAreTheVisits) {
  Grid::Config config;
  config.hi = Vec3(9, 8, 7);
  config.periodic = true;
  for (const std::uint32_t n : {200u, 5000u}) {
    Grid grid(config, n);
    std::mt19937_64 rng(n);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (std::uint32_t e = 0; e < n; ++e) grid.Insert(e, Vec3(9 * u(rng), 8 * u(rng), 7 * u(rng)));
    BigVector<std::uint32_t> pending;
    int interior = 0;
    std::size_t most = 0;
    for (std::uint32_t e = 0; e < n; ++e) {
      const Grid::Place place = grid.PlaceOf(e);
      if (!grid.Interior(place)) continue;
      ++interior;
      std::multiset<std::uint32_t> visited = {e};
      grid.ForEachNeighbor(e, place, [&](std::uint32_t j, const Vec3& shift) {
        EXPECT_EQ(shift, Vec3::Zero());
        visited.insert(j);
      });
      std::multiset<std::uint32_t> gathered;
      grid.ForEachGatheredAround(place, pending, [&](std::uint32_t j, const Vec3& shift) {
        EXPECT_EQ(shift, Vec3::Zero());
        gathered.insert(j);
      });
      EXPECT_EQ(gathered, visited) << e;
      most = std::max(most, gathered.size());
      for (int axis = 0; axis < 3; ++axis) {
        for (const int direction : {-1, 1}) {
          std::multiset<std::uint32_t> fresh, gathered_new;
          grid.ForEachNewNeighbor(e, place, axis, direction,
                                  [&](std::uint32_t j, const Vec3&) { fresh.insert(j); });
          grid.ForEachGatheredNew(place, axis, direction, pending,
                                  [&](std::uint32_t j, const Vec3&) { gathered_new.insert(j); });
          EXPECT_EQ(gathered_new, fresh) << e << " " << axis << " " << direction;
        }
      }
    }
    EXPECT_GT(interior, static_cast<int>(n) / 5);
    if (n == 5000) {
      EXPECT_GT(most, 200u) << "some cells should hold long lists";
    }
  }
}

// The gathers for any place (the outer layer's wrap or walls included) against the walks
// element by element: the same elements with the same image shifts (e itself with none), and
// ImageShift gives each neighbour's shift back. Periodic grids of 3 cells along an axis (where
// both neighbours of an outer cell wrap to the same far side) and of more; a walled grid.
TEST(Grid, WrappedGathersAreTheVisitsWithTheirShifts) {
  using Visit = std::pair<std::uint32_t, std::array<double, 3>>;
  const auto visit = [](std::uint32_t j, const Vec3& shift) {
    return Visit{j, {shift[0], shift[1], shift[2]}};
  };
  for (const bool periodic : {true, false}) {
    for (const Vec3& hi : {Vec3(9, 8, 7), Vec3(3.5, 5, 12)}) {
      Grid::Config config;
      config.hi = hi;
      config.periodic = periodic;
      ASSERT_TRUE(Grid::Feasible(config));
      const std::uint32_t n = 600;
      Grid grid(config, n);
      std::mt19937_64 rng(periodic ? 11 : 12);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      for (std::uint32_t e = 0; e < n; ++e) {
        grid.Insert(e, Vec3(hi[0] * u(rng), hi[1] * u(rng), hi[2] * u(rng)));
      }
      EXPECT_EQ(grid.Dimensions()[0], hi[0] < 4 ? 3 : 8);  // cells just over 1
      BigVector<std::uint32_t> pending;
      int outer = 0, shifted = 0;
      for (std::uint32_t e = 0; e < n; ++e) {
        const Grid::Place place = grid.PlaceOf(e);
        outer += grid.Interior(place) ? 0 : 1;
        std::multiset<Visit> visited = {visit(e, Vec3::Zero())};
        grid.ForEachNeighbor(e, place, [&](std::uint32_t j, const Vec3& shift) {
          visited.insert(visit(j, shift));
          EXPECT_EQ(grid.ImageShift(place, j), shift) << e << " " << j;
          shifted += shift.isZero(0.0) ? 0 : 1;
        });
        std::multiset<Visit> gathered;
        grid.ForEachGatheredAroundWrapped(place, pending, [&](std::uint32_t j, const Vec3& shift) {
          gathered.insert(visit(j, shift));
        });
        EXPECT_EQ(gathered, visited) << e;
        for (int axis = 0; axis < 3; ++axis) {
          for (const int direction : {-1, 1}) {
            std::multiset<Visit> fresh, gathered_new;
            grid.ForEachNewNeighbor(e, place, axis, direction, [&](std::uint32_t j, const Vec3& s) {
              fresh.insert(visit(j, s));
            });
            grid.ForEachGatheredNewWrapped(
                place, axis, direction, pending,
                [&](std::uint32_t j, const Vec3& s) { gathered_new.insert(visit(j, s)); });
            EXPECT_EQ(gathered_new, fresh) << e << " " << axis << " " << direction;
          }
        }
      }
      EXPECT_GT(outer, static_cast<int>(n) / 4);
      if (periodic) {
        EXPECT_GT(shifted, 100) << "the neighbourhoods should wrap";
      } else {
        EXPECT_EQ(shifted, 0);
      }
    }
  }
}

// The straight-line crossing (branch-free, from the face table) against the general one
// (SlabExitTime per axis) bit for bit, with axis and direction, velocity components that are
// zero included, in a periodic and a walled grid.
TEST(Grid, LinearCrossingIsTheGeneralCrossingBitForBit) {
  // Floating-point traps paused (docs/reliability.md): a zero velocity
  // component crosses no cell wall, which the crossing times get from 1/0 = +infinity.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  for (const bool periodic : {true, false}) {
    Grid::Config config;
    config.lo = Vec3(-1.5, 0.25, 3);
    config.hi = Vec3(8.5, 7.25, 9);
    config.periodic = periodic;
    Grid grid(config, 1);
    std::mt19937_64 rng(periodic ? 5 : 6);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int zero_components = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      const Vec3 p = config.lo + (config.hi - config.lo).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
      Vec3 v(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
      for (int k = 0; k < 3; ++k) {
        if (trial % (k + 4) == 0) {
          v[k] = 0.0;
          ++zero_components;
        }
      }
      grid.Insert(0, p);
      const Grid::Place place = grid.PlaceOf(0);
      const double min_dt = trial % 3 == 0 ? 0.0 : u(rng);
      int axis = -1, direction = 0, general_axis = -1, general_direction = 0;
      const double linear = grid.PredictLinearCrossing(p, v, place, min_dt, axis, direction);
      const Mover m{p, v, Vec3::Zero(), 0.5, 0.0, 0.0};
      const double general =
          grid.PredictCrossing(m, place.cell, min_dt, general_axis, general_direction);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(linear), std::bit_cast<std::uint64_t>(general))
          << trial << ": " << linear << " vs " << general;
      if (general != kInfinity) {
        EXPECT_EQ(axis, general_axis) << trial;
        EXPECT_EQ(direction, general_direction) << trial;
      }
      grid.Remove(0);
    }
    EXPECT_GT(zero_components, 5000);
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
