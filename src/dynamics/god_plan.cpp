// SPDX-License-Identifier: MIT
#include "dynamics/god_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "dynamics/god_move.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {

namespace {

// Per coefficient: Eigen's allFinite() subtracts inf from itself, which traps under the tests'
// floating-point exceptions.
bool IsFinite(const Vec3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

std::string Number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.17g", value);
  return buffer;
}

// The velocity chosen for target i without one: a Catmull-Rom sweep, the chord from the
// waypoint before it to the one after it over their time apart (the start of the plan counts
// as the waypoint before the first, if it is earlier); at the last target, rest.
Vec3 SweepVelocity(std::span<const GodTarget> track, std::size_t i, double t, const Vec3& p) {
  if (i + 1 == track.size()) return Vec3::Zero();
  const GodTarget& next = track[i + 1];
  if (i > 0) {
    const GodTarget& prev = track[i - 1];
    return (next.position - prev.position) / (next.time - prev.time);
  }
  if (t < track[0].time) return (next.position - p) / (next.time - t);
  return (next.position - track[0].position) / (next.time - track[0].time);
}

}  // namespace

GodPlan::GodPlan(double t, const Vec3& p, const Vec3& v, std::span<const GodTarget> track,
                 double max_acceleration)
    : max_acceleration_(max_acceleration) {
  SPARSEDYN_ASSERT(ValidateGodTrack(track, max_acceleration).ok(),
                   "GodPlan: bad track or max_acceleration (ValidateGodTrack)");
  SPARSEDYN_ASSERT(std::isfinite(t) && IsFinite(p) && IsFinite(v),
                   "GodPlan: start time and state must be finite");
  // The open piece: where the object is now; each move closes it and opens the next.
  pieces_.push_back(GodPiece{t, kInfinity, p, v, Vec3::Zero()});
  for (std::size_t i = 0; i < track.size(); ++i) {
    const GodTarget& target = track[i];
    AddMove(target, target.velocity ? *target.velocity : SweepVelocity(track, i, t, p));
  }
  // The final piece keeps the last velocity (zero unless one was given) for ever.
  pieces_.back().a = Vec3::Zero();
  pieces_.back().t1 = kInfinity;
}

// One target from the open piece's start: the requested duration if a one-switch move with
// |a| <= A makes it, otherwise the earliest that does (god_move.hpp).
void GodPlan::AddMove(const GodTarget& target, const Vec3& velocity) {
  const GodPiece& from = pieces_.back();
  const double start = from.t0;
  const GodMoveEnds ends{target.position - from.p0, from.v0, velocity};
  const double requested = target.time - start;
  const double duration = EarliestGodMoveDuration(ends, max_acceleration_, requested);
  const double arrival = duration == requested ? target.time : start + duration;
  arrivals_.push_back(arrival);
  if (duration <= 0.0) return;  // already there, at rest, as asked
  const GodMove move = MakeGodMove(ends, duration);
  if (move.switch_fraction < 1.0) {
    AddPiece(start + move.switch_fraction * duration, move.first);
    AddPiece(arrival, move.second);
  } else {
    AddPiece(arrival, move.first);
  }
  // The move ends at its target exactly, not at the round-off of its pieces (a move to rest
  // holds at zero velocity, not at 1e-16 m/s drifting away).
  pieces_.back().p0 = target.position;
  pieces_.back().v0 = velocity;
}

// Closes the open piece at t1 with acceleration a and opens the next where it ends. A piece
// that rounding leaves without time (t1 <= t0) is dropped: its effect is below A ulp(t).
void GodPlan::AddPiece(double t1, const Vec3& a) {
  GodPiece& open = pieces_.back();
  if (!(t1 > open.t0)) return;
  open.t1 = t1;
  open.a = a;
  const GodPiece next{t1, kInfinity, open.PositionAt(t1), open.VelocityAt(t1), Vec3::Zero()};
  pieces_.push_back(next);
}

const GodPiece& GodPlan::PieceAt(double t) const {
  SPARSEDYN_ASSERT(t >= pieces_.front().t0, "GodPlan::PieceAt before the plan starts");
  const auto after = std::upper_bound(pieces_.begin(), pieces_.end(), t,
                                      [](double x, const GodPiece& p) { return x < p.t0; });
  return *(after - 1);
}

GodState GodPlan::StateAt(double t) const {
  const GodPiece& piece = PieceAt(t);
  return GodState{piece.PositionAt(t), piece.VelocityAt(t), piece.a};
}

double GodPlan::NextSwitchAfter(double t) const {
  if (t < pieces_.front().t0) return pieces_.front().t0;
  return PieceAt(t).t1;
}

Status ValidateGodTrack(std::span<const GodTarget> track, double max_acceleration) {
  if (!(std::isfinite(max_acceleration) && max_acceleration > 0.0)) {
    return Error{"max_acceleration must be finite and > 0, got " + Number(max_acceleration)};
  }
  for (std::size_t i = 0; i < track.size(); ++i) {
    const GodTarget& target = track[i];
    const std::string name = "track[" + std::to_string(i) + "]";
    if (!std::isfinite(target.time)) return Error{name + ".time must be finite"};
    if (!IsFinite(target.position)) return Error{name + ".position must be finite"};
    if (target.velocity && !IsFinite(*target.velocity)) {
      return Error{name + ".velocity must be finite"};
    }
    if (i > 0 && !(target.time > track[i - 1].time)) {
      return Error{name + ".time must be after track[" + std::to_string(i - 1) + "].time (" +
                   Number(target.time) + " <= " + Number(track[i - 1].time) + ")"};
    }
  }
  return Status::Ok();
}

}  // namespace sparsedyn
