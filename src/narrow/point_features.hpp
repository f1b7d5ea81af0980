// SPDX-License-Identifier: MIT
// The closest feature of a convex polyhedron to a point (the sphere-polyhedron pair kind of the
// detailed phase, issue #36): a walk over the polyhedron's Voronoi regions (Lin & Canny 1991
// with one side a point), made unable to cycle the way the pair walk is (V-Clip's potential).
#pragma once

#include <optional>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/pose.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// What FindClosestFeatureToPoint found.
struct PointClosest {
  /// The feature of the polyhedron whose zone holds the point (outside), or the face of least
  /// penetration (inside: the face whose plane the point is nearest behind).
  FeatureId feature;
  /// Signed distance from the point to the polyhedron (m): the Euclidean distance outside,
  /// minus the penetration depth (the distance to the surface) inside, 0 on the surface.
  double distance = 0.0;
  /// The closest point of the polyhedron's surface, world frame. Always
  /// query point = point + distance * normal (to round-off).
  Vec3 point = Vec3::Zero();
  /// Unit, world frame, from the polyhedron towards the point (outside); inside, the outward
  /// normal of `feature` (the direction of least penetration). On the surface (distance 0):
  /// the feature's outward normal (for an edge or vertex, the normalised sum of its faces').
  Vec3 normal = Vec3::UnitX();
  int steps = 0;             ///< accepted walk steps (escapes included)
  bool brute_force = false;  ///< the walk gave up (a repeated escape, a lower step refused
                             ///< by round-off, or max_steps): every face was searched instead;
                             ///< the answer is as exact either way
};

/// The closest feature of `polyhedron` placed at X_WA to the world point p_W. `start`
/// warm-starts the walk (the previous answer of a tracked pair); without it the walk starts
/// from the App. J.1.2 direction table (or vertex 0 when options.use_direction_table is false).
/// Every step either strictly lowers the distance from the point to the current feature or
/// keeps it (to round-off) and lowers the feature's dimension, so between two escapes no
/// feature repeats; an escape (the point over a face but behind its plane, by more than
/// round-off: within it the point is on the surface) jumps to the face whose plane the point
/// is farthest in front of, or reports the point inside when there is none; a second escape to the
/// same face, a lower step that round-off makes look longer than the allowance, or
/// options.max_steps steps, ends in a search of every face. So the walk always terminates, and the
/// answer does not depend on the start. Method and measured figures:
/// docs/narrow-phase.md#a-sphere-against-a-polyhedron.
PointClosest FindClosestFeatureToPoint(const TrackedPolyhedron& polyhedron, const Pose& X_WA,
                                       const Vec3& p_W,
                                       std::optional<FeatureId> start = std::nullopt,
                                       const ClosestFeaturesOptions& options = {});

}  // namespace sparsedyn
