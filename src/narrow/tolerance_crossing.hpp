// SPDX-License-Identifier: MIT
// Pinning a contact time to the first double at which the computed distance is within the
// tolerance: a root of the gap polynomial can leave the walk's distance a hair above it, and
// the World acts on a contact only where the walk agrees (distance <= tolerance).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "math/cap_counters.hpp"

namespace sparsedyn::narrow {

/// The smallest time in (apart, within] (to adjacent doubles) with distance(t) <= level, where
/// distance(apart) > level >= distance(within) and the distance crosses the level once in
/// between (a translating pair: convex distance).
template <class Distance>
double BisectFirstWithin(const Distance& distance, double apart, double within, double level) {
  // Halving in value reaches adjacent doubles in at most ~2100 steps (exponent range plus
  // mantissa); the cap only guards against a bug turning into a hang. `within` stays valid.
  constexpr int kMaxBisections = 4096;
  for (int step = 0; step < kMaxBisections; ++step) {
    const double mid = apart + 0.5 * (within - apart);
    if (mid <= apart || mid >= within) return within;
    (distance(mid) <= level ? within : apart) = mid;
  }
  caps::Count(caps::bisection);
  return within;
}

/// What StepIntoLevel found.
struct LevelCrossing {
  std::optional<double> time;  // the first time with distance <= level, if reached
  double apart = 0.0;          // otherwise: the last time seen above the level (>= t)
};

/// From t, where distance(t) = d_t is above the level by round-off (a root of the gap just
/// computed), steps forward by doubling steps (from one ulp of t) until the distance is within
/// the level, then bisects. Gives up when the distance starts rising (it only grazed the
/// level), at t_end, or after 200 doublings.
template <class Distance>
LevelCrossing StepIntoLevel(const Distance& distance, double t, double d_t, double level,
                            double t_end) {
  double lo = t, d_lo = d_t;
  double step = std::max(
      std::nextafter(std::abs(t), std::numeric_limits<double>::infinity()) - std::abs(t), 1e-18);
  constexpr int kMaxDoublings = 200;
  for (int k = 0; k < kMaxDoublings; ++k, step *= 2.0) {
    const double hi = std::min(t + step, t_end);
    if (hi <= lo) return {std::nullopt, lo};
    const double d_hi = distance(hi);
    if (d_hi <= level) return {BisectFirstWithin(distance, lo, hi, level), lo};
    if (d_hi > d_lo) return {std::nullopt, hi};
    lo = hi;
    d_lo = d_hi;
  }
  caps::Count(caps::level_crossing);
  return {std::nullopt, lo};
}

}  // namespace sparsedyn::narrow
