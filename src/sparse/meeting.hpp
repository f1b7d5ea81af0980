// SPDX-License-Identifier: MIT
#pragma once

#include "sparse/mover.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// Default prediction horizon (seconds after `now`): far beyond any run, finite for root finders.
inline constexpr double kPredictionHorizon = 1e30;

/// Earliest dt >= 0 at which the spheres of `a` and `b` (b displaced by `shift_b`, the periodic
/// image offset) touch: |dp(dt)| = Ra(dt) + Rb(dt) (App. F.1, F.3). kInfinity when they never
/// meet within `horizon`. Conservative: never later than the exact meeting of these paths.
/// Finite precision (Bannerman et al. 2014): spheres already touching or overlapping by round-off
/// meet now if approaching and are ignored while separating (the next real approach counts).
double PredictMeeting(const Mover& a, const Mover& b, const Vec3& shift_b,
                      double horizon = kPredictionHorizon);

/// Earliest dt >= 0 at which the sphere of `a` reaches the plane n.x = d from the side n.x > d
/// (n is the unit normal pointing into the allowed half-space), i.e. n.p(dt) - d = R(dt) while
/// approaching. Same conventions as PredictMeeting.
double PredictWallMeeting(const Mover& a, const Vec3& n, double d,
                          double horizon = kPredictionHorizon);

/// Earliest dt >= 0 at which the spheres of `a` and `b`, now overlapping, stop overlapping
/// (the end of an engagement, §3.3). kInfinity if they stay engaged within `horizon`.
/// Never earlier than the exact separation (an engagement must not end too soon).
double PredictSeparation(const Mover& a, const Mover& b, const Vec3& shift_b,
                         double horizon = kPredictionHorizon);

}  // namespace sparsedyn
