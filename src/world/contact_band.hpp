// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

// Zone events or advancement steps per contact prediction before it is resumed by a checkpoint
// event: bounds the work of one event, and a prediction interrupted by a path change is not
// wasted beyond this.
inline constexpr int kIterationsPerPrediction = 64;

// The time after `now` at which a pair (or a body and a wall) that touches within `tolerance`
// without approaching is looked at again: the band cannot be closed before, since the gap
// changes at most by max_speed (plus the relative acceleration's share) per second. This is what
// keeps a pair that has just bounced from colliding again at once, without missing a contact.
inline double BandExit(double now, double tolerance, double max_speed, double max_acceleration) {
  double dt = kInfinity;
  if (max_speed > 0) dt = 0.5 * tolerance / max_speed;
  if (max_acceleration > 0) dt = std::min(dt, std::sqrt(tolerance / max_acceleration));
  if (dt == kInfinity) return kInfinity;
  return std::max(now + dt, std::nextafter(now, kInfinity));
}

// How fast a rigid body's gap to a fixed plane (outward unit normal n) can close: its centre
// moves at v with acceleration a and it turns at omega, no point further than spin_radius from
// the centre. The gap's rate is n.v + omega.(r x n): the spin about n slides points within
// planes parallel to the wall and moves no gap, so a body sliding along a wall, or spinning on
// it, waits for as long as its motion across the wall allows (a bound on the full speed made a
// polyhedron gliding along a wall look again every few nanoseconds: a fuzzed scene).
struct GapClosing {
  double speed = 0.0;         // m/s, for BandExit's max_speed
  double acceleration = 0.0;  // m/s^2, for BandExit's max_acceleration
};

inline GapClosing PlaneGapClosing(const Vec3& n, const Vec3& v, const Vec3& a, const Vec3& omega,
                                  double spin_radius) {
  const double along = std::abs(omega.dot(n));
  const double across = (omega - omega.dot(n) * n).norm();
  // d/dt of omega.(r x n) is omega.((omega x r) x n) = along (across . r) - (n . r) across^2.
  return GapClosing{std::max(-n.dot(v), 0.0) + across * spin_radius,
                    std::max(-n.dot(a), 0.0) + across * (along + across) * spin_radius};
}

// `wait_until` (a BandExit) capped for a body pressed back towards the contact at
// `pressing` (> 0, m/s^2) that leaves it at `separating` (m/s): it comes back to where it is
// after 2 separating / pressing, and must not land while the contact waits (a micro-bounce
// under gravity would sink into the wall or table). A rebound too slow to matter (back within
// a thousandth of the wait: a body resting on an edge or a vertex, which no wall holds yet)
// keeps the wait, so that the clock moves on (and the progress check reports the crawl).
inline double FallBackCap(double now, double wait_until, double separating, double pressing) {
  if (!(pressing > 0) || !(separating > 0)) return wait_until;
  const double back = 2.0 * separating / pressing;
  if (back < 1e-3 * (wait_until - now)) return wait_until;
  return std::min(wait_until, now + back);
}

}  // namespace sparsedyn
