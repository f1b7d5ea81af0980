// SPDX-License-Identifier: MIT
// BoxCrossing (a moving sphere against an axis-aligned box, inflated by its radius) against
// long double twins: the closed form on straight lines, dense sampling on curved paths with
// growing and shrinking radii. Entries never late, exits never early, and both within
// round-off of where the test really changes.
#include "broadphase/box_crossing.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "box_oracle.hpp"

namespace sparsedyn {
namespace {

using testing::BoxCases;
using testing::Margin;

// The test's round-off in space: a few ulps of the coordinates involved (positions up to
// ~130 m here), so a time is "at the boundary" when the margin there is below this.
double Scale(const Mover& m, const Aabb& box) {
  return 1e-13 * (m.p.cwiseAbs().maxCoeff() + box.lo.cwiseAbs().maxCoeff() +
                  box.hi.cwiseAbs().maxCoeff() + m.r0 + 1.0);
}

TEST(NonNegativeSet, QuadraticsWithKnownRoots) {
  // (dt - 1)(dt - 3) >= 0: [0, 1] and [3, inf).
  DtIntervals s = NonNegativeSet(1.0, -4.0, 3.0, 0.0, 0.0, 0.0);
  EXPECT_TRUE(s.Holds(0.0) && s.Holds(1.0) && s.Holds(3.0) && s.Holds(1e9));
  EXPECT_FALSE(s.Holds(1.01) || s.Holds(2.0) || s.Holds(2.99));
  EXPECT_NEAR(s.hi[0], 1.0, 1e-14);
  EXPECT_NEAR(s.lo[1], 3.0, 1e-14);
  // -(dt - 1)(dt - 3) >= 0: [1, 3], the ends moved outwards.
  s = NonNegativeSet(-1.0, 4.0, -3.0, 0.0, 0.0, 0.0);
  EXPECT_LE(s.lo[0], 1.0);
  EXPECT_GE(s.hi[0], 3.0);
  EXPECT_NEAR(s.lo[0], 1.0, 1e-14);
  EXPECT_FALSE(s.Holds(0.5) || s.Holds(3.5));
  // A double root (dt - 2)^2 <= 0 only at 2: -(dt - 2)^2 >= 0 keeps a neighbourhood of 2.
  s = NonNegativeSet(-1.0, 4.0, -4.0, 0.0, 0.0, 0.0);
  EXPECT_TRUE(s.Holds(2.0));
  EXPECT_FALSE(s.Holds(1.9));
  // Linear, constant, never.
  s = NonNegativeSet(0.0, 2.0, -1.0, 0.0, 0.0, 0.0);
  EXPECT_LT(s.lo[0], 0.5);
  EXPECT_GT(s.lo[0], 0.5 - 1e-15);
  EXPECT_TRUE(NonNegativeSet(0.0, 0.0, 0.0, 0.0, 0.0, 0.0).Holds(5.0));
  EXPECT_FALSE(NonNegativeSet(0.0, 0.0, -1e-300, 0.0, 0.0, 0.0).Holds(5.0));
  EXPECT_FALSE(NonNegativeSet(-1.0, 0.0, -1.0, 0.0, 0.0, 0.0).Holds(0.0));
}

TEST(BoxCrossing, TouchingNowIsEntryAtZero) {
  const Aabb box{{0, 0, 0}, {1, 1, 1}};
  Mover m;
  m.r0 = 0.25;
  m.p = {-0.25, 0.5, 0.5};  // the sphere touches the face x = 0
  m.v = {-1, 0, 0};         // and leaves it
  EXPECT_EQ(BoxCrossing(m).Entry(box, kInfinity), 0.0);
  EXPECT_LE(BoxCrossing(m).Exit(box), 1e-15);  // it holds only at dt = 0 (to round-off)
  m.p = {-0.5, 0.5, 0.5};
  EXPECT_EQ(BoxCrossing(m).Entry(box, kInfinity), kInfinity);
  m.v = {1, 0, 0};
  EXPECT_NEAR(BoxCrossing(m).Entry(box, kInfinity), 0.25, 1e-15);
  EXPECT_EQ(BoxCrossing(m).Entry(box, 0.2), kInfinity);  // beyond the horizon
  EXPECT_NEAR(BoxCrossing(m).Exit(Aabb{{-1, 0, 0}, {1, 1, 1}}), 1.75, 1e-14);
}

TEST(BoxCrossing, StraightLinesEqualTheClosedForm) {
  BoxCases cases(20261220);
  int entries = 0, exits = 0;
  double worst_margin = 0.0, worst_time = 0.0;
  for (int trial = 0; trial < 20000; ++trial) {
    Mover m = cases.Next(/*curved=*/false);
    if (trial % 3 == 0) m.r1 = 0.1 * cases.Signed();  // a radius growing linearly
    const Aabb box = cases.Box();
    SCOPED_TRACE(trial);
    long double exit = 0.0L;
    const std::optional<long double> oracle = testing::LinearEntry(m, box, &exit);
    const BoxCrossing crossing(m);
    const double entry = crossing.Entry(box, kInfinity);
    const double scale = Scale(m, box);
    if (!oracle) {
      // Only a round-off touch may be reported where the closed form has none.
      if (entry != kInfinity) {
        EXPECT_GE(Margin(m, box, entry), -scale);
      }
      continue;
    }
    ++entries;
    EXPECT_LE(entry, *oracle * (1 + 1e-17L)) << "late";
    EXPECT_GE(Margin(m, box, entry), -scale) << "not at the box at the entry " << entry;
    worst_time =
        std::max(worst_time, static_cast<double>((*oracle - entry) / std::max(1.0L, *oracle)));
    if (*oracle > 0) {
      EXPECT_LE(Margin(m, box, entry), scale) << "entry " << entry << " early: " << *oracle;
      worst_margin =
          std::max(worst_margin, static_cast<double>(std::abs(Margin(m, box, entry))) / scale);
    }
    if (*oracle == 0 && std::isfinite(static_cast<double>(exit))) {
      ++exits;
      const double out = crossing.Exit(box);
      EXPECT_GE(out, exit * (1 - 1e-17L)) << "early exit";
      EXPECT_LE(Margin(m, box, out), scale) << "exit " << out << " late: " << exit;
    }
  }
  std::printf(
      "[box crossing] straight lines: %d entries, %d exits, worst |margin| at entry %.3g x 1e-13 "
      "scale, worst (exact - entry) %.3g relative\n",
      entries, exits, worst_margin, worst_time);
  EXPECT_GE(entries, 500);
  EXPECT_GE(exits, 200);
}

TEST(BoxCrossing, CurvedPathsAgainstDenseSampling) {
  BoxCases cases(20261221);
  const double T = 20.0;
  int entries = 0, exits = 0, touches = 0;
  double max_error = 0.0;
  for (int trial = 0; trial < 3000; ++trial) {
    Mover m = cases.Next(/*curved=*/true, 10.0);
    const Aabb box = cases.Box(10.0);
    const bool start_inside = trial % 4 == 0;
    if (start_inside)
      m.p = 0.5 * (box.lo + box.hi) + 0.5 * (box.hi - box.lo).cwiseProduct(cases.Random(1.0));
    SCOPED_TRACE(trial);
    const BoxCrossing crossing(m);
    const double scale = Scale(m, box);
    const std::optional<long double> oracle = testing::SampledCrossing(m, box, T, false, 1e-7 * T);
    const double entry = crossing.Entry(box, T);
    if (entry < kInfinity) {
      EXPECT_GE(Margin(m, box, entry), -scale) << "entry " << entry;
    }
    if (!oracle) {
      touches += entry < kInfinity;  // a touch narrower than the sampling step
      continue;
    }
    ++entries;
    EXPECT_LE(entry, *oracle * (1 + 1e-15L)) << "late";
    if (*oracle > 0 && Margin(m, box, entry) > scale)
      ADD_FAILURE() << "early: " << entry << " vs " << *oracle;
    max_error = std::max(max_error, static_cast<double>(*oracle - entry));
    if (*oracle == 0) {
      const std::optional<long double> out = testing::SampledCrossing(m, box, T, true, 1e-7 * T);
      const double exit = crossing.Exit(box);
      if (!out) continue;
      ++exits;
      // The sampled exit is the end of its bisection interval, 1e-16 wide.
      EXPECT_GE(exit, *out - 2e-16L * std::max(1.0L, *out)) << "early exit";
      EXPECT_LE(Margin(m, box, exit), scale) << "exit " << exit << " late: " << *out;
    }
  }
  std::printf(
      "[box crossing] curved: %d entries, %d exits, %d touches, max (oracle - entry) %.3g s\n",
      entries, exits, touches, max_error);
  EXPECT_GE(entries, 500);
  EXPECT_GE(exits, 300);
}

}  // namespace
}  // namespace sparsedyn
