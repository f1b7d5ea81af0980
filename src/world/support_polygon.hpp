// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The points of a contact region (a face on a wall or on a static's face) sorted around their
/// mean, seen along the unit normal n, so that they form the region's polygon.
void OrderAroundMean(std::vector<Vec3>& points, const Vec3& n);

/// Whether the centre of mass c lies strictly inside the polygon `points` (in the plane of
/// normal n, in order around their mean) seen along n: every edge turns the same way to it.
/// A body resting on that polygon is balanced (it does not tip) exactly then.
bool OverPolygon(const std::vector<Vec3>& points, const Vec3& c, const Vec3& n);

}  // namespace sparsedyn
