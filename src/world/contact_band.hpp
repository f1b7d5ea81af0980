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

}  // namespace sparsedyn
