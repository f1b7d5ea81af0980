// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstddef>

#include "math/polynomial.hpp"

namespace sparsedyn {

/// A closed interval [lo, hi] of the time axis (lo <= hi).
struct RootInterval {
  double lo;
  double hi;
};

/// The result of IsolateRealRoots: sorted, disjoint intervals (fixed capacity, no heap).
struct RootIntervals {
  /// Room for every interval a degree-8 isolation can produce (see AddInterval in the .cpp).
  static constexpr int kCapacity = 2 * kMaxPolynomialDegree + 2;

  /// Only items[0, count) are meaningful; the rest is left uninitialised on purpose (this sits
  /// on the prediction hot path, where zeroing 288 bytes per derivative level was measurable).
  std::array<RootInterval, kCapacity> items;
  int count = 0;

  const RootInterval& operator[](int i) const { return items[static_cast<std::size_t>(i)]; }
};

/// p(t) evaluated in extended precision with a rigorous bound on its rounding error:
/// |value - p_exact(t)| <= error_bound, where p_exact uses exactly the double coefficients of p.
struct CertifiedValue {
  long double value = 0.0L;
  long double error_bound = 0.0L;

  /// +1 or -1 when the sign of p_exact(t) is certain, 0 when p_exact(t) may be zero.
  int Sign() const { return value > error_bound ? 1 : (value < -error_bound ? -1 : 0); }
};

/// Horner's rule in long double (64-bit mantissa, 15-bit exponent: no overflow or underflow
/// is possible for double coefficients and |t| <= DBL_MAX at degree <= 8) with the a-priori
/// bound gamma_2d * sum |c_i| |t|^i (Higham, "Accuracy and Stability of Numerical Algorithms",
/// Thm 5.3), doubled as a margin for the rounding of the bound itself.
CertifiedValue EvaluateCertified(const Polynomial& p, double t);

/// Certified isolation of the real roots of p in [lo, hi] (finite, lo <= hi): every real root of
/// p in [lo, hi] (any multiplicity) lies in one of the returned intervals, and at every point of
/// [lo, hi] outside them p has a certified non-zero sign. An interval around a simple root is
/// normally two adjacent doubles; around an even-multiplicity (touching) root it is the zone where
/// |p| is below the evaluation error (about 1e-9 relative for a double root); an interval may
/// also be a near-touch that does not reach zero. With `first_only`, isolation stops after the
/// first interval and only its `lo` is meaningful (the right edge may be left wide). The zero
/// polynomial yields [lo, hi]; a non-zero constant yields nothing.
RootIntervals IsolateRealRoots(const Polynomial& p, double lo, double hi, bool first_only = false);

/// A power of two B with |z| < B for every complex root z of p (Fujiwara's bound rounded up to
/// powers of two using only exponents); +infinity when B exceeds the double range, 0 when all
/// roots are 0. p must not be constant (asserted).
double RootMagnitudeBound(const Polynomial& p);

}  // namespace sparsedyn
