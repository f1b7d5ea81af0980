// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include <utility>

#include "scenes/random.hpp"
#include "sparse/mover.hpp"

namespace sparsedyn::testing {

/// The slow twin of PredictMeeting: the gap function g(dt) = |dp(dt)|^2 - R(dt)^2 is sampled
/// densely in long double over [0, horizon]; a sign change is bisected, and every sampling
/// interval in which g' goes from - to + is searched for its minimum, so that a graze between
/// two samples is found too. Returns the earliest dt with g(dt) <= 0 (to ~1e-15 relative).
std::optional<long double> OracleMeeting(const Mover& a, const Mover& b, long double horizon,
                                         int samples = 2000);

/// A random pair of movers for the oracle checks: positions in [-5, 5]^3, speeds up to ~2,
/// radii in [0.1, 1), b aimed roughly at a (most pairs meet, some graze, some miss); with
/// `accelerated`, accelerations up to 1 per axis; with `envelope`, a linear envelope on a and a
/// quadratic one on b. The pair may start overlapping: callers skip those.
std::pair<Mover, Mover> RandomMoverPair(scenes::Random& random, bool accelerated, bool envelope);

/// g(dt) in long double (for checking that a predicted time is a real meeting).
long double OracleGap(const Mover& a, const Mover& b, long double dt);

}  // namespace sparsedyn::testing
