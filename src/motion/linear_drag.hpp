// SPDX-License-Identifier: MIT
#pragma once

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The unit round-off of double, u = 2^-53: |fl(x op y) - x op y| <= u |fl(x op y)| for a
/// normal result under round-to-nearest (Higham, "Accuracy and Stability", §2.2).
inline constexpr double kUnitRoundoff = 0x1p-53;

/// A body's true state at one time during a drag segment, with certified bounds: the exact
/// motion (of the segment's double inputs, at the exact time asked for) lies within
/// `position_error` (m) of `position`, `velocity_error` (m/s) of `velocity` and
/// `acceleration_error` (m/s^2) of `acceleration` (Euclidean norms, world frame).
struct DragState {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  double position_error = 0.0;
  double velocity_error = 0.0;
  double acceleration_error = 0.0;
};

/// phi1(u) = (1 - e^-u) / u and phi2(u) = (e^-u - 1 + u) / u^2 for u = c1 dt >= 0, and the
/// decay e^-u: the closed form of linear drag is x = x0 + dt (v0 phi1 + g dt phi2). phi1(0) = 1
/// and phi2(0) = 1/2 exactly, so that c1 = 0 is the constant-acceleration polynomial.
struct LinearDragFactors {
  double phi1 = 1.0;
  double phi2 = 0.5;
  double decay = 1.0;
};

/// The factors at u >= 0 (finite), each within kLinearDragFactorError relative of its exact
/// value at this u (linear_drag.cpp derives the constant).
LinearDragFactors LinearDragFactorsAt(double u);

/// Relative error bound of LinearDragFactorsAt, in units of kUnitRoundoff: phi2's series below
/// u = 1 (Horner over 19 terms whose magnitudes sum to at most twice phi2, < 77 u) is the
/// largest part (linear_drag.cpp). It assumes that glibc's expm1 and exp, documented to 1 ulp
/// on x86-64, are within 2 ulps.
inline constexpr double kLinearDragFactorError = 96.0;

/// The exact motion under a = g - c1 v (c1 >= 0, finite; App. H.2 without the quadratic term)
/// from position p0 and velocity v0, `dt` >= 0 later (dt taken as exact), with certified
/// round-off bounds:
///   v(dt) = v0 + (g - c1 v0) dt phi1(c1 dt),  x(dt) = x0 + dt (v0 phi1 + g dt phi2),
///   a(dt) = (g - c1 v0) e^(-c1 dt),  and the terminal velocity g / c1 as dt -> infinity.
/// For c1 = 0 it is the polynomial p0 + dt (v0 + (dt / 2) g) of Path::PositionAt, bit for bit.
DragState LinearDragStateAfter(const Vec3& p0, const Vec3& v0, const Vec3& g, double c1, double dt);

}  // namespace sparsedyn
