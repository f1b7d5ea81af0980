// SPDX-License-Identifier: MIT
#pragma once

#include "motion/drag_stepper.hpp"
#include "motion/linear_drag.hpp"
#include "motion/path.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The sparse phase's view of a drag segment from time `path.t0` on: the quadratic Path of the
/// true state there (position, velocity, acceleration) and an Envelope, measured from
/// path.t0, that holds the true motion, |x(path.t0 + dt) - path.PositionAt(path.t0 + dt)| <=
/// envelope.At(dt) for dt in [0, horizon], both the exact motion and the positions
/// DragMotion reports (its round-off and integration error included). docs/dynamics.md, "Drag".
struct TaylorSegment {
  Path path;
  Envelope envelope;
  double horizon = 0.0;  // s
};

/// The true motion of one segment of a body under drag (App. H.2, issue #36 part 5):
///   x'' = a = g - c1 v - c2 |v| v   from position p0 and velocity v0 at time t0,
/// with g the body's constant acceleration (gravity plus thrust, m/s^2) and Drag{c1, c2}.
/// - c2 = 0: the closed form of linear drag (linear_drag.hpp), exactly the constant-acceleration
///   polynomial of Path for c1 = 0;
/// - c2 > 0: a certified Taylor-series integrator (drag_stepper.hpp, drag_taylor.hpp) whose
///   error bound is rigorous (Cauchy estimates for the series tail, ball arithmetic for the
///   round-off, and the monotonicity of drag so that step errors add up).
/// Every state comes with a certified bound against the exact solution of the double inputs
/// at the exact time asked for. Evaluations are deterministic: the same motion and time give
/// the same bits, whatever was evaluated before (nothing is cached).
///
/// Preconditions (asserted; checking user input is the caller's job): all inputs finite,
/// c1 >= 0, c2 >= 0, times t >= t0. Cost: the closed form is O(1) (~50 ns); the integrator
/// walks its step grid from t0 at each evaluation, O(steps) with a few microseconds a step, so
/// the World should start a new DragMotion at every event of the body (a check included),
/// which keeps a walk to one horizon. The offsets t - t0 must stay far above the steps'
/// resolution: a segment longer than ~2^40 of its step size asserts.
class DragMotion {
 public:
  DragMotion(double t0, const Vec3& p0, const Vec3& v0, const Vec3& g, const Drag& drag);

  double t0() const { return t0_; }
  const Vec3& p0() const { return p0_; }
  const Vec3& v0() const { return v0_; }
  const Vec3& g() const { return g_; }
  const Drag& drag() const { return drag_; }
  /// True when c2 = 0: the closed form, O(1) per evaluation.
  bool IsClosedForm() const { return drag_.quadratic == 0.0; }

  /// The true state at t >= t0 with its certified error bounds.
  DragState StateAt(double t) const;
  Vec3 PositionAt(double t) const { return StateAt(t).position; }
  Vec3 VelocityAt(double t) const { return StateAt(t).velocity; }
  Vec3 AccelerationAt(double t) const { return StateAt(t).acceleration; }
  /// A certified bound on |PositionAt(t) - x_exact(t)| (m); non-decreasing in t.
  double PositionErrorAt(double t) const { return StateAt(t).position_error; }

  /// The quadratic path about t >= t0 and its envelope over [t, t + horizon] (horizon >= 0,
  /// finite).
  TaylorSegment SegmentAt(double t, double horizon) const;

  /// The longest horizon (within 1%, at most max_horizon) over which the envelope of
  /// SegmentAt(t, horizon) stays <= max_error (m, > 0): check events "at the rate the bound
  /// allows" (App. E.2). It grows without bound as the body settles at terminal velocity and
  /// is infinite only for a body at rest without gravity. It is 0 when the state at t is not
  /// known to max_error.
  double HorizonFor(double t, double max_error, double max_horizon = kInfinity) const;

  /// HorizonFor and SegmentAt at once, with one walk of the integrator instead of two: what
  /// the World calls at the start of each segment.
  TaylorSegment SegmentFor(double t, double max_error, double max_horizon = kInfinity) const;

  /// The velocity the motion tends to: g / c1 for linear drag, g 2 / (c1 + sqrt(c1^2 +
  /// 4 c2 |g|)) with quadratic drag (the root of c1 s + c2 s^2 = |g| along g); 0 without g.
  /// Precondition: drag is not zero or g = 0.
  Vec3 TerminalVelocity() const;

  /// An a-priori bound on the speed for all t >= t0: max(|v0|, terminal speed) with drag
  /// (the speed falls whenever it is above the terminal speed of |g|); infinite without drag
  /// when g != 0.
  double SpeedBound() const { return speed_bound_; }
  /// An a-priori bound on |acceleration| for all t >= t0.
  double AccelerationBound() const { return accel_bound_; }

 private:
  struct Horizon;
  Horizon FindHorizon(double t, double max_error, double max_horizon) const;
  DragState ClosedFormStateAt(double dt) const;
  DragState AddTimeRounding(DragState state, double dt) const;

  double t0_;
  Vec3 p0_;
  Vec3 v0_;
  Vec3 g_;
  Drag drag_;
  double accel_bound_;  // >= |a(t0)| >= |a(t)| for every t >= t0
  double speed_bound_;
  DragFlow flow_;  // c2 > 0 only
};

}  // namespace sparsedyn
