// SPDX-License-Identifier: MIT
#include "motion/drag_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {

// Why errors add up instead of growing exponentially: f(v) = g - grad(c1 |v|^2/2 + c2 |v|^3/3)
// is the gradient field of a concave function, and
//   (|v| v - |w| w) . (v - w) = |v|^3 + |w|^3 - (|v| + |w|) v.w
//                             = (|v| + |w|) |v - w|^2 / 2 + (|v| - |w|)^2 (|v| + |w|) / 2,
// so (f(v) - f(w)) . (v - w) <= -(c1 + c2 (|v| + |w|) / 2) |v - w|^2 <= 0. Two solutions of
// v' = f(v) therefore never move apart: d|v - w|/dt <= 0. If the node of a step is within
// E_v of the exact motion, the exact solution from the node stays within E_v of it for the
// whole step, and the positions drift apart by at most E_v per second. Each step adds only its
// own error (DragStepper::EvaluateInStep); there is no Gronwall factor. With w = v_terminal
// (f(w) = 0) the same inequality makes |v - v_terminal| decay at least like e^(-mu t),
// mu = c1 + c2 |v_terminal| / 2: the settled step's bound.

namespace {

double RoundedDown(double x) { return x * (1.0 - 0x1p-40); }

// Bound of how far a Taylor step lands from its planned end (round-off of the offsets):
// the step must stay well inside the Cauchy disc.
constexpr double kMaxShareAfterRounding = 0.75;

}  // namespace

DragFlow DragFlow::Make(const DragModel& model, const Vec3& v0) {
  SPARSEDYN_ASSERT(model.c2 > 0.0, "DragFlow is for quadratic drag (c2 > 0)");
  DragFlow flow;
  flow.model = model;
  const double g_norm = model.g.norm();
  if (g_norm > 0.0) {
    const double c1 = model.c1;
    const double k = 2.0 / (c1 + std::sqrt(c1 * c1 + 4.0 * model.c2 * g_norm));
    flow.terminal_velocity = model.g * k;
    // |g| (2.6 u), the radicand (3 more), the root (half of that, plus u), the sum, the
    // quotient and the product: about 10 u relative; 16 u is claimed.
    flow.terminal_velocity_error = RoundedUp(16.0 * kUnitRoundoff * flow.terminal_velocity.norm());
  }
  const double terminal_speed = flow.terminal_velocity.norm() + flow.terminal_velocity_error;
  flow.speed_bound = RoundedUp(std::max(v0.norm(), terminal_speed) * (1.0 + 4.0 * kUnitRoundoff));
  flow.contraction = RoundedDown(
      model.c1 +
      0.5 * model.c2 * std::max(0.0, flow.terminal_velocity.norm() - flow.terminal_velocity_error));
  // RoundedUp keeps it >= DBL_MIN, the floor of every bound: a body at rest without gravity
  // (speed bound 0) then settles at once instead of taking steps of no length.
  flow.tolerance = RoundedUp(kDragStepTolerance * flow.speed_bound);
  return flow;
}

DragStepper::DragStepper(const DragFlow& flow, const Vec3& p0, const Vec3& v0)
    : flow_(&flow), position_(p0), velocity_(v0) {
  PrepareStep();
}

// Chooses the current step from its node: settled if the node is within the tolerance of
// terminal velocity, else the longer of a Taylor step and a slow step.
void DragStepper::PrepareStep() {
  const DragFlow& flow = *flow_;
  const DragModel& model = flow.model;
  const Vec3 a = model.AccelerationAt(velocity_);
  accel_bound_ = RoundedUp(a.norm() + model.AccelerationRounding(velocity_, a));

  // Settled: the exact motion's distance from terminal velocity only shrinks, so once the
  // node is as close to it as the node's own uncertainty (or the tolerance), moving at
  // terminal velocity is as good as any further step, and its position bound stops growing
  // (deviation / mu) where further steps would add E_v per second.
  const double gap =
      RoundedUp((velocity_ - flow.terminal_velocity).norm() + flow.terminal_velocity_error);
  const double deviation = RoundedUp(gap + velocity_error_);
  if (gap <= std::max(flow.tolerance, velocity_error_)) {
    kind_ = Kind::kSettled;
    settled_deviation_ = deviation;
    end_ = kInfinity;
    return;
  }

  // Slow: the linear-drag closed form from the node neglects c2 |v| v, whose effect on the
  // velocity is at most c2 integral |v|^2 <= c2 h (S + A h)^2 (S >= |v(node)|, A >= |a|).
  // 0.4 min(tol / (c2 S^2), (tol / (c2 A^2))^(1/3)) keeps it below tol (2 (0.4) + 2 (0.4^3)).
  const double speed = RoundedUp(velocity_.norm() * (1.0 + 4.0 * kUnitRoundoff));
  const double tol_per_c2 = flow.tolerance / model.c2;
  // A square so small that the quotient would overflow (or the square underflow to 0) means
  // no limit: tested first, so no division traps (the tests run with floating-point traps).
  const auto limit = [tol_per_c2](double square) {
    return square > tol_per_c2 / std::numeric_limits<double>::max() ? tol_per_c2 / square
                                                                     : kInfinity;
  };
  const double by_speed = limit(speed * speed);
  const double by_accel = std::cbrt(limit(accel_bound_ * accel_bound_));
  const double slow_length = 0.4 * std::min(by_speed, by_accel);

  const DragTaylorPlan plan = PlanDragTaylorStep(model, velocity_, accel_bound_, flow.tolerance);
  if (plan.length > slow_length) {
    kind_ = Kind::kTaylor;
    series_ = DragTaylorSeriesAt(model, velocity_, plan);
    end_ = begin_ + plan.length;
    // The step actually taken is the rounded difference of its offsets.
    const double taken = end_ - begin_;
    SPARSEDYN_ASSERT(taken > 0.0 && taken <= kMaxShareAfterRounding * plan.rho,
                     "drag segment too long for the resolution of its offsets");
    series_.plan.length = std::max(plan.length, taken);
  } else {
    kind_ = Kind::kSlow;
    end_ = begin_ + slow_length;  // infinite when the node is at rest without gravity
    SPARSEDYN_ASSERT(end_ > begin_, "drag segment too long for the resolution of its offsets");
  }
}

void DragStepper::Advance() {
  SPARSEDYN_ASSERT(std::isfinite(end_), "DragStepper::Advance past the final step");
  const DragState node = Evaluate(end_);
  begin_ = end_;
  position_ = node.position;
  velocity_ = node.velocity;
  position_error_ = node.position_error;
  velocity_error_ = node.velocity_error;
  ++steps_;
  PrepareStep();
}

void DragStepper::AdvanceTo(double offset) {
  SPARSEDYN_ASSERT(offset >= begin_, "DragStepper::AdvanceTo goes forward only");
  while (offset > end_) Advance();
}

DragState DragStepper::Evaluate(double offset) const {
  SPARSEDYN_ASSERT(offset >= begin_ && offset <= end_, "DragStepper::Evaluate outside the step");
  const double sigma = offset - begin_;
  DragState state = EvaluateInStep(sigma);
  // The rounded sigma is within u sigma of offset - begin_; the exact solution from the node
  // moves by at most its speed (<= speed_bound + E_v) or acceleration bound times that.
  // The node's own errors: E_x plus E_v sigma (the two motions drift apart by at most E_v per
  // second), except on the settled step, whose bound holds the node's velocity error already.
  const double time_error = kUnitRoundoff * sigma;
  const bool settled = kind_ == Kind::kSettled;
  const double drift = settled ? 0.0 : velocity_error_ * sigma * (1.0 + kUnitRoundoff);
  state.position_error = RoundedUp(state.position_error + position_error_ + drift +
                                   (flow_->speed_bound + velocity_error_) * time_error);
  state.velocity_error = RoundedUp(state.velocity_error + (settled ? 0.0 : velocity_error_) +
                                   accel_bound_ * time_error);
  // a = f(v): |f(v_exact) - fl(f(v))| <= L |v_exact - v| + rounding.
  const DragModel& model = flow_->model;
  state.acceleration = model.AccelerationAt(state.velocity);
  state.acceleration_error = RoundedUp(
      model.Lipschitz(state.velocity.norm() + state.velocity_error) * state.velocity_error +
      model.AccelerationRounding(state.velocity, state.acceleration));
  return state;
}

// The exact solution from the node (position_, velocity_), sigma later, with the bounds of
// this step's own approximation (Evaluate adds the node's errors; the settled step's bound
// is against the exact motion itself, its deviation d holding the node's velocity error).
DragState DragStepper::EvaluateInStep(double sigma) const {
  const DragFlow& flow = *flow_;
  switch (kind_) {
    case Kind::kTaylor:
      return EvaluateDragTaylor(series_, position_, sigma);
    case Kind::kSlow: {
      DragState s = LinearDragStateAfter(position_, velocity_, flow.model.g, flow.model.c1, sigma);
      // The neglected quadratic drag (PrepareStep): c2 sigma (S + A sigma)^2 on the velocity,
      // its integral c2 sigma^2 (S + A sigma)^2 / 2 on the position.
      const double reach = velocity_.norm() * (1.0 + 4.0 * kUnitRoundoff) + accel_bound_ * sigma;
      const double drift = flow.model.c2 * sigma * reach * reach;
      s.velocity_error = RoundedUp(s.velocity_error + drift);
      s.position_error = RoundedUp(s.position_error + 0.5 * sigma * drift);
      return s;
    }
    case Kind::kSettled: {
      // |v - v_terminal| <= d e^(-mu sigma), so the position moves by v_terminal sigma within
      // d min(sigma, 1 / mu), plus v_terminal's own error times sigma and the rounding of
      // X + v_terminal sigma.
      DragState s;
      const Vec3& vt = flow.terminal_velocity;
      s.position = position_ + vt * sigma;
      s.velocity = vt;
      const double d = settled_deviation_;
      const double settle =
          flow.contraction > 0.0 ? std::min(sigma, 1.0 / flow.contraction) : sigma;
      s.position_error = RoundedUp(d * settle + flow.terminal_velocity_error * sigma +
                                   1.01 * kUnitRoundoff * (position_.norm() + vt.norm() * sigma));
      s.velocity_error = RoundedUp(d + flow.terminal_velocity_error);
      return s;
    }
  }
  return {};
}

}  // namespace sparsedyn
