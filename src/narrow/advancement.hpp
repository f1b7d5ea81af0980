// SPDX-License-Identifier: MIT
// One step of conservative advancement: how long two bodies (or a body and a wall) separated by
// a gap along a fixed direction stay apart, given a bound on how fast the gap can close.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "motion/rigid_path.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn::narrow {

/// The longest horizon the predictions search (s): EarliestRoot needs a finite interval, and an
/// open-ended one (t_end = infinity) is searched this far, then reported as kNone at infinity.
inline constexpr double kMaxHorizon = 1e30;

/// The first dt in [0, horizon] at which a gap closing at most at speed + accel * dt (so by at
/// most speed dt + accel dt^2 / 2 in total) may have closed by `closable` (> 0). Before that
/// time the gap certainly has not. std::nullopt when it cannot close within the horizon (e.g.
/// speed <= 0 and accel <= 0). Closed form (the stable root of the quadratic), then lowered by
/// kStepRoundingSlack: the rounding of a few operations is far below it, so the step is never
/// later than the exact root; a near-touch within the discriminant's rounding counts as a root.
inline constexpr double kStepRoundingSlack = 1e-13;
inline std::optional<double> AdvancementStep(double closable, double speed, double accel,
                                             double horizon) {
  if (speed <= 0.0 && accel <= 0.0) return std::nullopt;
  if (!(closable > 0.0)) return 0.0;
  double dt;
  if (accel == 0.0) {
    dt = closable / speed;
  } else {
    // speed dt + accel dt^2 / 2 = closable; disc = speed^2 + 2 accel closable. With accel < 0
    // the two terms cancel: disc is raised by its rounding bound, which moves the smaller root
    // earlier (the safe side) and keeps a touch within round-off a root.
    const double product = 2.0 * accel * closable;
    double disc = std::fma(speed, speed, product);
    if (accel < 0.0) {
      disc += 4.0 * std::numeric_limits<double>::epsilon() * (speed * speed - product);
      if (disc < 0.0) return std::nullopt;  // the closing stops short of `closable`
    }
    const double root = std::sqrt(disc);
    // speed > 0: 2 closable / (speed + root) has no cancellation; speed <= 0 (so accel > 0):
    // (root - speed) / accel has none either.
    dt = speed > 0.0 ? 2.0 * closable / (speed + root) : (root - speed) / accel;
  }
  dt *= 1.0 - kStepRoundingSlack;
  if (!(dt <= horizon)) return std::nullopt;
  return dt;
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
/// `support(u_B)` returns the support vertex index of `poly` in body-frame direction u_B.
template <typename Support>
SpinRate SpinRateAlong(const ConvexPolyhedron& poly, const Pose& X, const Vec3& omega,
                       const Vec3& d, double spin_radius, const Support& support) {
  const Vec3 u = d.cross(omega);
  if (u.squaredNorm() == 0.0) return {};
  const Vec3 u_B = X.rotation.normalized().conjugate() * u;
  const double h = u_B.dot(poly.vertex(support(u_B)));
  return {std::max(h, 0.0), omega.norm() * u.norm() * spin_radius};
}
inline SpinRate SpinRateAlong(const ConvexPolyhedron& poly, const Pose& X, const Vec3& omega,
                              const Vec3& d, double spin_radius) {
  return SpinRateAlong(poly, X, omega, d, spin_radius,
                       [&poly](const Vec3& u_B) { return poly.SupportVertex(u_B); });
}

}  // namespace sparsedyn::narrow
