// SPDX-License-Identifier: MIT
// Zone events of a translating pair (thesis §5.2, App. K): while a feature pair stays closest,
// its witness points move polynomially in time, so the time the pair's distance reaches the
// tolerance and the time a witness leaves the other feature's zone are roots of polynomials.
#pragma once

#include <Eigen/Core>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn::narrow {

/// B's motion relative to A in A's (fixed) frame, dt after the current time:
/// p_AB(dt) = p + v dt + a dt^2 / 2, and B's points x_B map to R_AB x_B + p_AB(dt).
struct RelativeTranslation {
  Eigen::Matrix3d R_AB = Eigen::Matrix3d::Identity();
  Vec3 p = Vec3::Zero();
  Vec3 v = Vec3::Zero();
  Vec3 a = Vec3::Zero();
};

/// What the current feature pair predicts.
struct ZoneEvent {
  enum class Kind : std::uint8_t {
    kContact,      // the pair's distance reaches the tolerance at dt, before any zone exit
    kExit,         // a witness leaves a zone at dt; `next` is the pair across that zone plane
    kNone,         // neither happens within the horizon
    kUnsupported,  // the pair is degenerate (parallel features left after reduction, or a
                   // witness already outside a zone): the caller advances conservatively
  };
  Kind kind = Kind::kUnsupported;
  double dt = 0.0;
  FeaturePair next;
  bool stalled = false;  // kUnsupported because a witness is already over a zone plane by more
                         // than the slack; `next` is the pair across that plane
};

/// The next zone event of the closest pair `pair` (as FindClosestFeatures reported it, with its
/// witnesses point_a_A, point_b_A in A's frame) within [0, horizon]. `slack` (length) is how far
/// a witness may stray over a zone plane before it counts as an exit: it keeps a witness that
/// sits on a plane (just after an exit, or parallel features) from stalling the prediction.
ZoneEvent NextZoneEvent(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                        const RelativeTranslation& motion, FeaturePair pair, const Vec3& point_a_A,
                        const Vec3& point_b_A, double tolerance, double horizon, double slack);

}  // namespace sparsedyn::narrow
