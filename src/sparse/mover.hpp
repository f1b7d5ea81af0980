// SPDX-License-Identifier: MIT
#pragma once

#include "motion/path.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// An element's bounding sphere as seen from the prediction time `now`: centre position,
/// velocity and acceleration at `now`, and radius R(dt) = r0 + r1 dt + r2 dt^2 / 2 (the body's
/// bounding radius plus its envelope), all as functions of dt = t - now.
struct Mover {
  Vec3 p = Vec3::Zero();
  Vec3 v = Vec3::Zero();
  Vec3 a = Vec3::Zero();
  double r0 = 0.0;
  double r1 = 0.0;
  double r2 = 0.0;
};

/// The mover of an element on `path` with bounding radius `radius` and envelope `envelope`
/// (measured from the segment start path.t0), seen at time `now` >= path.t0.
inline Mover MoverAt(const Path& path, double radius, const Envelope& envelope, double now) {
  const double dt = now - path.t0;
  return Mover{path.PositionAt(now), path.VelocityAt(now), path.a,
               radius + envelope.At(dt), envelope.e1 + envelope.e2 * dt, envelope.e2};
}

/// A mover without envelope (exact body sphere), the common case.
inline Mover MoverAt(const Path& path, double radius, double now) {
  return Mover{path.PositionAt(now), path.VelocityAt(now), path.a, radius, 0.0, 0.0};
}

}  // namespace sparsedyn
