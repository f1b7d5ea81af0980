// SPDX-License-Identifier: MIT
// One step of conservative advancement: how long two bodies (or a body and a wall) separated by
// a gap along a fixed direction stay apart, given a bound on how fast the gap can close.
#pragma once

#include <optional>

#include "math/polynomial.hpp"
#include "math/roots.hpp"

namespace sparsedyn::narrow {

/// The first dt in [0, horizon] at which a gap closing at most at speed + accel * dt (so by at
/// most speed dt + accel dt^2 / 2 in total) may have closed by `closable` (> 0). Before that
/// time the gap certainly has not. std::nullopt when it cannot close within the horizon (e.g.
/// speed <= 0 and accel <= 0). Conservative: EarliestRoot is never later than the true root.
inline std::optional<double> AdvancementStep(double closable, double speed, double accel,
                                             double horizon) {
  if (speed <= 0.0 && accel <= 0.0) return std::nullopt;
  return EarliestRoot(Polynomial{-closable, speed, 0.5 * accel}, 0.0, horizon);
}

}  // namespace sparsedyn::narrow
