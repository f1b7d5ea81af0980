// SPDX-License-Identifier: MIT
#include "motion/linear_drag.hpp"

#include <array>
#include <cmath>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {

namespace {

// 1/(k+2)! for k = 0..18: phi2(u) = sum_k (-u)^k / (k+2)!, an alternating series whose terms
// fall for u < 1, so the first term left out, u^19/21! < 2e-20, bounds the truncation.
constexpr std::array<double, 19> kPhi2Series = [] {
  std::array<double, 19> c{};
  double factorial = 2.0;  // (k+2)! for k = 0
  for (std::size_t k = 0; k < c.size(); ++k) {
    c[k] = 1.0 / factorial;
    factorial *= static_cast<double>(k + 3);
  }
  return c;
}();

// Round-off of phi2 by the series (u < 1): Horner's rule over 19 terms is within
// gamma_38 sum_k |c_k| u^k (Higham, "Accuracy and Stability", eq. 5.3), the rounded
// coefficients add u sum_k |c_k| u^k, and sum_k |c_k| u^k = (e^u - 1 - u)/u^2 <= e - 2 while
// phi2 >= e^-1 on [0, 1]: 39 (e - 2) e u < 77 u. By the closed form (u >= 1),
// S = u + expm1(-u) >= e^-1 carries expm1's error (<= 2 ulps of |expm1| <= 1, i.e. 4u) and one
// rounding, 4 e + 1 < 12 u relative, and the two divisions 2u more. phi1 = -expm1(-u)/u is
// within 4u + u, and e^-u within 4u. All are below kLinearDragFactorError = 96 u.

}  // namespace

LinearDragFactors LinearDragFactorsAt(double u) {
  SPARSEDYN_ASSERT(u >= 0.0 && std::isfinite(u), "linear drag: c1 dt must be finite and >= 0");
  if (u == 0.0) return {};
  LinearDragFactors f;
  const double em1 = std::expm1(-u);  // e^-u - 1, without cancellation for small u
  f.phi1 = -em1 / u;
  f.decay = std::exp(-u);
  if (u < 1.0) {
    double sum = kPhi2Series.back();
    for (std::size_t k = kPhi2Series.size() - 1; k-- > 0;) sum = kPhi2Series[k] - u * sum;
    f.phi2 = sum;
  } else {
    // (u - 1 + e^-u) / u^2 as (S / u) / u, which cannot overflow for any finite u.
    f.phi2 = ((u + em1) / u) / u;
  }
  return f;
}

DragState LinearDragStateAfter(const Vec3& p0, const Vec3& v0, const Vec3& g, double c1,
                               double dt) {
  SPARSEDYN_ASSERT(c1 >= 0.0 && std::isfinite(c1), "linear drag: c1 must be finite and >= 0");
  SPARSEDYN_ASSERT(dt >= 0.0 && std::isfinite(dt), "linear drag: dt must be finite and >= 0");
  constexpr double u = kUnitRoundoff;
  // Every bound below is a sum of non-negative terms evaluated in round-to-nearest; the factor
  // 1.01 covers both the (1 + u)^k of that evaluation and the second-order terms of the
  // first-order analyses (k u < 0.01 throughout).
  constexpr double kSlack = 1.01;
  DragState s;
  const double c1_dt = c1 * dt;
  const LinearDragFactors f = LinearDragFactorsAt(c1_dt);
  const Vec3 a0 = g - c1 * v0;  // the acceleration at the start

  if (c1 == 0.0) {
    // The constant-acceleration polynomial, written as Path::PositionAt / VelocityAt write it.
    s.position = p0 + dt * (v0 + (0.5 * dt) * g);
    s.velocity = v0 + dt * g;
    s.acceleration = g;
  } else {
    s.position = p0 + dt * (v0 * f.phi1 + (g * dt) * f.phi2);
    s.velocity = v0 + (a0 * dt) * f.phi1;
    s.acceleration = a0 * f.decay;
  }

  // Relative errors of the factors: their evaluation (kLinearDragFactorError), and the
  // rounding of u = c1 dt, which moves phi1 and phi2 by at most |u phi'(u) / phi(u)| <= 1 times
  // its relative error (both log-derivatives lie in [-1, 0]; tests/motion check it) and e^-u by
  // u times it.
  const double phi_error = (kLinearDragFactorError + 2.0) * u;
  const double decay_error = (kLinearDragFactorError + c1_dt) * u;

  // a0 = fl(g - fl(c1 v0)) is within u (|a0| + c1 |v0|) per component (two roundings).
  const double a0_norm = a0.norm();
  const double a0_error = kSlack * u * (a0_norm + c1 * v0.norm());

  // x = fl(p0 + fl(dt fl(fl(v0 phi1) + fl(fl(g dt) phi2)))): the last addition is within
  // u |x| <= u (|p0| + moved), and the bracket carries the factor errors and four roundings of
  // its own. dt phi1 = (1 - e^-u)/c1 and dt^2 phi2 grow with dt, so the bounds do too (a bound
  // at the end of an interval bounds all of it).
  const double moved = dt * (v0.norm() * f.phi1 + g.norm() * dt * f.phi2);
  s.position_error = kSlack * (u * (p0.norm() + kSlack * moved) + (phi_error + 4.0 * u) * moved);
  // v = fl(v0 + fl(fl(a0 dt) phi1)): the sum, the factor, two roundings, and a0's own error.
  const double gained = dt * f.phi1 * a0_norm;
  s.velocity_error = kSlack * (u * (v0.norm() + kSlack * gained) + (phi_error + 2.0 * u) * gained +
                               dt * f.phi1 * a0_error);
  // a = fl(a0 e^-u): one rounding, the decay's error and a0's.
  s.acceleration_error =
      kSlack * (u * s.acceleration.norm() + f.decay * (decay_error * a0_norm + a0_error));
  return s;
}

}  // namespace sparsedyn
