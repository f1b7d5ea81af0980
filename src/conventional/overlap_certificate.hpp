// SPDX-License-Identifier: MIT
#pragma once

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/pose.hpp"

namespace sparsedyn {

/// True when A at X_WA and B at X_WB certainly overlap: a GJK search (Gilbert, Johnson & Keerthi
/// 1988, boolean form) found a tetrahedron of vertex differences a_i - b_j that strictly
/// encloses the origin. False means "not shown" (separated, touching, or a degenerate search):
/// ask the closest-feature query then. Costs a few support-vertex scans, far less than a
/// penetration depth, which is why the conventional method's bisection asks this first.
bool CertainlyOverlap(const ConvexPolyhedron& a, const Pose& X_WA, const ConvexPolyhedron& b,
                      const Pose& X_WB);

}  // namespace sparsedyn
