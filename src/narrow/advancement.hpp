// SPDX-License-Identifier: MIT
// One step of conservative advancement: how long two bodies (or a body and a wall) separated by
// a gap along a fixed direction stay apart, given a bound on how fast the gap can close.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "math/polynomial.hpp"
#include "math/roots.hpp"
#include "motion/rigid_path.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn::narrow {

/// The longest horizon the predictions search (s): EarliestRoot needs a finite interval, and an
/// open-ended one (t_end = infinity) is searched this far, then reported as kNone at infinity.
inline constexpr double kMaxHorizon = 1e30;

/// The first dt in [0, horizon] at which a gap closing at most at speed + accel * dt (so by at
/// most speed dt + accel dt^2 / 2 in total) may have closed by `closable` (> 0). Before that
/// time the gap certainly has not. std::nullopt when it cannot close within the horizon (e.g.
/// speed <= 0 and accel <= 0). Conservative: EarliestRoot is never later than the true root.
inline std::optional<double> AdvancementStep(double closable, double speed, double accel,
                                             double horizon) {
  if (speed <= 0.0 && accel <= 0.0) return std::nullopt;
  return EarliestRoot(Polynomial{-closable, speed, 0.5 * accel}, 0.0, horizon);
}

/// The largest speed at which a point of the body on `path` moves along any unit direction n
/// because of its spin is |n x w| times this: the largest distance of a vertex from the spin
/// axis through the path's centre ((w x r) . n = r . (n x w) and n x w is normal to w, so only
/// r's part normal to w counts). Rotation about that axis keeps these distances, so one
/// evaluation at any time serves the whole path. 0 for a body that does not spin.
inline double SpinRadius(const ConvexPolyhedron& poly, const RigidPath& path) {
  if (!path.Rotates()) return 0.0;
  const Vec3 axis_B = (path.q0.conjugate() * path.omega).normalized();
  double r2 = 0.0;
  for (const Vec3& v : poly.vertices())
    r2 = std::max(r2, (v - v.dot(axis_B) * axis_B).squaredNorm());
  return std::sqrt(r2);
}

/// A bound rate(dt) <= now + growth * dt on (w x r) . d, the speed along d that a body's spin w
/// gives its points r (offsets from the path's centre), for all dt >= 0 from the pose X:
/// (w x r) . d = r . u with u = d x w normal to w; after turning by theta = |w| dt,
/// r(dt) . u = cos(theta) r . u - sin(theta) r . (w^ x u) <= max(h(u), 0) + theta |u| r_s, where
/// h is the support function at X and r_s the SpinRadius (for theta >= pi/2 the right side
/// already exceeds the plain bound |u| r_s). Near contact h(u) is often well below |u| r_s.
struct SpinRate {
  double now = 0.0;
  double growth = 0.0;
};
inline SpinRate SpinRateAlong(const ConvexPolyhedron& poly, const Pose& X, const Vec3& omega,
                              const Vec3& d, double spin_radius) {
  const Vec3 u = d.cross(omega);
  if (u.squaredNorm() == 0.0) return {};
  const Vec3 u_B = X.rotation.normalized().conjugate() * u;
  const double h = u_B.dot(poly.vertex(poly.SupportVertex(u_B)));
  return {std::max(h, 0.0), omega.norm() * u.norm() * spin_radius};
}

}  // namespace sparsedyn::narrow
