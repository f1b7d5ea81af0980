// SPDX-License-Identifier: MIT
// The detailed phase's predictions (thesis §5.2, App. K): when does an engaged pair of convex
// polyhedra, each on its rigid path, first come within the contact tolerance? Exact for
// translating pairs (zone events: the closest feature pair changes at roots of polynomials in
// t); a guaranteed lower bound for rotating ones (conservative advancement).
#pragma once

#include <optional>

#include "motion/rigid_path.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn {

/// What a prediction found in [t_begin, t_end].
struct ContactPrediction {
  enum class Kind : std::uint8_t {
    kContact,     // at `time` the walk (warm-started from `features`) reports a distance
                  // <= tolerance, and `time` is never later than the first time the distance
                  // reaches the tolerance (translating pairs: it is that time, to round-off) or
                  // advancement_target x tolerance (rotating pairs)
    kNone,        // the distance stays > tolerance until t_end (which may be infinity)
    kCheckpoint,  // the work cap was reached at `time` < t_end with distance > tolerance:
                  // predict again from there (a detail event that only resumes the prediction)
  };
  Kind kind = Kind::kNone;
  double time = 0.0;
  ClosestFeatures features;   // the closest features at `time` (at t_end for kNone)
  int iterations = 0;         // zone events or advancement steps taken
  int advancement_steps = 0;  // of which conservative-advancement steps taken by a translating
                              // pair whose features were degenerate (diagnostics)
};

/// Rotating bodies advance until the gap may have closed to this fraction of the tolerance
/// (pairs and walls alike): below 1 so that a prediction ends in finitely many steps, near 1 so
/// that the last steps before contact stay long.
inline constexpr double kAdvancementTarget = 0.9;

struct ContactPredictionOptions {
  double tolerance = 0.0;   // contact when the distance <= tolerance (m, > 0)
  int max_iterations = 64;  // per call; beyond it kCheckpoint
  // Rotating pairs: each advancement step stops where the gap may first have closed to
  // advancement_target * tolerance (in (0, 1)), so the prediction reaches a gap <= tolerance
  // in finitely many steps and is never later than the first time the gap is that small.
  double advancement_target = kAdvancementTarget;
  // narrow::SpinRadius of each path when the caller keeps it (it is O(vertices) and constant
  // along a path); < 0: computed here.
  double spin_radius_a = -1.0;
  double spin_radius_b = -1.0;
  ClosestFeaturesOptions walk;
};

/// The first time in [t_begin, t_end] at which A on `path_a` and B on `path_b` come within
/// options.tolerance. `warm` is the feature pair last seen for this pair (coherence).
/// Translating pairs (neither rotates; accelerations may differ): exact up to round-off, by
/// zone events. Otherwise: conservative advancement, never later than the true time.
/// Within the tolerance (or penetrating) at t_begin: kContact at t_begin, 0 iterations.
/// Preconditions (asserted): t_begin finite and <= t_end; tolerance > 0. t_end may be infinity
/// (e.g. element spheres that never separate): it is searched up to 1e30 s ahead, and kNone then
/// carries time = infinity and the features of the last time evaluated. The polyhedra's frame
/// origins are the points their paths move (the centres of mass when Recentered()).
/// Method, guarantees and measured iteration counts: docs/narrow-phase.md#predicting-contact.
ContactPrediction PredictContact(const TrackedPolyhedron& a, const RigidPath& path_a,
                                 const TrackedPolyhedron& b, const RigidPath& path_b,
                                 double t_begin, double t_end, std::optional<FeaturePair> warm,
                                 const ContactPredictionOptions& options);

/// A static plane: n.x >= offset is the allowed side (n unit, pointing into the container).
struct WallContactPrediction {
  ContactPrediction::Kind kind = ContactPrediction::Kind::kNone;
  double time = 0.0;
  int vertex = -1;   // the polyhedron's vertex nearest the plane at `time`
  double gap = 0.0;  // its distance to the plane at `time`
  int iterations = 0;
};

/// The first time in [t_begin, t_end] at which the polyhedron on `path` comes within `tolerance`
/// of the plane {x : normal.x = offset}. Exact for a non-rotating body (a root of the nearest
/// vertex's polynomial), conservative advancement for a rotating one (never later than the
/// first time the gap is 0.9 tolerance, with gap <= tolerance at the returned time). The
/// polyhedron's frame origin is the point `path` moves; t_end may be infinity (as for
/// PredictContact; kNone then reports the last gap evaluated). `spin_radius`: the path's
/// narrow::SpinRadius if the caller keeps it (< 0: computed here).
WallContactPrediction PredictWallContact(const TrackedPolyhedron& body, const RigidPath& path,
                                         const Vec3& normal, double offset, double t_begin,
                                         double t_end, double tolerance, int max_iterations = 64,
                                         double spin_radius = -1.0);

}  // namespace sparsedyn
