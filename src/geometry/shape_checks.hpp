// SPDX-License-Identifier: MIT
// Up-front refusals of point sets and vertex lists that no hull or polyhedron can be built from
// reliably, and the last check of a finished polyhedron (issue #39 part 1: degenerate point sets
// crashed Qhull in qh_normalize2 instead of being refused).
#pragma once

#include <Eigen/Core>
#include <span>
#include <string_view>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/result.hpp"

namespace sparsedyn {

/// Largest |coordinate| accepted: cubes of differences (volumes, 1e150) and the inertia's fifth
/// powers (1e250) stay far from overflow.
inline constexpr double kMaxCoordinate = 1e50;
/// Smallest bounding-box diagonal accepted: volumes (1e-150) and inertias (1e-250) stay far from
/// the subnormal range, where relative tolerances stop meaning anything.
inline constexpr double kMinScale = 1e-50;
/// Smallest bounding-box diagonal accepted relative to the largest |coordinate|: below it the
/// points differ only in their last few thousand ulps, so every plane through them is round-off.
inline constexpr double kMinRelativeScale = 1e-12;
/// Smallest thickness (relative to the bounding-box diagonal) that counts as volume, whatever
/// MeshValidation::tolerance says: thinner sets are flat within round-off.
inline constexpr double kMinRelativeThickness = 1e-12;

/// Every coordinate finite and at most kMaxCoordinate in magnitude. `noun` names an element in
/// the messages ("point 3 has ...", "vertex 3 has ...").
Status CheckCoordinates(std::span<const Eigen::Vector3d> points, std::string_view noun);

/// The points (checked by CheckCoordinates, at least one) are not all one point, span at least
/// kMinScale, and at least kMinRelativeScale times their largest |coordinate|. `nouns` names
/// them in the messages ("points", "vertices").
Status CheckExtent(std::span<const Eigen::Vector3d> points, std::string_view nouns);

/// The points (checked by CheckExtent) are neither collinear nor coplanar: some point lies
/// farther than max(relative_tolerance, kMinRelativeThickness) x scale from the line, then the
/// plane, through the points found farthest apart.
Status CheckHasVolume(std::span<const Eigen::Vector3d> points, double relative_tolerance);

/// All checks of a point set before it goes to Qhull: at least 4 points, then the above.
Status CheckHullInput(std::span<const Eigen::Vector3d> points, double relative_tolerance);

/// A finished polyhedron before it is handed out: closed (every half-edge has its twin, loops
/// link up, V - E + F = 2), convex (no vertex above a face plane by more than its tolerance x
/// scale) and of finite, positive volume with finite mass properties.
Status CheckFinishedPolyhedron(const ConvexPolyhedron& polyhedron);

}  // namespace sparsedyn
