// SPDX-License-Identifier: MIT
#include "math/roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

// The representative of an isolating interval: for a simple root the bracket is two adjacent
// doubles and we keep the one where |p| is smaller; a wider interval surrounds a multiple (or
// nearly multiple) root, whose best estimate is its middle.
double Representative(const Polynomial& p, const RootInterval& interval) {
  if (interval.hi <= std::nextafter(interval.lo, std::numeric_limits<double>::infinity())) {
    const long double at_lo = std::fabs(EvaluateCertified(p, interval.lo).value);
    const long double at_hi = std::fabs(EvaluateCertified(p, interval.hi).value);
    return at_lo <= at_hi ? interval.lo : interval.hi;
  }
  return interval.lo / 2 + interval.hi / 2;  // halves first: no overflow near DBL_MAX
}

// All real roots of p (any degree <= 8), ascending, at most `capacity`.
int SolveByIsolation(const Polynomial& p, double* roots, int capacity) {
  if (p.Degree() <= 2) {
    std::array<double, 2> quadratic_roots{};
    const int count = std::min(capacity, SolveQuadratic(p.Coefficient(2), p.Coefficient(1),
                                                        p.Coefficient(0), quadratic_roots));
    std::copy_n(quadratic_roots.begin(), count, roots);
    return count;
  }
  const double kMax = std::numeric_limits<double>::max();
  const RootIntervals intervals = IsolateRealRoots(p, -kMax, kMax);
  const int count = std::min(capacity, intervals.count);
  for (int i = 0; i < count; ++i) roots[i] = Representative(p, intervals[i]);
  return count;
}

}  // namespace

int SolveQuadratic(double a, double b, double c, std::array<double, 2>& roots) {
  // Degree drop: linear or constant.
  if (a == 0.0) {
    if (b == 0.0) return 0;
    const double root = -c / b;
    if (!std::isfinite(root)) return 0;
    roots[0] = root;
    return 1;
  }

  // Long double holds b^2 and 4ac without overflow and with 11 extra bits against cancellation.
  const long double la = a;
  const long double lb = b;
  const long double lc = c;
  const long double discriminant = lb * lb - 4 * la * lc;
  if (discriminant < 0) return 0;
  const long double q = -(lb + std::copysign(std::sqrt(discriminant), lb)) / 2;
  int count = 0;
  if (q == 0) {
    roots[count++] = 0.0;  // b == 0 and disc == 0, hence c == 0: double root at 0
    roots[count++] = 0.0;
    return count;
  }
  double r1 = static_cast<double>(q / la);
  double r2 = discriminant == 0 ? r1 : static_cast<double>(lc / q);
  if (r2 < r1) std::swap(r1, r2);
  if (std::isfinite(r1)) roots[count++] = r1;
  if (std::isfinite(r2)) roots[count++] = r2;
  return count;
}

int SolveCubic(const Polynomial& p, std::array<double, 3>& roots) {
  SPARSEDYN_ASSERT(p.Degree() <= 3, "SolveCubic needs degree <= 3");
  return SolveByIsolation(p, roots.data(), 3);
}

int SolveQuartic(const Polynomial& p, std::array<double, 4>& roots) {
  SPARSEDYN_ASSERT(p.Degree() <= 4, "SolveQuartic needs degree <= 4");
  return SolveByIsolation(p, roots.data(), 4);
}

std::optional<double> EarliestRoot(const Polynomial& p, double lo, double hi) {
  SPARSEDYN_ASSERT(std::isfinite(lo) && std::isfinite(hi) && lo <= hi,
                   "EarliestRoot needs a finite interval with lo <= hi");
  for (double c : p.Coefficients()) {
    SPARSEDYN_ASSERT(std::isfinite(c), "EarliestRoot needs finite coefficients");
  }
  const RootIntervals roots = IsolateRealRoots(p, lo, hi, /*first_only=*/true);
  if (roots.count == 0) return std::nullopt;
  return roots[0].lo;
}

}  // namespace sparsedyn
