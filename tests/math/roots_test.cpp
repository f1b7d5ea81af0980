// SPDX-License-Identifier: MIT
#include "math/roots.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "math/root_oracle.hpp"
#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

// A double root is only located to within the zone where |p| is below the long double
// evaluation error: sqrt(~2e-18) ~ 1.5e-9 relative, with margin.
constexpr double kDoubleRootTol = 1e-8;

// A simple, well-conditioned root is found to adjacent doubles: allow a few ulps.
double Ulps(double t, int count) {
  return count * (std::nextafter(std::abs(t), 1e308) - std::abs(t));
}

// ---- SolveQuadratic -----------------------------------------------------------------------

TEST(SolveQuadratic, TwoRootsAscending) {
  std::array<double, 2> r{};
  ASSERT_EQ(SolveQuadratic(1, -3, 2, r), 2);
  EXPECT_EQ(r[0], 1.0);
  EXPECT_EQ(r[1], 2.0);
  ASSERT_EQ(SolveQuadratic(-2, 6, -4, r), 2);  // negative leading coefficient
  EXPECT_EQ(r[0], 1.0);
  EXPECT_EQ(r[1], 2.0);
}

TEST(SolveQuadratic, DoubleRootIsReportedTwice) {
  std::array<double, 2> r{};
  ASSERT_EQ(SolveQuadratic(1, -2, 1, r), 2);
  EXPECT_EQ(r[0], 1.0);
  EXPECT_EQ(r[1], 1.0);
  ASSERT_EQ(SolveQuadratic(3, 0, 0, r), 2);
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 0.0);
}

TEST(SolveQuadratic, NegativeDiscriminantHasNoRealRoots) {
  std::array<double, 2> r{};
  EXPECT_EQ(SolveQuadratic(1, 0, 1, r), 0);
  EXPECT_EQ(SolveQuadratic(1, 1, 1, r), 0);
}

TEST(SolveQuadratic, DegreeDropsToLinearAndConstant) {
  std::array<double, 2> r{};
  ASSERT_EQ(SolveQuadratic(0, 2, -1, r), 1);
  EXPECT_EQ(r[0], 0.5);
  EXPECT_EQ(SolveQuadratic(0, 0, 1, r), 0);
  EXPECT_EQ(SolveQuadratic(0, 0, 0, r), 0);  // every t solves 0 = 0: documented as 0 roots
}

TEST(SolveQuadratic, SmallRootHasNoCancellation) {
  // t^2 - 1e8 t + 1: the naive formula loses the small root 1e-8 to cancellation.
  std::array<double, 2> r{};
  ASSERT_EQ(SolveQuadratic(1, -1e8, 1, r), 2);
  EXPECT_NEAR(r[0], 1e-8, Ulps(1e-8, 2));
  EXPECT_NEAR(r[1], 1e8, Ulps(1e8, 2));
}

TEST(SolveQuadratic, HugeAndTinyCoefficientsNeitherOverflowNorUnderflow) {
  std::array<double, 2> r{};
  for (double scale : {1e-200, 1e-150, 1e150, 1e200, 1e300}) {
    SCOPED_TRACE(scale);
    ASSERT_EQ(SolveQuadratic(scale, -3 * scale, 2 * scale, r), 2);
    EXPECT_NEAR(r[0], 1.0, Ulps(1.0, 2));
    EXPECT_NEAR(r[1], 2.0, Ulps(2.0, 2));
  }
  // b^2 alone would overflow a double.
  ASSERT_EQ(SolveQuadratic(1, -1e200, 1e199, r), 2);
  EXPECT_NEAR(r[0], 0.1, Ulps(0.1, 2));
  EXPECT_NEAR(r[1], 1e200, Ulps(1e200, 2));
}

// ---- SolveCubic / SolveQuartic -------------------------------------------------------------

TEST(SolveCubic, ThreeSimpleRootsAreRefinedToTheUlp) {
  std::array<double, 3> r{};
  ASSERT_EQ(SolveCubic(Polynomial{-6, 11, -6, 1}, r), 3);
  EXPECT_EQ(r[0], 1.0);
  EXPECT_EQ(r[1], 2.0);
  EXPECT_EQ(r[2], 3.0);
}

TEST(SolveCubic, OneRealRootAndLowerDegrees) {
  std::array<double, 3> r{};
  ASSERT_EQ(SolveCubic(Polynomial{-2, 0, 0, 1}, r), 1);  // t^3 = 2
  EXPECT_NEAR(r[0], std::cbrt(2.0), Ulps(1.26, 1));
  ASSERT_EQ(SolveCubic(Polynomial{2, -3, 1}, r), 2);  // quadratic
  EXPECT_EQ(SolveCubic(Polynomial{1}, r), 0);
}

TEST(SolveCubic, DoubleRootIsReportedOnceNearItsTouchPoint) {
  std::array<double, 3> r{};
  ASSERT_EQ(SolveCubic(Polynomial{1, -2, 1} * Polynomial{-3, 1}, r), 2);  // (t-1)^2 (t-3)
  EXPECT_NEAR(r[0], 1.0, kDoubleRootTol);
  EXPECT_EQ(r[1], 3.0);
}

TEST(SolveQuartic, FourRootsNoRootsAndDegreeDrop) {
  std::array<double, 4> r{};
  ASSERT_EQ(SolveQuartic(Polynomial{24, -50, 35, -10, 1}, r), 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(r[static_cast<std::size_t>(i)], i + 1.0);
  EXPECT_EQ(SolveQuartic(Polynomial{1, 0, 0, 0, 1}, r), 0);
  ASSERT_EQ(SolveQuartic(Polynomial{-6, 11, -6, 1, 0}, r), 3);
}

// ---- EarliestRoot: unit cases --------------------------------------------------------------

TEST(EarliestRoot, SimpleRootOfAQuadraticToTheUlpAndNeverLater) {
  const auto r = EarliestRoot(Polynomial{-2, 0, 1}, 0, 10);
  ASSERT_TRUE(r);
  EXPECT_LE(static_cast<long double>(*r) * *r, 2.0L);  // r <= sqrt(2) exactly
  EXPECT_NEAR(*r, std::sqrt(2.0), Ulps(1.414, 2));
}

TEST(EarliestRoot, DoubleRootIsReportedNoLaterThanTheTouch) {
  for (int degree_of_rest : {0, 2, 6}) {
    SCOPED_TRACE(degree_of_rest);
    Polynomial p{0.25, -1, 1};  // (t - 0.5)^2
    for (int i = 0; i < degree_of_rest; i += 2) p = p * Polynomial{1, 0, 1};
    const auto r = EarliestRoot(p, 0, 1e30);
    ASSERT_TRUE(r);
    EXPECT_LE(*r, 0.5);
    EXPECT_GE(*r, 0.5 - kDoubleRootTol);
  }
}

TEST(EarliestRoot, TripleRootIsReportedNoLaterThanIt) {
  const auto r = EarliestRoot(Polynomial{-1, 3, -3, 1}, -5, 5);  // (t - 1)^3
  ASSERT_TRUE(r);
  EXPECT_LE(*r, 1.0);
  EXPECT_GE(*r, 1.0 - 1e-5);  // cbrt of the evaluation error
}

TEST(EarliestRoot, RootExactlyAtZeroAndAtLo) {
  EXPECT_EQ(EarliestRoot(Polynomial{0, -2, 1}, 0, 10), 0.0);             // t (t - 2)
  EXPECT_EQ(EarliestRoot(Polynomial{-3, -1, 2}, 1.5, 10), 1.5);          // (2t - 3)(t + 1)
  EXPECT_EQ(EarliestRoot(Polynomial{0, 0, 0, 0, 1}, 0, 1), 0.0);         // t^4 touches at lo
  EXPECT_EQ(EarliestRoot(Polynomial{-1, 1}, 1, 1), 1.0);                 // lo == hi on the root
  EXPECT_EQ(EarliestRoot(Polynomial{-1, 1}, 2, 2), std::nullopt);        // lo == hi off it
  const auto through_zero = EarliestRoot(Polynomial{0, 1, 1}, -0.5, 1);  // t (t + 1) from -0.5
  ASSERT_TRUE(through_zero);
  EXPECT_LE(*through_zero, 0.0);
  EXPECT_GE(*through_zero, -1e-300);
}

TEST(EarliestRoot, DegreeDropWithZeroOrTinyLeadingCoefficient) {
  EXPECT_NEAR(*EarliestRoot(Polynomial{-1, 2, 0}, 0, 10), 0.5, Ulps(0.5, 1));
  // 1e-300 t^2 + 2t - 1: roots 0.5 and about -2e300 (outside [-1e30, 1e30]).
  EXPECT_NEAR(*EarliestRoot(Polynomial{-1, 2, 1e-300}, -1e30, 1e30), 0.5, Ulps(0.5, 1));
  // 1e-300 t^4 + t - 1 from far below: the huge root -1e100.
  const auto r = EarliestRoot(Polynomial{-1, 1, 0, 0, 1e-300}, -1e200, 1e30);
  ASSERT_TRUE(r);
  EXPECT_NEAR(*r, -1e100, 1e100 * 1e-14);
}

TEST(EarliestRoot, NoRealRootsGivesNullopt) {
  EXPECT_EQ(EarliestRoot(Polynomial{1, 0, 1}, -1e30, 1e30), std::nullopt);
  EXPECT_EQ(EarliestRoot(Polynomial{1, 0, 0, 0, 1}, -1e30, 1e30), std::nullopt);
  EXPECT_EQ(EarliestRoot(Polynomial{1, 0, 0, 0, 0, 0, 0, 0, 1}, 0, 1e30), std::nullopt);
  EXPECT_EQ(EarliestRoot(Polynomial{-6, 11, -6, 1}, 3.5, 1e30), std::nullopt);  // roots passed
  EXPECT_EQ(EarliestRoot(Polynomial{5}, 0, 1), std::nullopt);
}

TEST(EarliestRoot, ZeroPolynomialIsZeroAtLo) { EXPECT_EQ(EarliestRoot(Polynomial{}, 2, 3), 2.0); }

TEST(EarliestRoot, CoefficientScalingFrom1eMinus150To1e150DoesNotMatter) {
  // Powers of two keep the coefficients exact, so the roots stay exactly 1, 2, 3, 4.
  for (int exponent : {-500, -330, 0, 330, 500}) {
    const double scale = std::ldexp(1.0, exponent);
    SCOPED_TRACE(scale);
    const Polynomial p = Polynomial{24, -50, 35, -10, 1} * scale;
    EXPECT_NEAR(*EarliestRoot(p, 0, 1e30), 1.0, Ulps(1.0, 1));
    EXPECT_NEAR(*EarliestRoot(p, 2.5, 1e30), 3.0, Ulps(3.0, 2));
    EXPECT_LE(*EarliestRoot(p, 2.5, 1e30), 3.0);
  }
}

TEST(EarliestRoot, RootsAcrossTwoHundredOrdersOfMagnitude) {
  const Polynomial p = Polynomial{-1e-100, 1} * Polynomial{-1e100, 1};
  EXPECT_NEAR(*EarliestRoot(p, 0, 1e300), 1e-100, 1e-100 * 1e-15);
  EXPECT_NEAR(*EarliestRoot(p, 1, 1e300), 1e100, 1e100 * 1e-15);
}

TEST(EarliestRoot, ClusteredRootsAreNotSkipped) {
  // Roots 1, 1 + 2^-10, 1 + 2^-9, 1 + 3 2^-10: exact coefficients, so these are the true roots;
  // |p'| ~ 1e-9 at each, so the uncertainty zone is ~1e-17 / 1e-9 wide.
  constexpr double kSpacing = 0x1p-10;
  constexpr double kClusterTol = 1e-7;
  Polynomial p{1};
  for (int i = 0; i < 4; ++i) p = p * Polynomial{-(1 + i * kSpacing), 1};
  const auto r = EarliestRoot(p, 0, 1e30);
  ASSERT_TRUE(r);
  EXPECT_LE(*r, 1.0);
  EXPECT_GE(*r, 1.0 - kClusterTol);
  // Just past the first root, the second one.
  const auto second = EarliestRoot(p, 1 + 0.5 * kSpacing, 1e30);
  ASSERT_TRUE(second);
  EXPECT_LE(*second, 1 + kSpacing);
  EXPECT_GE(*second, 1 + kSpacing - kClusterTol);
}

TEST(EarliestRoot, EveryDegreeFrom1To8) {
  for (int degree = 1; degree <= kMaxPolynomialDegree; ++degree) {
    SCOPED_TRACE(degree);
    Polynomial p{1};
    for (int i = 1; i <= degree; ++i) p = p * Polynomial{-static_cast<double>(i), 1};
    // p(1) is exactly 0, but the evaluation cannot certify that, so the answer may be the
    // double just below (the last one certified to lie before the root).
    const auto first = EarliestRoot(p, 0, 1e30);
    ASSERT_TRUE(first);
    EXPECT_LE(*first, 1.0);
    EXPECT_GE(*first, 1.0 - Ulps(1.0, 1));
    EXPECT_EQ(EarliestRoot(p, 0.5 + degree, 1e30), std::nullopt);
    if (degree >= 2) {
      const auto r = EarliestRoot(p, 1.5, 1e30);
      ASSERT_TRUE(r);
      EXPECT_LE(*r, 2.0);
      // Wilkinson-like conditioning at degree 8: sum |c_i| 2^i / |p'(2)| ~ 2500, times the
      // ~2e-18 evaluation error, is a few 1e-15.
      EXPECT_GE(*r, 2.0 - 1e-13);
    }
  }
}

TEST(EarliestRoot, ExtremeCoefficientsNeverGiveNaN) {
  for (double c : {1e308, -1e308, 1e-308, 5e-324}) {
    SCOPED_TRACE(c);
    const Polynomial p{c, -c, c, -c, c, -c, c, -c, c};
    const auto r = EarliestRoot(p, -1e30, 1e30);
    if (r) {
      EXPECT_TRUE(std::isfinite(*r));
    }
    const Polynomial q{-c, 0, 0, 0, 0, 0, 0, 0, 1e-300};
    const auto s = EarliestRoot(q, 0, 1e30);
    if (s) {
      EXPECT_TRUE(std::isfinite(*s));
    }
  }
}

TEST(IsolateRealRoots, SimpleRootsGetAdjacentDoubleBrackets) {
  const RootIntervals intervals = IsolateRealRoots(Polynomial{-6, 11, -6, 1}, -10, 10);
  ASSERT_EQ(intervals.count, 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_LE(intervals[i].lo, i + 1.0);
    EXPECT_GE(intervals[i].hi, i + 1.0);
    EXPECT_LE(intervals[i].hi, std::nextafter(std::nextafter(intervals[i].lo, 1e9), 1e9));
  }
}

TEST(RootMagnitudeBound, BoundsEveryRoot) {
  EXPECT_GT(RootMagnitudeBound(Polynomial{24, -50, 35, -10, 1}), 4.0);
  EXPECT_LE(RootMagnitudeBound(Polynomial{24, -50, 35, -10, 1}), 64.0);
  EXPECT_EQ(RootMagnitudeBound(Polynomial{0, 0, 3}), 0.0);
  EXPECT_EQ(RootMagnitudeBound(Polynomial{-1e300, 1e-300}),
            std::numeric_limits<double>::infinity());
}

// ---- EarliestRoot against the independent long double oracle (smaller runs; the 10^5 runs are in
// roots_slow_test.cpp, which the sanitizer job skips) -----------------------------------------

void RunOracleCheck(const char* name, std::uint64_t seed, int degree, int cases) {
  // Floating-point traps paused (docs/reliability.md): random polynomials with roots beyond the
  // double range, which SolveQuadratic rounds to +infinity and drops.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  testing::PolynomialGenerator gen(seed);
  testing::CheckStats stats;
  for (int i = 0; i < cases && stats.failures < 10; ++i) {
    testing::CheckEarliestRoot(testing::MakeCase(gen, degree), stats);
  }
  testing::PrintStats(name, seed, stats);
  EXPECT_EQ(stats.failures, 0);
  EXPECT_LT(stats.inconclusive, cases / 100 + 1);
}

TEST(EarliestRootOracle, RandomQuadratics) { RunOracleCheck("quadratic", 20260611, 2, 20000); }
TEST(EarliestRootOracle, RandomQuartics) { RunOracleCheck("quartic", 20260612, 4, 20000); }
TEST(EarliestRootOracle, RandomLinearAndCubics) {
  RunOracleCheck("linear", 20260613, 1, 1000);
  RunOracleCheck("cubic", 20260614, 3, 2000);
}
TEST(EarliestRootOracle, RandomDegrees5To8) {
  for (int degree = 5; degree <= 8; ++degree) {
    RunOracleCheck("degree5to8", 20260615 + static_cast<std::uint64_t>(degree), degree, 2000);
  }
}

}  // namespace
}  // namespace sparsedyn
