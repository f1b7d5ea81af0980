// SPDX-License-Identifier: MIT
// A second-order conservative-advancement step for rotating pairs. The separation of two convex
// bodies along a fixed direction n is bounded below by a concave function of the step dt, exact
// to first order: so a step can go nearly all the way to where the slab may close, and the
// advancement converges quadratically instead of by a constant fraction per step.
#pragma once

#include <optional>

#include "motion/rigid_path.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::narrow {

/// Sep(t + dt) >= Bound(dt), Sep being B's lowest point minus A's highest along the fixed unit
/// world direction n, both on their rigid paths from time t. A vertex at offset r from its
/// centre rises along n at the rate r . u, u = n x w, and that rate changes by at most
/// |w| |u| r_s per second (r_s the SpinRadius), so A's top after dt is at most
/// h_A(n + dt u_A) + |w_A| |u_A| r_A dt^2 / 2, with h_A the support function of A's offsets at
/// t: the maximum over the vertices of the first-order heights is a support in a direction
/// linear in dt. Likewise B's bottom, and the centres move on their parabolas (an acceleration
/// that opens the gap is dropped, which keeps the bound concave). Bound(0) is the slab's
/// separation at t, less kSupportSlack x scale for the round-off of the supports.
class SlabBound {
 public:
  /// `near` (optional) names features of A and B near the slab's faces (e.g. the closest
  /// features that gave n): their vertices start the support climbs.
  SlabBound(const TrackedPolyhedron& a, const RigidPath& path_a, double spin_radius_a,
            const TrackedPolyhedron& b, const RigidPath& path_b, double spin_radius_b,
            const Vec3& n, double t, std::optional<FeaturePair> near = std::nullopt);
  /// B against the static plane {x : n . x = offset} (n towards B's allowed side): the plane
  /// takes A's place, so Bound is a lower bound on B's gap to the plane.
  static SlabBound Wall(const TrackedPolyhedron& b, const RigidPath& path_b, double spin_radius_b,
                        const Vec3& n, double offset, double t);

  /// Bound(0): the slab's separation at t (less the round-off slack).
  double Separation() const { return at_zero_; }
  /// Bound(dt), for dt >= 0. Concave in dt.
  double operator()(double dt);

  /// A step dt in (0, horizon] with Bound(dt) >= level, hence (concavity) Bound >= level on all
  /// of [0, dt]: the slab has not closed to `level` before t + dt. Found from the tangent model
  /// at 0 and then regula falsi from below; `fallback` (a valid step) is tried when the model
  /// never closes. std::nullopt when Bound(0) <= level or no step longer than 0 was found.
  std::optional<double> Step(double level, double horizon, double fallback);

 private:
  // h(d) of one body: the largest offset . d over its vertices; climbs from the last support.
  double Support(const TrackedPolyhedron& body, const Eigen::Quaterniond& rotation,
                 const Vec3& direction_W, int& vertex) const;

  SlabBound(const TrackedPolyhedron& b, const RigidPath& path_b, const Vec3& n, double t);
  void Finish(double spin_radius_b, const RigidPath& path_b, double closing_accel,
              double curvature_a);

  const TrackedPolyhedron* a_ = nullptr;  // nullptr: a wall
  const TrackedPolyhedron& b_;
  Eigen::Quaterniond rotation_a_, rotation_b_;  // body to world at t
  Vec3 n_, u_a_, u_b_;
  double gap_ = 0.0;         // n . (c_B - c_A) at t
  double closing_ = 0.0;     // n . (v_B - v_A)
  double curvature_ = 0.0;   // spin terms plus a closing acceleration, per s^2 (>= 0)
  double slack_ = 0.0;
  double at_zero_ = 0.0;
  int top_a_ = -1, bottom_b_ = -1;  // support vertices at the last evaluation
  int top_a_0_ = -1, bottom_b_0_ = -1;  // ... and at dt = 0
};

}  // namespace sparsedyn::narrow
