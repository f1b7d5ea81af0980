// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

#include <Eigen/Geometry>

#include "motion/path.hpp"
#include "sparsedyn/geometry/pose.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The rotation by the world-frame rotation vector `theta` (axis theta/|theta|, angle |theta|),
/// accurate for tiny angles too (no division by a vanishing angle).
inline Eigen::Quaterniond RotationFromVector(const Vec3& theta) {
  const double angle = theta.norm();
  const double half = 0.5 * angle;
  // sin(half) / angle, by its series below 1e-4 where the quotient loses digits.
  const double s = half < 1e-4 ? 0.5 * (1.0 - half * half / 6.0) : std::sin(half) / angle;
  return Eigen::Quaterniond(std::cos(half), s * theta.x(), s * theta.y(), s * theta.z());
}

/// A rigid body's motion during one segment (docs/decisions/0003-rotation-model.md): its centre
/// of mass follows `centre` (App. F.1), and it turns at the constant world-frame angular
/// velocity `omega` from the orientation `q0` it had at centre.t0:
///   q(t) = exp(omega (t - t0)) q0.
/// Everything is evaluated relative to the segment start, so precision does not degrade with
/// the absolute simulation time.
struct RigidPath {
  Path centre;
  Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity();  // body to world at centre.t0, unit
  Vec3 omega = Vec3::Zero();                               // rad/s, world frame

  double t0() const { return centre.t0; }
  bool Rotates() const { return omega.x() != 0.0 || omega.y() != 0.0 || omega.z() != 0.0; }

  Eigen::Quaterniond OrientationAt(double t) const {
    if (!Rotates()) return q0;
    return RotationFromVector(omega * (t - centre.t0)) * q0;
  }
  Pose PoseAt(double t) const { return Pose{OrientationAt(t), centre.PositionAt(t)}; }

  /// Velocity at time t of the body point that is at `point_W` (world frame) at that time.
  Vec3 PointVelocity(const Vec3& point_W, double t) const {
    return centre.VelocityAt(t) + omega.cross(point_W - centre.PositionAt(t));
  }

  /// The same motion as a segment starting at t (orientation renormalized there).
  RigidPath RebasedAt(double t) const {
    return RigidPath{centre.RebasedAt(t), OrientationAt(t).normalized(), omega};
  }
};

}  // namespace sparsedyn
