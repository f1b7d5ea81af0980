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

}  // namespace sparsedyn::narrow
