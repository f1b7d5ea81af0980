// SPDX-License-Identifier: MIT
#pragma once

#include <array>

#include "motion/linear_drag.hpp"
#include "motion/rounding_bounds.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The velocity ODE of drag (App. H.2): v' = f(v) = g - c1 v - c2 |v| v (g, c1 >= 0, c2 >= 0
/// exact doubles). Positions follow x' = v.
struct DragModel {
  Vec3 g = Vec3::Zero();
  double c1 = 0.0;
  double c2 = 0.0;

  /// f(v) in double.
  Vec3 AccelerationAt(const Vec3& v) const { return g - c1 * v - (c2 * v.norm()) * v; }

  /// A bound on |f(v) - fl(f(v))| for the computed `a` = AccelerationAt(v): |v| is within
  /// 2.6 u relative (a three-term dot product and a square root), and each component carries
  /// at most six more roundings; 8 u covers them all.
  double AccelerationRounding(const Vec3& v, const Vec3& a) const {
    return RoundedUp(8.0 * kUnitRoundoff *
                     (a.norm() + g.norm() + c1 * v.norm() + c2 * v.squaredNorm()));
  }

  /// A Lipschitz constant of f on real velocities of norm <= speed: the Jacobian
  /// -c1 I - c2 (|v| I + v v^T / |v|) has norm c1 + 2 c2 |v|.
  double Lipschitz(double speed) const { return RoundedUp(c1 + 2.0 * c2 * speed); }
};

/// Degree of the velocity series of a Taylor step. The cost per unit time is about n^2 / q(n)
/// with q(n) = (2^-52 / 4)^(1/(n+1)) the step's share of the Cauchy radius; it is flat between
/// 12 and 24 and lowest near 16.
inline constexpr int kDragTaylorOrder = 16;

/// Largest share of the Cauchy radius that a step uses (the tail's 1 / (1 - q) stays <= 2).
inline constexpr double kDragTaylorMaxShare = 0.5;

/// How long a Taylor step from velocity V may be, and the Cauchy-estimate data of its tail
/// (drag_taylor.cpp derives them): the exact solution from V continues analytically to the
/// complex disc |tau| <= rho and stays within r of V there.
struct DragTaylorPlan {
  double r = 0.0;       // m/s
  double rho = 0.0;     // s
  double length = 0.0;  // s, the planned step (0: no Taylor step is possible from V)
};

/// The plan for a step from velocity `v` (|v| > 0) with |f(v)| <= accel_bound, whose series
/// tail should stay below `tolerance` (m/s).
DragTaylorPlan PlanDragTaylorStep(const DragModel& model, const Vec3& v, double accel_bound,
                                  double tolerance);

/// The Taylor series of the exact velocity about a node, u(sigma) = sum_m c_m sigma^m, with
/// certified radii for c_0..c_n (componentwise), the position coefficients c_m / (m + 1) with
/// theirs, the norms that the evaluation's bounds use, and the plan that bounds the rest.
struct DragTaylorSeries {
  std::array<Vec3, kDragTaylorOrder + 1> mid;
  std::array<Vec3, kDragTaylorOrder + 1> rad;
  std::array<Vec3, kDragTaylorOrder + 1> position_mid;
  std::array<double, kDragTaylorOrder + 1> mid_norm;
  std::array<double, kDragTaylorOrder + 1> rad_norm;
  std::array<double, kDragTaylorOrder + 1> position_mid_norm;
  std::array<double, kDragTaylorOrder + 1> position_rad_norm;
  DragTaylorPlan plan;
};

/// The series of the exact solution from velocity `v` (|v| > 0), by the recurrences of
/// automatic differentiation run in ball arithmetic (drag_taylor.cpp).
DragTaylorSeries DragTaylorSeriesAt(const DragModel& model, const Vec3& v,
                                    const DragTaylorPlan& plan);

/// The exact solution from (`position`, velocity c_0) evaluated `sigma` later, 0 <= sigma <=
/// plan.length (sigma exact): position and velocity with bounds on round-off and series tail
/// together. The bounds are non-decreasing in sigma (so the one at the step's end bounds the
/// whole step). The acceleration is left to the caller.
DragState EvaluateDragTaylor(const DragTaylorSeries& series, const Vec3& position, double sigma);

}  // namespace sparsedyn
