// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "motion/path.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// One constant-acceleration piece of a plan, for t in [t0, t1) (t1 may be infinite).
struct GodPiece {
  double t0 = 0.0;
  double t1 = 0.0;
  Vec3 p0 = Vec3::Zero();
  Vec3 v0 = Vec3::Zero();
  Vec3 a = Vec3::Zero();

  Vec3 PositionAt(double t) const { return ToPath().PositionAt(t); }
  Vec3 VelocityAt(double t) const { return ToPath().VelocityAt(t); }
  /// The piece as the sparse phase's Path: exact, so a god object needs no envelope while
  /// it follows its plan.
  Path ToPath() const { return Path{p0, v0, a, t0}; }
};

/// A god object's position, velocity and acceleration at one time.
struct GodState {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
};

/// The motion of a god object (App. H.3, issue #36 part 7): driven from outside with
/// |acceleration| <= A, it follows a track of targets in order. Each target is reached by a
/// move of at most two constant-acceleration pieces (one switch, god_move.hpp): at the
/// target's time when a move with |a| <= A can do it (the gentlest such move: the least
/// largest |a|), otherwise at the earliest time one can, lagging behind (the thesis's
/// "floating hand"); the next target is then planned from there. A target without velocity
/// gets V_i = (P_(i+1) - P_(i-1)) / (T_(i+1) - T_(i-1)) (a Catmull-Rom sweep through the
/// waypoints, with the object's start as P_(-1)); the last one without velocity gets 0.
/// After the last target the object keeps that target's velocity: it holds still at it when
/// none was given, or coasts on at the given velocity. Position and velocity are continuous
/// (each piece starts where the last one ends); every piece is an exact Path.
class GodPlan {
 public:
  /// The plan from position p and velocity v at time t through `track` (times strictly
  /// increasing, all values finite) with max_acceleration A > 0 (asserted; ValidateGodTrack
  /// checks user input).
  GodPlan(double t, const Vec3& p, const Vec3& v, std::span<const GodTarget> track,
          double max_acceleration);

  double max_acceleration() const { return max_acceleration_; }
  double start_time() const { return pieces_.front().t0; }
  /// The pieces in time order; the last one is infinite (the hold or the coast).
  const std::vector<GodPiece>& pieces() const { return pieces_; }
  /// When each target was reached: its time, or later when the plan lags.
  const std::vector<double>& arrival_times() const { return arrivals_; }
  /// When the last target is reached (the start of the final piece).
  double EndTime() const { return pieces_.back().t0; }

  /// The piece that holds t >= start_time(): the last one with t0 <= t.
  const GodPiece& PieceAt(double t) const;
  GodState StateAt(double t) const;
  /// The first piece boundary after t (an event for the World: the path changes there), or
  /// infinity after the last one.
  double NextSwitchAfter(double t) const;

 private:
  void AddMove(const GodTarget& target, const Vec3& velocity);
  void AddPiece(double t1, const Vec3& a);

  double max_acceleration_;
  std::vector<GodPiece> pieces_;  // pieces_.back() is open-ended while planning
  std::vector<double> arrivals_;
};

/// Checks a god object's definition as user input: max_acceleration finite and > 0, every
/// time, position and velocity finite, times strictly increasing. The Error names the field
/// ("max_acceleration", "track[3].time", ...); the caller adds the body.
Status ValidateGodTrack(std::span<const GodTarget> track, double max_acceleration);

/// The envelope of a god object whose control is not known ahead (a hand moved live): about
/// the path with its current position and velocity and no acceleration it strays at most
/// A dt^2 / 2, so Envelope{0, 0, A} bounds where it can be (App. H.3).
inline Envelope GodReachEnvelope(double max_acceleration) {
  return Envelope{0.0, 0.0, max_acceleration};
}

}  // namespace sparsedyn
