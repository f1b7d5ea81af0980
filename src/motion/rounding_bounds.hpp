// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <limits>

#include "motion/linear_drag.hpp"

namespace sparsedyn {

// Rigorous round-off bounds for the certified drag integrator (drag_taylor.cpp), in the
// standard model of IEEE double arithmetic with round-to-nearest and no overflow:
// fl(x op y) = (x op y)(1 + d) + e with |d| <= u = 2^-53 and |e| <= 2^-1075 (underflow), and
// sqrt correctly rounded (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed.,
// §2.2; the project builds with -ffp-contract=off, so no fused operation changes a rounding).
//
// A "ball" is a value `mid` (a double) with a radius `rad` >= |exact - mid|, as in Rump's
// midpoint-radius arithmetic (Rump, "Fast and parallel interval arithmetic", BIT 39, 1999).

/// A radius evaluated in round-to-nearest as an expression of non-negative terms, made an upper
/// bound of the exact expression: each of its at most ~4000 roundings loses at most u relative,
/// which 2^-40 covers, and DBL_MIN covers any number (< 2^53) of underflows of 2^-1075 each.
inline double RoundedUp(double rad) {
  return rad * (1.0 + 0x1p-40) + std::numeric_limits<double>::min();
}

/// An upper bound of gamma_k = k u / (1 - k u) (Higham, Lemma 3.1) for k u <= 0.01.
inline double Gamma(int k) { return 1.01 * k * kUnitRoundoff; }

/// A scalar with a certified radius: the exact value lies in [mid - rad, mid + rad].
struct Ball {
  double mid = 0.0;
  double rad = 0.0;
};

/// The sum of products sum_j a_j b_j of balls, accumulated in round-to-nearest (in any order,
/// k terms). With R = sum_j (|a.mid| b.rad + a.rad (|b.mid| + b.rad)) and Q = sum_j
/// |a.mid b.mid|:
///   |sum_j a_j b_j - fl(sum_j a.mid b.mid)| <= R + gamma_k Q,
/// since |a b - a.mid b.mid| <= |a.mid| b.rad + a.rad |b| and the dot product of the mids is
/// within gamma_k Q (Higham, eq. 3.4, which holds for any order of summation). The computed R
/// (non-negative terms, k + 3 roundings each) is within gamma_(k+3) of R and the computed Q
/// within gamma_(k+1) of Q; RoundedUp covers the former, the factor 1.02 the latter.
struct BallSum {
  double mid = 0.0;
  double abs = 0.0;
  double rad = 0.0;
  int terms = 0;

  void Add(double a_mid, double a_rad, double b_mid, double b_rad) {
    const double product = a_mid * b_mid;
    mid += product;
    abs += std::abs(product);
    rad += std::abs(a_mid) * b_rad + a_rad * (std::abs(b_mid) + b_rad);
    ++terms;
  }
  /// The same with an exact first factor (a model constant such as c1, or a power of two).
  void AddExact(double a, double b_mid, double b_rad) {
    const double product = a * b_mid;
    mid += product;
    abs += std::abs(product);
    rad += std::abs(a) * b_rad;
    ++terms;
  }
  /// Adds another sum's terms (a split accumulation).
  void Merge(const BallSum& other) {
    mid += other.mid;
    abs += other.abs;
    rad += other.rad;
    terms += other.terms;
  }

  double Radius() const { return RoundedUp(rad + 1.02 * Gamma(terms) * abs); }
  Ball Result() const { return Ball{mid, Radius()}; }
};

/// x / d for an exact positive integer (or other exact double) d.
inline Ball DividedBy(const Ball& x, double d) {
  const double mid = x.mid / d;
  return Ball{mid, RoundedUp(x.rad / d + kUnitRoundoff * std::abs(mid))};
}

/// n / d for a ball d with d.mid > d.rad >= 0:
///   |n / d - n.mid / d.mid| <= (n.rad d.mid + |n.mid| d.rad) / ((d.mid - d.rad) d.mid),
/// plus the rounding of the quotient.
inline Ball DividedBy(const Ball& n, const Ball& d) {
  const double mid = n.mid / d.mid;
  const double rad = (n.rad * d.mid + std::abs(n.mid) * d.rad) / ((d.mid - d.rad) * d.mid);
  return Ball{mid, RoundedUp(rad + kUnitRoundoff * std::abs(mid))};
}

/// sqrt(x) for x.mid > 0: |sqrt(x) - sqrt(x.mid)| = |x - x.mid| / (sqrt(x) + sqrt(x.mid))
/// <= x.rad / sqrt(x.mid), plus the rounding of the square root.
inline Ball SquareRoot(const Ball& x) {
  const double mid = std::sqrt(x.mid);
  return Ball{mid, RoundedUp(x.rad / mid + kUnitRoundoff * mid)};
}

}  // namespace sparsedyn
