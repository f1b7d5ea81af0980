// SPDX-License-Identifier: MIT
#pragma once
// Finite but absurd values refused before a run (issue #39 part 4, docs/reliability.md): a
// value that passes std::isfinite can still overflow the meeting quadratics (a velocity of
// 1e300 squared), vanish below the resolution of its own coordinates (a radius of 1e-300 at
// x = 5) or make the clock too coarse for the motion (one ulp of t longer than the time a body
// takes to move by its radius), and the event loop would then stall or divide by zero later.
#include <optional>
#include <string>

#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// The largest magnitude of any length, speed, acceleration, mass or tolerance the World takes:
/// products of two stay below 1e200 and sums of a few of them far from overflow.
inline constexpr double kMaxMagnitude = 1e100;
/// The smallest radius and mass: their inverses and squares stay normal doubles.
inline constexpr double kMinMagnitude = 1e-100;
/// A body's radius must be at least this fraction of its largest coordinate (2^-40: the sphere
/// spans 2^12 ulps of its own position), or gaps and contact tolerances are below round-off.
inline constexpr double kMinRadiusPerCoordinate = 0x1p-40;
/// One ulp of the clock must be at most this fraction of the time any body takes to move by
/// its own radius (2^-20), or consecutive events could not be told apart in time.
inline constexpr double kMaxClockUlpPerCrossing = 0x1p-20;

/// The magnitudes of `def` against the limits above (finite values are CheckDefinition's);
/// the Error names the body ("body 3: ") and the field.
std::optional<Error> CheckHostileValues(const BodyDef& def, const WorldSettings& settings,
                                        std::size_t index);

}  // namespace sparsedyn
