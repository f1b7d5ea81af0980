// SPDX-License-Identifier: MIT
// Closed forms of linear drag (a = g - c1 v), the oracles of the drag tests: heights and times in
// long double, contact times by bisection.
#pragma once

#include <cmath>

namespace sparsedyn::testing {

using Real = long double;

// Linear drag from rest with gravity g (< 0) along z: z(t) = z0 + v_inf t - v_inf (1 - e^(-c1 t))
// / c1, v_inf = g / c1.
inline Real FallHeight(Real z0, Real g, Real c1, Real t) {
  const Real v_inf = g / c1;
  return z0 + v_inf * t - v_inf * (-std::expm1(-c1 * t)) / c1;
}

// The first time the fall from z0 reaches height `contact` (bisection on [0, t_max]).
inline double FallTime(Real z0, Real g, Real c1, Real contact, Real t_max) {
  Real lo = 0, hi = t_max;
  for (int k = 0; k < 200; ++k) {
    const Real mid = (lo + hi) / 2;
    (FallHeight(z0, g, c1, mid) > contact ? lo : hi) = mid;
  }
  return static_cast<double>(lo);
}

// Without gravity from speed v0: the distance s(t) = v0 (1 - e^(-c1 t)) / c1 covers d at
// t = -ln(1 - c1 d / v0) / c1.
inline double CoastTime(Real v0, Real c1, Real d) {
  return static_cast<double>(-std::log1p(-c1 * d / v0) / c1);
}

}  // namespace sparsedyn::testing
