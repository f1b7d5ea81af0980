// SPDX-License-Identifier: MIT
// StaticTree against brute force over every static: the first entry of random movers
// (straight and parabolic, growing radii, finite and open limits, statics skipped) equal to
// the minimum over all statics, never later than dense sampling; exits; pruning measured by
// the nodes visited; inserts, removals and overlap queries against a plain map.
#include "broadphase/static_tree.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <iomanip>
#include <map>

#include "box_oracle.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {
namespace {

using testing::BoxCases;

// Statics of very different sizes: half sizes log-uniform in 1e-2..10 per axis (one in 50 up
// to 100), and a floor slab 1000 x 1 x 1000 under them.
std::vector<Aabb> Statics(BoxCases& cases, int n, double region) {
  std::vector<Aabb> boxes;
  boxes.push_back({{-500, -region - 1, -500}, {500, -region, 500}});
  for (int i = 1; i < n; ++i) boxes.push_back(cases.Box(region, i % 50 == 0 ? 1e2 : 10.0));
  return boxes;
}

// The brute-force twin: every static's own entry, the earliest (the lowest index on ties).
StaticTree::Entry BruteForce(const std::vector<Aabb>& boxes, const std::vector<bool>& present,
                             const Mover& m, double limit, const std::vector<bool>& skipped) {
  const BoxCrossing crossing(m);
  StaticTree::Entry best;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    if (!present[i] || skipped[i]) continue;
    const double dt = crossing.Entry(boxes[i], limit);
    if (dt < best.dt) best = {dt, i};
  }
  return best;
}

TEST(StaticTree, FirstEntryIsTheBruteForceMinimum) {
  BoxCases cases(20261222);
  const std::vector<Aabb> boxes = Statics(cases, 2000, 80.0);
  std::vector<bool> present(boxes.size(), true);
  StaticTree tree;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) tree.Insert(i, boxes[i]);
  tree.Build();
  // Some removed and some inserted since the build (dead and pending statics).
  for (std::uint32_t i = 0; i < boxes.size(); i += 37) {
    tree.Remove(i);
    present[i] = false;
  }
  for (std::uint32_t i = 5; i < boxes.size(); i += 41) {
    if (present[i]) continue;
    tree.Insert(i, boxes[i]);
    present[i] = true;
  }
  int found = 0, zero = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Mover m = cases.Next(/*curved=*/trial % 2 == 1, 80.0);
    const double limits[] = {1.0, 10.0, kInfinity};
    const double limit = limits[trial % 3];
    std::vector<bool> skipped(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
      skipped[i] = (i * 7919 + static_cast<std::size_t>(trial)) % 10 == 0;
    SCOPED_TRACE(trial);
    const StaticTree::Entry expected = BruteForce(boxes, present, m, limit, skipped);
    const StaticTree::Entry got =
        tree.FirstEntry(m, limit, [&](std::uint32_t i) { return static_cast<bool>(skipped[i]); });
    EXPECT_EQ(got.dt, expected.dt);
    if (got.dt == expected.dt && got.index != expected.index) {
      // A tie: the same time at another static.
      EXPECT_EQ(BoxCrossing(m).Entry(boxes[got.index], limit), expected.dt);
    }
    found += got.index != kNoIndex;
    zero += got.dt == 0.0;
  }
  std::printf("[static tree] 3000 queries over %zu statics: %d found, %d at dt = 0\n", boxes.size(),
              found, zero);
  EXPECT_GE(found, 600);
  EXPECT_GE(zero, 30);
}

TEST(StaticTree, FirstEntryIsNeverLaterThanDenseSampling) {
  BoxCases cases(20261223);
  const std::vector<Aabb> boxes = Statics(cases, 150, 40.0);
  StaticTree tree;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) tree.Insert(i, boxes[i]);
  tree.Build();
  const double T = 10.0;
  double max_gap = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    const Mover m = cases.Next(/*curved=*/true, 40.0);
    SCOPED_TRACE(trial);
    long double oracle = std::numeric_limits<long double>::infinity();
    for (const Aabb& box : boxes) {
      const auto t = testing::SampledCrossing(m, box, T, false, 1e-6 * T);
      if (t) oracle = std::min(oracle, *t);
    }
    const StaticTree::Entry got = tree.FirstEntry(m, T, [](std::uint32_t) { return false; });
    if (std::isfinite(static_cast<double>(oracle))) {
      EXPECT_LE(got.dt, oracle * (1 + 1e-15L)) << "late";
      max_gap = std::max(max_gap, static_cast<double>(oracle - got.dt));
    }
    if (got.index != kNoIndex) {
      EXPECT_GE(testing::Margin(m, boxes[got.index], got.dt), -1e-11L);
    }
  }
  std::printf("[static tree] curved paths vs sampling: max (oracle - entry) %.3g s\n", max_gap);
}

TEST(StaticTree, ExitIsTheBoxCrossingsAndNeverEarly) {
  BoxCases cases(20261224);
  const std::vector<Aabb> boxes = Statics(cases, 500, 20.0);
  StaticTree tree;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) tree.Insert(i, boxes[i]);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Mover m = cases.Next(trial % 2 == 1, 20.0);
    const auto i = static_cast<std::uint32_t>(cases.rng()() % boxes.size());
    const Aabb& b = boxes[i];
    m.p = 0.5 * (b.lo + b.hi) + 0.5 * (b.hi - b.lo).cwiseProduct(cases.Random(1.0));
    const double exit = tree.Exit(m, i);
    EXPECT_EQ(exit, BoxCrossing(m).Exit(b));
    const auto out = testing::SampledCrossing(m, b, 50.0, true, 1e-6);
    if (out) {
      ++checked;
      // The sampled exit is the end of its bisection interval, 1e-16 wide.
      EXPECT_GE(exit, *out - 2e-16L * std::max(1.0L, *out))
          << std::setprecision(20) << trial << " " << *out;
    }
  }
  EXPECT_GE(checked, 1000);
}

// At N = 10^4 statics, a query should touch a small part of the tree: pruning by the swept
// box and by entry times, nearest first.
TEST(StaticTree, QueriesVisitFewNodes) {
  BoxCases cases(20261225);
  const int n = 10000;
  const std::vector<Aabb> boxes = Statics(cases, n, 300.0);
  StaticTree tree;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) tree.Insert(i, boxes[i]);
  tree.Build();
  long nodes = 0, statics = 0;
  const int queries = 2000;
  for (int trial = 0; trial < queries; ++trial) {
    const Mover m = cases.Next(trial % 2 == 1, 300.0);
    StaticTree::Work work;
    tree.FirstEntry(
        m, trial % 2 ? 5.0 : kInfinity, [](std::uint32_t) { return false; }, &work);
    nodes += work.nodes;
    statics += work.statics;
  }
  const double per_query = static_cast<double>(nodes + statics) / queries;
  std::printf(
      "[static tree] N = %d, depth %d: %.1f nodes and %.1f statics tested per query "
      "(%.2f%% of a linear scan), %zu bytes (%.0f per static)\n",
      n, tree.depth(), static_cast<double>(nodes) / queries, static_cast<double>(statics) / queries,
      100.0 * per_query / n, tree.MemoryBytes(), static_cast<double>(tree.MemoryBytes()) / n);
  EXPECT_LT(per_query, 0.02 * n);
  EXPECT_LE(tree.depth(), 40);
  EXPECT_LT(tree.MemoryBytes(), 400u * n);
}

TEST(StaticTree, InsertRemoveAndOverlapsMatchAPlainMap) {
  BoxCases cases(20261226);
  StaticTree tree;
  std::map<std::uint32_t, Aabb> reference;
  for (int step = 0; step < 3000; ++step) {
    const auto index = static_cast<std::uint32_t>(cases.rng()() % 600);
    if (reference.count(index) != 0) {
      tree.Remove(index);
      reference.erase(index);
    } else {
      reference[index] = cases.Box(40.0);
      tree.Insert(index, reference[index]);
    }
    if (step % 500 == 250) tree.Build();
    ASSERT_EQ(tree.size(), reference.size());
    if (step % 10 != 0) continue;
    const Aabb query = cases.Box(40.0);
    std::vector<std::uint32_t> got, expected;
    tree.ForEachOverlapping(query, [&](std::uint32_t i) { got.push_back(i); });
    for (const auto& [i, b] : reference) {
      EXPECT_TRUE(tree.Contains(i));
      EXPECT_EQ(tree.box(i).lo, b.lo);
      if (b.Overlaps(query)) expected.push_back(i);
    }
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, expected) << "step " << step;
  }
}

TEST(StaticTree, BoxOfPolyhedronHoldsEveryVertex) {
  const ConvexPolyhedron poly = *RandomConvexPolyhedron(30, 5);
  Pose pose;
  pose.rotation = Eigen::Quaterniond(0.3, -0.5, 0.7, 0.2).normalized();
  pose.translation = {1e4, -3, 2};
  const Aabb box = BoxOfPolyhedron(poly, pose);
  for (const Vec3& v : poly.vertices()) {
    const Eigen::Matrix<long double, 3, 1> p =
        pose.rotation.cast<long double>().toRotationMatrix() * v.cast<long double>() +
        pose.translation.cast<long double>();
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(static_cast<long double>(box.lo[k]), p[k]);
      EXPECT_GE(static_cast<long double>(box.hi[k]), p[k]);
    }
  }
  EXPECT_LT((box.hi - box.lo).maxCoeff(),
            2.0 * poly.bounding_radius() + 2 * poly.centroid().norm() + 1e-9);
}

}  // namespace
}  // namespace sparsedyn
