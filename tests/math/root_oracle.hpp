// SPDX-License-Identifier: MIT
// The slow, independent twin of EarliestRoot (STYLE.md §1 `reference_*`): branch-and-bound
// subdivision of [lo, hi] with Taylor-model enclosures in long double, plus the random polynomial
// families and the checker shared by roots_test.cpp and roots_slow_test.cpp. It shares no code
// with src/math/root_isolation.cpp: no derivative cascade, its own root bound (Cauchy), its own
// Taylor shift and error bounds.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "math/polynomial.hpp"
#include "math/roots.hpp"

namespace sparsedyn::testing {

using Real = long double;

inline constexpr Real kOracleUnitRoundoff = std::numeric_limits<Real>::epsilon() / 2;

// A cell narrower than this (relative to max(|t|, kOracleAbsoluteFloor * bound)) on which p cannot
// be shown non-zero is a "possible" (touching or near-touching) root. 2^-40 ~ 1e-12: finer than
// the sqrt(1e-18) ~ 1e-9 zone in which EarliestRoot may report a double root.
inline constexpr Real kOracleCellRel = 0x1p-40L;
inline constexpr Real kOracleAbsoluteFloor = 0x1p-60L;

// Inside a zone where |p| <= kOracleNearZeroRel * sum |c_i| |t|^i (a multiple root's or a
// tight cluster's fuzz: (1e-16)^(1/k) relative wide for k coalescing roots, up to 1e-2 for k = 8)
// cells stop at 2^-20 ~ 1e-6 relative instead of 2^-40. A pair of simple roots 1e-7 apart is
// not such a zone (|p| ~ 2.5e-15 between them), so it is still resolved.
inline constexpr Real kOracleNearZeroRel = 1e-16L;
inline constexpr Real kOracleZoneCellRel = 0x1p-20L;

// Upper limit on cells per oracle call; beyond it the case is skipped as inconclusive (counted).
inline constexpr int kOracleMaxCells = 200000;

// What the oracle knows about the earliest root in [lo, hi].
struct OracleResult {
  bool conclusive = true;
  // The earliest certified root (a certified sign change, or an exact zero) lies in
  // [certain_lo, certain_hi]; certain_hi - certain_lo is the oracle's own error (a few long double
  // ulps for a well-conditioned root), which is the only slack the lateness check allows.
  bool has_certain = false;
  Real certain_lo = 0;
  Real certain_hi = 0;
  // The earliest cell (width <= kOracleCellRel relative) on which p might vanish, if any.
  bool has_possible = false;
  Real possible = 0;
};

// p(t) and a rigorous bound on its rounding error (independent re-implementation).
struct OracleValue {
  Real value;
  Real bound;
  int Sign() const { return value > bound ? 1 : (value < -bound ? -1 : 0); }
  bool ExactZero() const { return value == 0 && bound == 0; }
};

inline OracleValue OracleEvaluate(const std::vector<Real>& c, Real t) {
  Real value = 0;
  Real magnitude = 0;
  for (std::size_t i = c.size(); i-- > 0;) {
    value = value * t + c[i];
    magnitude = magnitude * std::fabs(t) + std::fabs(c[i]);
  }
  // gamma_2n with a factor 4 of margin.
  return {value, 8 * static_cast<Real>(c.size()) * kOracleUnitRoundoff * magnitude};
}

// sum |c_i| |t|^i: the natural scale of p(t) and of its evaluation error.
inline Real AbsoluteScale(const Polynomial& p, Real t) {
  Real magnitude = 0;
  for (int i = std::max(p.Degree(), 0); i >= 0; --i) {
    magnitude = magnitude * std::fabs(t) + std::fabs(static_cast<Real>(p.Coefficient(i)));
  }
  return magnitude;
}

// p(t) in long double (the oracle's own evaluation).
inline Real OracleValueAt(const Polynomial& p, Real t) {
  Real value = 0;
  for (int i = std::max(p.Degree(), 0); i >= 0; --i) value = value * t + p.Coefficient(i);
  return value;
}

// Taylor coefficients of c about m (synthetic division), in place.
inline void TaylorShift(std::vector<Real>& c, Real m) {
  const std::size_t n = c.size();
  for (std::size_t k = 0; k + 1 < n; ++k) {
    for (std::size_t i = n - 1; i-- > k;) c[i] += m * c[i + 1];
  }
}

inline OracleResult OracleEarliestRoot(const Polynomial& p, double lo, double hi) {
  OracleResult result;
  const int n = p.Degree();
  if (n < 0) {
    result.has_certain = true;
    result.certain_lo = result.certain_hi = lo;
    return result;
  }
  if (n == 0) return result;
  std::vector<Real> c(static_cast<std::size_t>(n) + 1);
  std::vector<Real> abs_c(c.size());
  for (int i = 0; i <= n; ++i) {
    c[static_cast<std::size_t>(i)] = p.Coefficient(i);
    abs_c[static_cast<std::size_t>(i)] = std::fabs(c[static_cast<std::size_t>(i)]);
  }

  // Cauchy's bound: every root has |z| < 1 + max |c_i / c_n|.
  Real bound = 0;
  for (int i = 0; i < n; ++i) bound = std::max(bound, abs_c[static_cast<std::size_t>(i)]);
  bound = 1 + bound / abs_c[static_cast<std::size_t>(n)];
  const Real a = std::max<Real>(lo, -bound);
  const Real b = std::min<Real>(hi, bound);
  if (a > b) return result;
  const Real floor = kOracleAbsoluteFloor * std::min(bound, std::max(std::fabs(a), std::fabs(b)));

  // Depth-first over cells, leftmost first, so the first certain root found is the earliest.
  std::vector<std::pair<Real, Real>> stack{{a, b}};
  int cells = 0;
  std::vector<Real> taylor(c.size());
  std::vector<Real> abs_taylor(c.size());
  while (!stack.empty()) {
    if (++cells > kOracleMaxCells) {
      result.conclusive = false;
      return result;
    }
    const auto [u, w] = stack.back();
    stack.pop_back();
    const OracleValue at_u = OracleEvaluate(c, u);
    if (at_u.ExactZero()) {
      result.has_certain = true;
      result.certain_lo = result.certain_hi = u;
      return result;
    }

    // Taylor model about the midpoint with a bound on the rounding of the shift.
    const Real m = u / 2 + w / 2;
    const Real h = std::max(m - u, w - m) * (1 + 64 * kOracleUnitRoundoff);
    taylor = c;
    TaylorShift(taylor, m);
    abs_taylor = abs_c;
    TaylorShift(abs_taylor, std::fabs(m));
    const Real shift_error = 16 * static_cast<Real>(n + 1) * kOracleUnitRoundoff;
    Real radius = shift_error * abs_taylor[0];
    Real slope_radius = shift_error * abs_taylor[1];
    Real h_power = 1;
    for (int k = 1; k <= n; ++k) {
      const auto sk = static_cast<std::size_t>(k);
      const Real term = std::fabs(taylor[sk]) + shift_error * abs_taylor[sk];
      if (k >= 2) slope_radius += static_cast<Real>(k) * term * h_power;
      h_power *= h;
      radius += term * h_power;
    }
    if (std::fabs(taylor[0]) > radius * (1 + 1e-12L)) continue;  // no root in the cell

    // Monotone cell: the end signs decide.
    const OracleValue at_w = OracleEvaluate(c, w);
    const int su = at_u.Sign();
    const int sw = at_w.Sign();
    const bool monotone = std::fabs(taylor[1]) > slope_radius * (1 + 1e-12L);
    if (monotone && su != 0 && su == sw) continue;
    // Narrow: at the resolution limit, or inside a near-zero zone (around a multiple root, where
    // |p| stays below the evaluation error on a whole stretch) at a coarser resolution.
    const Real scale = std::max(std::fabs(m), floor);
    const bool near_zero_zone = std::fabs(taylor[0]) <= kOracleNearZeroRel * abs_taylor[0] &&
                                w - u <= kOracleZoneCellRel * scale;
    const bool narrow = w - u <= kOracleCellRel * scale || near_zero_zone;
    if ((monotone || narrow) && su != 0 && sw == -su) {
      // Certified sign change: bisect, keeping certified signs at both ends.
      Real x1 = u;
      Real x2 = w;
      for (int i = 0; i < 200; ++i) {
        const Real mid = x1 / 2 + x2 / 2;
        if (mid <= x1 || mid >= x2) break;
        const int s = OracleEvaluate(c, mid).Sign();
        if (s == su) {
          x1 = mid;
        } else if (s == -su) {
          x2 = mid;
        } else {
          break;  // inside the fuzz of the root: [x1, x2] is as sharp as long double allows
        }
      }
      result.has_certain = true;
      result.certain_lo = x1;
      result.certain_hi = x2;
      return result;
    }
    if (narrow) {
      if (!result.has_possible) {
        result.has_possible = true;
        result.possible = u;
      }
      continue;
    }
    stack.emplace_back(m, w);
    stack.emplace_back(u, m);
  }
  return result;
}

// ---------------------------------------------------------------------------------------------
// Random polynomials with a fixed, printed seed (splitmix64: the same numbers on every platform).

class PolynomialGenerator {
 public:
  explicit PolynomialGenerator(std::uint64_t seed) : state_(seed) {}

  std::uint64_t Next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double Uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(Next() >> 11) * 0x1p-53;
  }
  int Int(int lo, int hi) {
    return lo + static_cast<int>(Next() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool Chance(double probability) { return Uniform(0, 1) < probability; }
  double Sign() { return Chance(0.5) ? 1.0 : -1.0; }
  // Magnitude log-uniform in [10^lo, 10^hi] with a random sign.
  double LogUniform(double lo, double hi) { return Sign() * std::pow(10.0, Uniform(lo, hi)); }
  // An exact power of two 2^k, k uniform in [-max_exponent, max_exponent] (scales exactly).
  double PowerOfTwo(int max_exponent) { return std::ldexp(1.0, Int(-max_exponent, max_exponent)); }

  // A real root: mostly O(1), sometimes tiny, huge or exactly 0.
  double Root() {
    switch (Int(0, 9)) {
      case 0:
        return 0.0;
      case 1:
        return LogUniform(-8, 0);
      case 2:
        return LogUniform(0, 6);
      default:
        return Uniform(-10, 10);
    }
  }

  // A monic factor: (t - r) or a quadratic with complex roots re +- i im.
  Polynomial LinearFactor() { return Polynomial{-Root(), 1.0}; }
  Polynomial ComplexPairFactor() {
    const double re = Root();
    const double im = Chance(0.2) ? std::abs(re) * LogUniform(-9, -3) : LogUniform(-3, 1);
    return Polynomial{re * re + im * im, -2 * re, 1.0};
  }
  // (4t - k)^multiplicity with |k| <= 16: integer coefficients, exact root k / 4.
  Polynomial ExactFactor(int multiplicity, std::vector<double>& exact_roots) {
    const int k = Int(-16, 16);
    exact_roots.push_back(k / 4.0);
    Polynomial factor{1.0};
    for (int i = 0; i < multiplicity; ++i)
      factor = factor * Polynomial{-static_cast<double>(k), 4.0};
    return factor;
  }

  // Random coefficients of mixed magnitudes (some zero).
  Polynomial RandomCoefficients(int degree) {
    Polynomial p;
    for (int i = 0; i <= degree; ++i) {
      if (i < degree && Chance(0.1)) continue;
      p.SetCoefficient(i, LogUniform(-3, 3));
    }
    return p;
  }

 private:
  std::uint64_t state_;
};

// A test case: the polynomial, the interval, and the exact roots known from construction.
struct RootCase {
  Polynomial p;
  double lo = 0;
  double hi = 0;
  std::vector<double> exact_roots;  // true roots of p (in exact arithmetic) by construction

  std::string Describe() const {
    char buffer[160];
    std::snprintf(buffer, sizeof(buffer), "EarliestRoot(%s, %.17g, %.17g)", p.ToString().c_str(),
                  lo, hi);
    return buffer;
  }
};

// Builds a case of degree `degree` (the family is drawn at random): roots drawn then expanded,
// complex pairs, random coefficients, exact double/triple roots, roots at 0, degree drops,
// clustered roots; scaled by up to 2^+-450 (~1e+-135) and given a random [lo, hi].
inline RootCase MakeCase(PolynomialGenerator& gen, int degree) {
  RootCase rc;
  const int family = gen.Int(0, 9);
  if (family <= 2) {
    // Real roots and complex pairs, expanded.
    Polynomial p{1.0};
    int d = 0;
    while (d < degree) {
      if (degree - d >= 2 && gen.Chance(0.35)) {
        p = p * gen.ComplexPairFactor();
        d += 2;
      } else {
        p = p * gen.LinearFactor();
        d += 1;
      }
    }
    rc.p = p * gen.LogUniform(-100, 100);
  } else if (family <= 4) {
    rc.p = gen.RandomCoefficients(degree) * gen.LogUniform(-150, 150);
  } else if (family <= 6) {
    // Exact multiple roots (and other exact roots), integer coefficients.
    Polynomial p{1.0};
    int d = 0;
    while (d < degree) {
      const int multiplicity = std::min(degree - d, gen.Int(1, 3));
      p = p * gen.ExactFactor(multiplicity, rc.exact_roots);
      d += multiplicity;
    }
    if (gen.Chance(0.3) && degree >= 2) {
      // Replace one factor's worth by a complex pair to leave touching roots alone.
      rc.exact_roots.clear();
      p = Polynomial{1.0};
      p = p * gen.ExactFactor(2, rc.exact_roots);
      for (int i = 2; i + 2 <= degree; i += 2)
        p = p * Polynomial{static_cast<double>(gen.Int(1, 9)), 0, 1};
      if (degree % 2 == 1) p = p * gen.ExactFactor(1, rc.exact_roots);
    }
    rc.p = p * gen.PowerOfTwo(450);
  } else if (family == 7) {
    // Clustered roots.
    const double center = gen.Uniform(-5, 5);
    const double spacing = std::pow(10.0, gen.Uniform(-7, -2));
    Polynomial p{1.0};
    for (int i = 0; i < degree; ++i) p = p * Polynomial{-(center + i * spacing), 1.0};
    rc.p = p * gen.LogUniform(-50, 50);
  } else {
    // Roots at 0 and degree drops (leading coefficient 0 or tiny).
    rc.p = gen.RandomCoefficients(degree) * gen.LogUniform(-100, 100);
    if (gen.Chance(0.5)) {
      rc.p.SetCoefficient(0, 0.0);
      rc.exact_roots.push_back(0.0);
    }
    if (gen.Chance(0.5) && degree >= 2) rc.p.SetCoefficient(degree, 0.0);
    if (gen.Chance(0.3) && degree >= 2) rc.p.SetCoefficient(degree, gen.LogUniform(-300, -280));
  }

  // The interval: from 0, from a random time, or from near a root; to a horizon or far away.
  switch (gen.Int(0, 3)) {
    case 0:
      rc.lo = 0.0;
      break;
    case 1:
      rc.lo = gen.Uniform(-12, 12);
      break;
    case 2:
      rc.lo = rc.exact_roots.empty() ? -1e30 : rc.exact_roots[0];
      break;
    default:
      rc.lo = -gen.Uniform(0, 1) * 1e3;
      break;
  }
  rc.hi = gen.Chance(0.5) ? 1e30 : rc.lo + std::pow(10.0, gen.Uniform(-3, 2));
  return rc;
}

// Tolerances of the checks (the guarantees themselves are exact, see docs/math.md).
// A simple root must be found to within 1e-12 relative, plus the root's own condition
// (sum |c_i||t|^i / |p'(t)|, the forward error of a 1e-15 backward error), plus 4 ulps.
inline constexpr Real kSimpleRootRelTol = 1e-12L;
inline constexpr Real kSimpleRootBackwardError = 1e-15L;
// An answer earlier than the oracle's root is still legitimate where |p| is within this of
// 0 relative to sum |c_i| |t|^i (a near-touch inside EarliestRoot's ~2e-18 evaluation error).
inline constexpr Real kNearZeroRel = 1e-15L;

struct CheckStats {
  int cases = 0;
  int inconclusive = 0;
  int with_root = 0;
  int near_touch_early = 0;  // answers earlier than the oracle's root at a near-zero of p
  int failures = 0;
  Real max_simple_rel_error = 0;
};

inline void CheckEarliestRoot(const RootCase& rc, CheckStats& stats) {
  SCOPED_TRACE(rc.Describe());
  ++stats.cases;
  const std::optional<double> r = EarliestRoot(rc.p, rc.lo, rc.hi);
  const OracleResult oracle = OracleEarliestRoot(rc.p, rc.lo, rc.hi);
  if (!oracle.conclusive) {
    ++stats.inconclusive;
    if (std::getenv("SPARSEDYN_PRINT_INCONCLUSIVE") != nullptr) {
      std::printf("inconclusive: %s\n", rc.Describe().c_str());
    }
    return;
  }
  const int failures_before =
      ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();

  // Known exact roots bound the answer too.
  std::optional<double> known;
  for (double root : rc.exact_roots) {
    if (root >= rc.lo && root <= rc.hi && (!known || root < *known)) known = root;
  }
  if (r) {
    EXPECT_TRUE(std::isfinite(*r));
    EXPECT_GE(*r, rc.lo);
    EXPECT_LE(*r, rc.hi);
  }

  // Never late, never missed.
  if (oracle.has_certain) {
    ++stats.with_root;
    EXPECT_TRUE(r.has_value()) << "missed root in [" << static_cast<double>(oracle.certain_lo)
                               << ", " << static_cast<double>(oracle.certain_hi) << "]";
    if (r) {
      EXPECT_LE(static_cast<Real>(*r), oracle.certain_hi) << "later than the true root";
    }
  }
  if (known) {
    EXPECT_TRUE(r.has_value()) << "missed exact root " << *known;
    if (r) {
      EXPECT_LE(*r, *known) << "later than the exact root";
    }
  }

  // Not needlessly early: an answer before the reference must sit at a near-zero of p.
  if (r) {
    std::optional<Real> reference;
    Real tolerance = 0;
    if (oracle.has_certain) {
      const Real t = oracle.certain_lo;
      const Real slope = std::fabs(static_cast<Real>(rc.p.Derivative()(static_cast<double>(t))));
      const Real ulp = std::nextafter(std::fabs(static_cast<double>(t)),
                                      std::numeric_limits<double>::infinity()) -
                       std::fabs(static_cast<double>(t));
      tolerance = kSimpleRootRelTol * std::fabs(t) + 4 * ulp +
                  (slope > 0 ? kSimpleRootBackwardError * AbsoluteScale(rc.p, t) / slope
                             : std::numeric_limits<Real>::infinity());
      reference = t;
      // Relative error statistics over simple roots of moderate condition (<= 1e6) that are the
      // reference (no earlier possible or known root).
      const bool earliest =
          (!oracle.has_possible || oracle.possible >= t) && (!known || *known >= t);
      if (earliest && slope > 0 && *r <= t && std::fabs(t) > 0 &&
          AbsoluteScale(rc.p, t) <= 1e6L * slope * std::fabs(t)) {
        stats.max_simple_rel_error = std::max(stats.max_simple_rel_error, (t - *r) / std::fabs(t));
      }
    }
    if (known && (!reference || *known < *reference)) {
      reference = *known;
      tolerance = 1e-8L * std::max(1.0, std::fabs(*known));  // multiple root: ~sqrt(1e-18)
    }
    if (oracle.has_possible && (!reference || oracle.possible < *reference)) {
      reference = oracle.possible;
      tolerance = 1e-8L * std::max<Real>(1, std::fabs(oracle.possible));
    }
    const bool near_zero =
        std::fabs(OracleValueAt(rc.p, *r)) <= kNearZeroRel * AbsoluteScale(rc.p, *r);
    if (!reference || *r < *reference - tolerance) {
      EXPECT_TRUE(near_zero) << "answer " << *r << " is early or spurious; reference "
                             << (reference ? static_cast<double>(*reference) : 0.0);
      if (near_zero) ++stats.near_touch_early;
    }
  }
  const int failures_after =
      ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
  if (failures_after != failures_before) ++stats.failures;
}

inline void PrintStats(const char* name, std::uint64_t seed, const CheckStats& stats) {
  std::printf(
      "[ %s ] seed=%llu cases=%d with_root=%d inconclusive=%d near_touch_early=%d "
      "max_simple_rel_error=%.3Lg failures=%d\n",
      name, static_cast<unsigned long long>(seed), stats.cases, stats.with_root, stats.inconclusive,
      stats.near_touch_early, stats.max_simple_rel_error, stats.failures);
}

}  // namespace sparsedyn::testing
