// SPDX-License-Identifier: MIT
#pragma once

#include "motion/drag_taylor.hpp"
#include "motion/linear_drag.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// Per-step tolerance of the certified quadratic-drag integrator, relative to the segment's
/// speed bound: the series tail of a Taylor step and the neglected quadratic drag of a slow
/// step stay below it (m/s); a settled step starts once the node is within the larger of it
/// and the node's own velocity bound of terminal velocity.
inline constexpr double kDragStepTolerance = 0x1p-52;

/// What one segment of quadratic drag (c2 > 0) knows before any step: the model, the
/// a-priori bounds of its exact motion, and its terminal velocity.
struct DragFlow {
  DragModel model;
  /// |v(t)| <= speed_bound for every t >= t0: d|v|/dt = v.g/|v| - c1 |v| - c2 |v|^2 < 0 above the
  /// terminal speed of |g|, so the speed never exceeds max(|v0|, terminal speed).
  double speed_bound = 0.0;
  /// The computed terminal velocity g 2 / (c1 + sqrt(c1^2 + 4 c2 |g|)) (the root of
  /// c1 s + c2 s^2 = |g| along g, written without cancellation) and a bound on its error.
  Vec3 terminal_velocity = Vec3::Zero();
  double terminal_velocity_error = 0.0;
  /// mu <= c1 + c2 |v_terminal| / 2, the rate at which |v - v_terminal| decays at least
  /// (drag_stepper.cpp derives it).
  double contraction = 0.0;
  double tolerance = 0.0;  // kDragStepTolerance times speed_bound

  /// The flow from velocity v0 at the segment start; c2 > 0 (asserted).
  static DragFlow Make(const DragModel& model, const Vec3& v0);
};

/// Walks the step grid of one quadratic-drag segment from its start, one step at a time. The
/// grid depends only on the segment (never on the times evaluated), so every evaluation of a
/// time gives the same bits, and nearby times are evaluated on the same step polynomial.
/// Steps are of three kinds (drag_stepper.cpp): a Taylor step (drag_taylor.hpp), a slow step
/// near zero speed (the linear-drag closed form plus a bound on the neglected quadratic term),
/// and a final settled step (at terminal velocity, whose distance from it only shrinks).
class DragStepper {
 public:
  /// At the segment start (offset 0) in position p0 with velocity v0.
  DragStepper(const DragFlow& flow, const Vec3& p0, const Vec3& v0);

  /// The current step covers offsets [Begin(), End()] from the segment start (s); End() is
  /// infinite for the final step.
  double Begin() const { return begin_; }
  double End() const { return end_; }

  /// Moves to the next step (the current one must not be final).
  void Advance();

  /// Moves forward until the current step contains `offset` (>= Begin()).
  void AdvanceTo(double offset);

  /// The exact motion at `offset` (a double, taken as exact) in [Begin(), End()], with
  /// certified bounds (DragState). The position bound does not decrease with the offset within
  /// a step nor from one step to the next, so its value at the end of an interval bounds the
  /// whole interval.
  DragState Evaluate(double offset) const;

  /// How many steps have been taken from the start.
  int steps() const { return steps_; }

 private:
  enum class Kind { kTaylor, kSlow, kSettled };
  void PrepareStep();
  DragState EvaluateInStep(double sigma) const;

  const DragFlow* flow_;
  // The node that starts the current step: state and bounds against the exact motion.
  double begin_ = 0.0;
  Vec3 position_ = Vec3::Zero();
  Vec3 velocity_ = Vec3::Zero();
  double position_error_ = 0.0;
  double velocity_error_ = 0.0;
  double accel_bound_ = 0.0;  // >= |f(velocity_)|, hence >= |a| of the exact motion after it
  // The current step.
  Kind kind_ = Kind::kSlow;
  double end_ = 0.0;
  double settled_deviation_ = 0.0;  // kSettled: >= |v(begin_) - v_terminal| of the exact motion
  DragTaylorSeries series_;         // kTaylor
  int steps_ = 0;
};

}  // namespace sparsedyn
