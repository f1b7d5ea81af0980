// SPDX-License-Identifier: MIT
// AddBody's overlap index against brute force: every body within reach is offered, once, in
// open, walled and periodic containers, with growing radii (rebuilds), coordinates on cell
// boundaries and queries far larger than the cells.
#include "broadphase/overlap_index.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

struct Body {
  Vec3 p;
  double r;
};

// Minimum image per periodic axis (length > 0), plain difference otherwise.
Vec3 Separation(const Vec3& a, const Vec3& b, const Vec3& length) {
  Vec3 d = b - a;
  for (int k = 0; k < 3; ++k) {
    if (length[k] > 0) d[k] -= length[k] * std::round(d[k] / length[k]);
  }
  return d;
}

// Adds `bodies` one by one; before each Add, queries it (as AddBody does) and a random probe,
// and checks that the index offers every body the brute force finds within reach, and each once.
void CheckAgainstBruteForce(const Vec3& origin, const Vec3& length, const std::vector<Body>& bodies,
                            std::mt19937_64& rng, double probe_lo, double probe_hi) {
  OverlapIndex index(origin, length);
  std::uniform_real_distribution<double> coordinate(probe_lo, probe_hi);
  std::uniform_real_distribution<double> probe_radius(0.0, 3.0);
  std::size_t offered_total = 0, near_total = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Body probe{Vec3(coordinate(rng), coordinate(rng), coordinate(rng)), probe_radius(rng)};
    for (const Body& query : {bodies[i], probe}) {
      std::multiset<std::uint32_t> offered;
      index.ForEachNear(query.p, query.r, [&](std::uint32_t j, const Vec3& q, double r) {
        ASSERT_LT(j, i);
        EXPECT_EQ(q, bodies[j].p);
        EXPECT_EQ(r, bodies[j].r);
        offered.insert(j);
      });
      for (std::uint32_t j = 0; j < i; ++j) {
        EXPECT_LE(offered.count(j), 1u) << "body " << j << " offered twice";
        const double reach = query.r + bodies[j].r;
        if (Separation(query.p, bodies[j].p, length).squaredNorm() <= reach * reach) {
          ++near_total;
          EXPECT_EQ(offered.count(j), 1u)
              << "body " << j << " within reach of the query before body " << i << " missed";
        }
      }
      offered_total += offered.size();
    }
    index.Add(bodies[i].p, bodies[i].r);
  }
  // The sample must test something, and the index must prune (not offer everything).
  EXPECT_GT(near_total, bodies.size() / 4);
  EXPECT_LT(offered_total, bodies.size() * bodies.size() / 4);
}

std::vector<Body> RandomBodies(std::mt19937_64& rng, int n, double lo, double hi, double r_lo,
                               double r_hi) {
  std::uniform_real_distribution<double> coordinate(lo, hi), radius(r_lo, r_hi);
  std::vector<Body> bodies;
  for (int i = 0; i < n; ++i) {
    bodies.push_back({Vec3(coordinate(rng), coordinate(rng), coordinate(rng)), radius(rng)});
  }
  return bodies;
}

TEST(OverlapIndex, OffersEveryBodyWithinReachOnceInAPeriodicBox) {
  std::mt19937_64 rng(1);
  // A length that is no multiple of the cell size, non-cubic, not at the origin.
  const Vec3 origin(-3.0, 1.0, 0.5), length(23.7, 19.1, 31.3);
  std::vector<Body> bodies = RandomBodies(rng, 1500, 0.0, 1.0, 0.2, 0.6);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (Body& b : bodies) {
    for (int k = 0; k < 3; ++k) b.p[k] = origin[k] + unit(rng) * length[k];
  }
  // Bodies on the box's faces and near its far faces, where the cells wrap.
  bodies[7].p = origin;
  bodies[9].p = origin + length * (1 - 1e-15);
  bodies[11].p = Vec3(origin[0], origin[1] + length[1] - 1e-12, origin[2] + 3.0);
  CheckAgainstBruteForce(origin, length, bodies, rng, -5.0, 30.0);
}

TEST(OverlapIndex, OffersEveryBodyWithinReachOnceInAnOpenSpaceWithGrowingRadii) {
  std::mt19937_64 rng(2);
  std::vector<Body> bodies = RandomBodies(rng, 1500, -12.0, 12.0, 0.05, 0.3);
  // Larger bodies now and then rebuild the cells; one spans many cells.
  bodies[100].r = 1.0;
  bodies[700].r = 2.5;
  bodies[1490].r = 9.0;  // late: after it every query reaches 9 + its radius
  // Bodies exactly on cell boundaries of several cell sizes.
  bodies[50].p = Vec3(0.0, 1.0, -2.0);
  bodies[51].p = Vec3(1.2, 2.4, 4.8);
  CheckAgainstBruteForce(Vec3::Zero(), Vec3::Zero(), bodies, rng, -14.0, 14.0);
}

TEST(OverlapIndex, FarCoordinatesFoldWithoutMissingNeighbours) {
  // Floating-point traps paused (docs/reliability.md): coordinates of
  // 1e300 overflow the cell coordinates to infinity before they are clamped, on purpose.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  std::mt19937_64 rng(3);
  // Beyond 2^21 cells from the origin the cell coordinates fold; at 1e300 they are clamped.
  std::vector<Body> bodies = RandomBodies(rng, 400, 0.0, 6.0, 0.3, 0.5);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (i % 3 == 1) bodies[i].p += Vec3::Constant(1e7);
    if (i % 3 == 2) bodies[i].p = Vec3::Constant(1e300) + bodies[i].p;
  }
  OverlapIndex index;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    std::set<std::uint32_t> offered;
    index.ForEachNear(bodies[i].p, bodies[i].r,
                      [&](std::uint32_t j, const Vec3&, double) { offered.insert(j); });
    for (std::uint32_t j = 0; j < i; ++j) {
      const double reach = bodies[i].r + bodies[j].r;
      if ((bodies[i].p - bodies[j].p).squaredNorm() <= reach * reach) {
        EXPECT_EQ(offered.count(j), 1u) << "body " << j << " missed before body " << i;
      }
    }
    index.Add(bodies[i].p, bodies[i].r);
  }
}

TEST(OverlapIndex, ClearEmptiesTheIndex) {
  OverlapIndex index;
  index.Add(Vec3::Zero(), 1.0);
  index.Clear();
  int offered = 0;
  index.ForEachNear(Vec3::Zero(), 1.0, [&](std::uint32_t, const Vec3&, double) { ++offered; });
  EXPECT_EQ(offered, 0);
  index.Add(Vec3(5, 5, 5), 0.5);  // usable again after Clear, with cells sized afresh
  index.ForEachNear(Vec3(5, 5, 6), 0.5, [&](std::uint32_t j, const Vec3&, double) {
    EXPECT_EQ(j, 0u);
    ++offered;
  });
  EXPECT_EQ(offered, 1);
}

}  // namespace
}  // namespace sparsedyn
