// SPDX-License-Identifier: MIT
// The detailed phase of a sphere and a convex polyhedron (issue #36): when does a sphere whose
// centre moves on a Path first come within the contact tolerance of a polyhedron on its rigid
// path, and where and along which normal do they touch. Exact for a polyhedron that does not
// rotate (zone events: in its frame the centre moves on a parabola), conservative advancement
// for one that does. A static polyhedron, or a static sphere, is the same call with a path
// that does not move.
#pragma once

#include <optional>

#include "motion/path.hpp"
#include "motion/rigid_path.hpp"
#include "narrow/point_features.hpp"
#include "narrow/time_of_contact.hpp"

namespace sparsedyn {

/// What PredictSphereContact found in [t_begin, t_end] (the conventions of ContactPrediction).
struct SphereContactPrediction {
  /// kContact: at `time` the walk (warm-started from closest.feature) reports a gap <= the
  /// tolerance, and `time` is never later than the first time the gap reaches the tolerance
  /// (a non-rotating polyhedron: it is that time, to round-off) or advancement_target x the
  /// tolerance (a rotating one). kNone: the gap stays above the tolerance until t_end (which
  /// may be infinity). kCheckpoint: the work cap was reached at `time` < t_end with the gap
  /// above the tolerance: predict again from there, warm-started from closest.feature.
  ContactPrediction::Kind kind = ContactPrediction::Kind::kNone;
  double time = 0.0;
  PointClosest closest;       ///< the polyhedron's closest feature to the centre at `time`
  double gap = 0.0;           ///< closest.distance - radius at `time` (negative: overlap)
  int iterations = 0;         ///< zone events or advancement steps taken
  int advancement_steps = 0;  ///< of which advancement steps by a non-rotating polyhedron
                              ///< whose zone test stalled (diagnostics)
};

/// The first time in [t_begin, t_end] at which the sphere of radius `radius` whose centre
/// follows `centre` comes within options.tolerance of the polyhedron on `path` (its frame
/// origin is the point the path moves). `warm` is the feature last seen for this pair.
/// The polyhedron not rotating (either may translate and accelerate): exact up to round-off,
/// by zone events. Rotating: conservative advancement, never later than the true time.
/// Within the tolerance (or overlapping) at t_begin: kContact at t_begin, 0 iterations.
/// Preconditions (asserted): t_begin finite and <= t_end; tolerance > 0; radius >= 0.
/// t_end may be infinity: searched up to narrow::kMaxHorizon, then kNone at infinity.
/// options.spin_radius_a is the polyhedron's narrow::SpinRadius if kept (< 0: computed);
/// spin_radius_b is not used. docs/narrow-phase.md#a-sphere-against-a-polyhedron.
SphereContactPrediction PredictSphereContact(const TrackedPolyhedron& polyhedron,
                                             const RigidPath& path, const Path& centre,
                                             double radius, double t_begin, double t_end,
                                             std::optional<FeatureId> warm,
                                             const ContactPredictionOptions& options);

}  // namespace sparsedyn
