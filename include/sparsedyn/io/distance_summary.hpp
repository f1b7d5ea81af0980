// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn {

/// "separated", "penetrating" or "iteration cap": how `sparsedyn distance` names a status.
const char* StatusName(ClosestFeatures::Status status);

/// A closest-feature answer as one JSON object, the one `sparsedyn distance --json` prints and
/// the Python package's `sparsedyn.distance` returns: distance (negative = penetration depth),
/// status, point_a, point_b, normal (world frame, from A to B), feature_a, feature_b (e.g.
/// "vertex 3"), steps.
std::string DistanceSummaryJson(const ClosestFeatures& result);

}  // namespace sparsedyn
