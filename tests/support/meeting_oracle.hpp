// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "sparse/mover.hpp"

namespace sparsedyn::testing {

/// The slow twin of PredictMeeting: the gap function g(dt) = |dp(dt)|^2 - R(dt)^2 is sampled
/// densely in long double over [0, horizon]; a sign change is bisected, and every sampling
/// interval in which g' goes from - to + is searched for its minimum, so that a graze between
/// two samples is found too. Returns the earliest dt with g(dt) <= 0 (to ~1e-15 relative).
std::optional<long double> OracleMeeting(const Mover& a, const Mover& b, long double horizon,
                                         int samples = 2000);

/// g(dt) in long double (for checking that a predicted time is a real meeting).
long double OracleGap(const Mover& a, const Mover& b, long double dt);

}  // namespace sparsedyn::testing
