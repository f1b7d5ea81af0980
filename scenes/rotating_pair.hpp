// SPDX-License-Identifier: MIT
// The thesis's §7.3 feature-tracking experiment as a precomputed pose sequence: polyhedron A
// spins by a fixed angle per step next to a fixed polyhedron B. Every engine (ours and the
// peers in bench/peers/) is fed the same poses.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/result.hpp"

namespace sparsedyn::scenes {

/// Parameters of one case of the experiment.
struct RotatingPairOptions {
  int faces = 64;                 // exact face count of both A and B
  double degrees_per_step = 1.0;  // A's spin about its own centroid per step
  /// A's centroid orbits B's at this distance (bounding radii are 1, so the spheres are
  /// 2 * 1 apart at most and the polyhedra stay separated by at least distance - 2).
  double orbit_radius = 2.5;
  /// The orbit advances by degrees_per_step / orbit_slowdown per step: slow, so that the
  /// spin dominates the relative motion, yet the pair sees new feature pairs over the loop.
  double orbit_slowdown = 10.0;
  std::uint64_t seed = 20261122;  // polyhedra and axes; the same for every angle
};

/// A and B (recentred, scaled to bounding radius 1, from RandomConvexPolyhedron with different
/// seeds) and A's poses over one closed loop: after X_WA.size() steps both the spin and the
/// orbit have made whole turns, so cycling through the poses is a steady motion with no jump.
struct RotatingPair {
  RotatingPairOptions options;
  std::shared_ptr<const ConvexPolyhedron> a;
  std::shared_ptr<const ConvexPolyhedron> b;
  std::vector<Pose> X_WA;  // A's pose at step k (world frame)
  Pose X_WB;               // B stays at the origin, unrotated
};

/// Builds the case. The loop length is the smallest k with k * degrees_per_step a multiple of
/// 360 * orbit_slowdown (3600 steps at 1°, 720 at 5°, 144 at 25° with the defaults). Fails for a
/// face count RandomConvexPolyhedron refuses, an orbit radius that is not above 2, or an angle
/// whose loop would exceed 10^6 steps.
[[nodiscard]] Result<RotatingPair> MakeRotatingPair(const RotatingPairOptions& options);

}  // namespace sparsedyn::scenes
