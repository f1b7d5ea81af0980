// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>

namespace sparsedyn {

/// Highest degree a Polynomial can hold: a quartic meeting equation (App. F.3) with a cubic
/// friction term (App. G.1) needs 6; 8 leaves room for one more order of motion.
inline constexpr int kMaxPolynomialDegree = 8;

/// p(t) = c[0] + c[1] t + ... + c[d] t^d with real (double) coefficients and fixed capacity
/// (no heap), so that it can live in events and be copied freely. `t` is whatever time variable
/// the caller chose (usually a duration since a segment's reference time, see motion/).
class Polynomial {
 public:
  /// The zero polynomial (Degree() == -1).
  Polynomial() = default;

  /// The polynomial with these coefficients, lowest order first; at most
  /// kMaxPolynomialDegree + 1 of them (asserted).
  Polynomial(std::initializer_list<double> coefficients_low_to_high);

  /// The polynomial with coefficients c[0..count), lowest order first; count <= 9 (asserted).
  static Polynomial FromCoefficients(const double* c, int count);

  /// Highest i with c[i] != 0, or -1 for the zero polynomial. A tiny but non-zero leading
  /// coefficient still counts: callers that want a degree drop must zero it explicitly.
  int Degree() const;

  /// c[i] for 0 <= i <= kMaxPolynomialDegree, 0 beyond the degree; i outside that range is 0 too.
  double Coefficient(int i) const {
    return i < 0 || i > kMaxPolynomialDegree ? 0.0 : c_[static_cast<std::size_t>(i)];
  }

  /// Sets c[i]; 0 <= i <= kMaxPolynomialDegree (asserted).
  void SetCoefficient(int i, double value);

  /// All kMaxPolynomialDegree + 1 coefficients, lowest order first (zeros beyond the degree).
  const std::array<double, kMaxPolynomialDegree + 1>& Coefficients() const { return c_; }

  /// p(t) by Horner's rule in double (a-priori error <= 2 d u sum |c_i| |t|^i, u = 2^-53).
  double operator()(double t) const;

  /// p'(t) as a polynomial (coefficients i c[i], rounded to double).
  Polynomial Derivative() const;

  /// q(t) = p(t + dt), i.e. the same curve about a new origin (Taylor shift by repeated
  /// synthetic division, O(d^2), rounded to double). Use it to re-base a path at a later t0.
  Polynomial Shifted(double dt) const;

  /// Sum, difference and product; the product's degree must stay <= kMaxPolynomialDegree
  /// (asserted).
  friend Polynomial operator+(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);

  /// Every coefficient times s.
  Polynomial operator*(double s) const;
  friend Polynomial operator*(double s, const Polynomial& p) { return p * s; }

  /// -p.
  Polynomial operator-() const;

  /// Coefficient-wise equality (so +0 == -0 and the degree is implied).
  friend bool operator==(const Polynomial& a, const Polynomial& b) = default;

  /// "Polynomial{c0, c1, ..., cd}" with 17 significant digits: paste-able C++ that rebuilds
  /// exactly this polynomial (for failure reports and regression tests).
  std::string ToString() const;

 private:
  std::array<double, kMaxPolynomialDegree + 1> c_{};
};

}  // namespace sparsedyn
