// SPDX-License-Identifier: MIT
#pragma once

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The analytic path of an element's centre during one segment (App. F.1, F.3):
/// P(t) = p0 + v0 (t - t0) + a (t - t0)^2 / 2, evaluated relative to the segment start t0 so that
/// precision does not degrade with the absolute simulation time.
struct Path {
  Vec3 p0 = Vec3::Zero();
  Vec3 v0 = Vec3::Zero();
  Vec3 a = Vec3::Zero();
  double t0 = 0.0;

  Vec3 PositionAt(double t) const {
    const double dt = t - t0;
    return p0 + dt * (v0 + (0.5 * dt) * a);
  }
  Vec3 VelocityAt(double t) const { return v0 + (t - t0) * a; }

  /// The same motion described as a segment that starts at `t` (position and velocity there).
  Path RebasedAt(double t) const { return Path{PositionAt(t), VelocityAt(t), a, t}; }
};

/// The per-body part of a Path when the acceleration is shared (gravity alone) or kept
/// elsewhere: 56 bytes instead of 80, which is most of a sphere's memory in a large World.
struct PathStart {
  Vec3 p0 = Vec3::Zero();
  Vec3 v0 = Vec3::Zero();
  double t0 = 0.0;
};

}  // namespace sparsedyn
