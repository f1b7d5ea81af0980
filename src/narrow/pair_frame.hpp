// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::narrow {

/// The pose X_AB of B in A's frame, computed once per query so that every step of the walk works
/// in A's local coordinates: the translations are subtracted before rotating, so two bodies far
/// from the origin (1e6) keep the precision of their small relative offset.
struct PairFrame {
  Eigen::Matrix3d R_WA = Eigen::Matrix3d::Identity();  // to report results in the world
  Eigen::Matrix3d R_AB = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_AB = Eigen::Vector3d::Zero();

  PairFrame() = default;
  PairFrame(const Pose& X_WA, const Pose& X_WB)
      : R_WA(RotationOf(X_WA.rotation)),
        // The quaternion product is a scaled rotation whatever the inputs' norms.
        R_AB(RotationOf(X_WA.rotation.conjugate() * X_WB.rotation)),
        p_AB(R_WA.transpose() * (X_WB.translation - X_WA.translation)) {}

  /// The rotation of a quaternion of any non-zero norm: the quadratic form scaled by 2 / |q|^2,
  /// one division instead of normalising (a square root and a division) on the update's
  /// critical path. Bit for bit Eigen's toRotationMatrix() when |q|^2 rounds to 1.
  static Eigen::Matrix3d RotationOf(const Eigen::Quaterniond& q) {
    const double s = 2.0 / q.squaredNorm();
    const double x = q.x(), y = q.y(), z = q.z(), w = q.w();
    const double sx = s * x, sy = s * y, sz = s * z;
    const double wx = sx * w, wy = sy * w, wz = sz * w;
    const double xx = sx * x, xy = sy * x, xz = sz * x;
    const double yy = sy * y, yz = sz * y, zz = sz * z;
    Eigen::Matrix3d r;  // element by element: Eigen's comma initializer costs ~25 instructions
    r(0, 0) = 1.0 - (yy + zz);
    r(0, 1) = xy - wz;
    r(0, 2) = xz + wy;
    r(1, 0) = xy + wz;
    r(1, 1) = 1.0 - (xx + zz);
    r(1, 2) = yz - wx;
    r(2, 0) = xz - wy;
    r(2, 1) = yz + wx;
    r(2, 2) = 1.0 - (xx + yy);
    return r;
  }

  /// A point of B (body frame) in A's frame.
  Eigen::Vector3d ToA(const Eigen::Vector3d& p_B) const { return R_AB * p_B + p_AB; }
  /// A point in A's frame in B's body frame.
  Eigen::Vector3d ToB(const Eigen::Vector3d& p_A) const { return R_AB.transpose() * (p_A - p_AB); }
};

}  // namespace sparsedyn::narrow
