// SPDX-License-Identifier: MIT
#include "motion/drag_motion.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "motion/rounding_bounds.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {

namespace {

bool IsFinite(const Vec3& v) { return v.allFinite(); }

// The position bound of a segment's evaluations over offsets [start, offset], asked for in any
// order: the integrator's steps are walked once and their end bounds kept (a step's bound at
// its end bounds the whole step, and bounds never decrease from one step to the next,
// DragStepper::Evaluate).
class ErrorProfile {
 public:
  explicit ErrorProfile(const DragFlow& flow, const Vec3& p0, const Vec3& v0)
      : stepper_(flow, p0, v0) {}

  DragStepper& stepper() { return stepper_; }

  double PositionErrorUntil(double offset) {
    if (offset < stepper_.Begin()) {
      // The first kept step that ends at or after the offset.
      const auto it = std::lower_bound(
          ends_.begin(), ends_.end(), offset,
          [](const std::pair<double, double>& e, double o) { return e.first < o; });
      SPARSEDYN_ASSERT(it != ends_.end(), "drag error profile before its first step");
      return it->second;
    }
    while (offset > stepper_.End()) {
      ends_.emplace_back(stepper_.End(), stepper_.Evaluate(stepper_.End()).position_error);
      stepper_.Advance();
    }
    return stepper_.Evaluate(offset).position_error;
  }

 private:
  DragStepper stepper_;
  std::vector<std::pair<double, double>> ends_;  // (step end offset, position bound there)
};

}  // namespace

DragMotion::DragMotion(double t0, const Vec3& p0, const Vec3& v0, const Vec3& g, const Drag& drag)
    : t0_(t0), p0_(p0), v0_(v0), g_(g), drag_(drag) {
  SPARSEDYN_ASSERT(std::isfinite(t0) && IsFinite(p0) && IsFinite(v0) && IsFinite(g),
                   "DragMotion: t0, p0, v0 and g must be finite");
  SPARSEDYN_ASSERT(std::isfinite(drag.linear) && drag.linear >= 0.0 &&
                       std::isfinite(drag.quadratic) && drag.quadratic >= 0.0,
                   "DragMotion: drag coefficients must be finite and >= 0");
  const DragModel model{g, drag.linear, drag.quadratic};
  const Vec3 a0 = model.AccelerationAt(v0);
  accel_bound_ = RoundedUp(a0.norm() + model.AccelerationRounding(v0, a0));
  if (!IsClosedForm()) {
    flow_ = DragFlow::Make(model, v0);
    speed_bound_ = flow_.speed_bound;
  } else if (drag.linear > 0.0) {
    // v -> g / c1 monotonically in each component's deviation: |v| <= max(|v0|, |g| / c1).
    speed_bound_ =
        RoundedUp(std::max(v0.norm(), g.norm() / drag.linear) * (1.0 + 4.0 * kUnitRoundoff));
  } else {
    speed_bound_ = g == Vec3::Zero() ? RoundedUp(v0.norm()) : kInfinity;
  }
}

DragState DragMotion::ClosedFormStateAt(double dt) const {
  return LinearDragStateAfter(p0_, v0_, g_, drag_.linear, dt);
}

// dt = fl(t - t0) is within u dt of the exact offset; the exact motion moves by at most its
// speed, acceleration and jerk bounds times that: |v| <= min(speed bound, |v0| + |a0| dt),
// |a| <= |a0| (|a| never grows under drag: a' = Df(v) a with Df symmetric and negative
// semi-definite), |a'| <= (c1 + 2 c2 |v|) |a0|.
DragState DragMotion::AddTimeRounding(DragState state, double dt) const {
  const double time_error = kUnitRoundoff * dt;
  const double speed = std::min(speed_bound_, v0_.norm() + accel_bound_ * dt);
  const double jerk = (drag_.linear + 2.0 * drag_.quadratic * speed) * accel_bound_;
  state.position_error = RoundedUp(state.position_error + speed * time_error);
  state.velocity_error = RoundedUp(state.velocity_error + accel_bound_ * time_error);
  state.acceleration_error = RoundedUp(state.acceleration_error + jerk * time_error);
  return state;
}

DragState DragMotion::StateAt(double t) const {
  SPARSEDYN_ASSERT(std::isfinite(t) && t >= t0_, "DragMotion::StateAt needs a finite t >= t0");
  const double dt = t - t0_;
  if (IsClosedForm()) return AddTimeRounding(ClosedFormStateAt(dt), dt);
  DragStepper stepper(flow_, p0_, v0_);
  stepper.AdvanceTo(dt);
  return AddTimeRounding(stepper.Evaluate(dt), dt);
}

// The envelope of the quadratic path about t (docs/dynamics.md, "Drag"). With A >= |a(t)| and
// S >= |v(t)|, for tau in [0, H]: |a(t + tau)| <= A (never grows), |v(t + tau)| <= V_H =
// min(speed bound, S + A H), and the jerk x''' = a' = Df(v) a has |x'''| <= J = (c1 + 2 c2 V_H) A.
// Taylor's theorem with the integral remainder bounds the exact motion's distance from its own
// quadratic by J tau^3 / 6 <= (J H / 3) tau^2 / 2, and also by 2 A tau^2 / 2 (|a(s) - a(t)| <=
// 2A). The path uses the computed state, off by (ex, ev, ea) from the exact one, and a reported
// position is off the exact one by at most its evaluation bound, <= E_max over the horizon:
//   e0 = ex + E_max,  e1 = ev,  e2 = ea + min(J H / 3, 2 A).
namespace {

struct EnvelopeModel {
  DragState state;
  double c1, c2, speed_bound, accel;

  double Curvature(double horizon) const {
    const double speed =
        std::min(speed_bound, state.velocity.norm() + state.velocity_error + accel * horizon);
    const double jerk = (c1 + 2.0 * c2 * speed) * accel;
    return RoundedUp(state.acceleration_error + std::min(jerk * horizon / 3.0, 2.0 * accel));
  }
  Envelope At(double horizon, double eval_error) const {
    return Envelope{RoundedUp(state.position_error + eval_error), state.velocity_error,
                    Curvature(horizon)};
  }
  // The envelope's value at the end of the horizon (its largest over [0, H]).
  double Reach(double horizon, double eval_error) const {
    return RoundedUp(At(horizon, eval_error).At(horizon));
  }
};

}  // namespace

struct DragMotion::Horizon {
  double horizon;
  TaylorSegment segment;
};

DragMotion::Horizon DragMotion::FindHorizon(double t, double max_error, double max_horizon) const {
  SPARSEDYN_ASSERT(max_error > 0.0 && max_horizon >= 0.0, "drag horizon: bad max_error");
  SPARSEDYN_ASSERT(std::isfinite(t) && t >= t0_, "drag horizon: t must be finite and >= t0");
  const double dt = t - t0_;
  std::optional<ErrorProfile> profile;
  DragState state;
  if (IsClosedForm()) {
    state = AddTimeRounding(ClosedFormStateAt(dt), dt);
  } else {
    profile.emplace(flow_, p0_, v0_);
    profile->stepper().AdvanceTo(dt);
    state = AddTimeRounding(profile->stepper().Evaluate(dt), dt);
  }
  const double accel = RoundedUp(state.acceleration.norm() + state.acceleration_error);
  const EnvelopeModel model{state, drag_.linear, drag_.quadratic, speed_bound_, accel};
  // E_max over [t, t + H]: the bound at the end (bounds never decrease with time).
  auto eval_error = [&](double horizon) {
    const double end = dt + horizon;
    if (!std::isfinite(end)) return kInfinity;
    if (IsClosedForm()) return AddTimeRounding(ClosedFormStateAt(end), end).position_error;
    const double inner = profile->PositionErrorUntil(end);
    return AddTimeRounding(DragState{.position_error = inner}, end).position_error;
  };
  auto fits = [&](double horizon) {
    return model.Reach(horizon, eval_error(horizon)) <= max_error;
  };
  auto segment = [&](double horizon, double error) {
    const Path path{state.position, state.velocity, state.acceleration, t};
    return Horizon{horizon, TaylorSegment{path, model.At(horizon, error), horizon}};
  };

  if (!fits(0.0)) return segment(0.0, eval_error(0.0));
  // At rest without gravity the body never moves, whatever its drag: every reported position
  // is p0 and its bound the same, so no check is ever needed.
  if (v0_ == Vec3::Zero() && g_ == Vec3::Zero()) {
    const Path path{state.position, Vec3::Zero(), Vec3::Zero(), t};
    const Envelope still{RoundedUp(state.position_error + eval_error(0.0)), 0.0, 0.0};
    return Horizon{kInfinity, TaylorSegment{path, still, kInfinity}};
  }
  // An upper bracket from the model alone (E_max >= 0 only adds): the shortest horizon the
  // model already rejects, to 1e-6, so that the integrator walks no further than needed.
  auto model_fits = [&](double horizon) { return model.Reach(horizon, 0.0) <= max_error; };
  double hi = std::min(1.0, max_horizon);
  double lo = 0.0;
  if (model_fits(hi)) {
    while (hi < max_horizon && model_fits(hi)) {
      lo = hi;
      hi = std::min(2.0 * hi, max_horizon);
    }
  } else {
    while (!model_fits(0.5 * hi) && hi > 1e-300) hi *= 0.5;
    lo = 0.5 * hi;
  }
  if (!std::isfinite(hi)) {
    // The model never leaves its path: a = 0 and v, a known exactly, so v = 0 too (a known
    // non-zero velocity has a velocity bound > 0, which grows the envelope).
    SPARSEDYN_ASSERT(state.velocity == Vec3::Zero(), "drag horizon: unbounded while moving");
    return segment(kInfinity, eval_error(0.0));
  }
  if (!model_fits(hi)) {
    while (hi - lo > 1e-6 * hi) {
      const double mid = 0.5 * (lo + hi);
      (model_fits(mid) ? lo : hi) = mid;
    }
  }
  if (fits(hi)) return segment(hi, eval_error(hi));  // hi == max_horizon
  // Bisection: the envelope's reach grows with the horizon, so [lo fits, hi does not].
  lo = 0.0;
  while (hi - lo > 1e-4 * hi) {
    const double mid = 0.5 * (lo + hi);
    (fits(mid) ? lo : hi) = mid;
  }
  return segment(lo, eval_error(lo));
}

double DragMotion::HorizonFor(double t, double max_error, double max_horizon) const {
  return FindHorizon(t, max_error, max_horizon).horizon;
}

TaylorSegment DragMotion::SegmentFor(double t, double max_error, double max_horizon) const {
  return FindHorizon(t, max_error, max_horizon).segment;
}

TaylorSegment DragMotion::SegmentAt(double t, double horizon) const {
  SPARSEDYN_ASSERT(std::isfinite(horizon) && horizon >= 0.0, "drag segment: bad horizon");
  SPARSEDYN_ASSERT(std::isfinite(t) && t >= t0_, "drag segment: t must be finite and >= t0");
  const DragState state = StateAt(t);
  const double accel = RoundedUp(state.acceleration.norm() + state.acceleration_error);
  const EnvelopeModel model{state, drag_.linear, drag_.quadratic, speed_bound_, accel};
  const double eval_error = PositionErrorAt(t + horizon);
  const Path path{state.position, state.velocity, state.acceleration, t};
  return TaylorSegment{path, model.At(horizon, eval_error), horizon};
}

Vec3 DragMotion::TerminalVelocity() const {
  if (g_ == Vec3::Zero()) return Vec3::Zero();
  SPARSEDYN_ASSERT(!drag_.IsZero(), "DragMotion::TerminalVelocity without drag");
  if (IsClosedForm()) return g_ / drag_.linear;
  return flow_.terminal_velocity;
}

}  // namespace sparsedyn
