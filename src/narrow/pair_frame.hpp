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
      : R_WA(X_WA.rotation.normalized().toRotationMatrix()),
        // The quaternion product is a scaled rotation whatever the inputs' norms: one normalise.
        R_AB((X_WA.rotation.conjugate() * X_WB.rotation).normalized().toRotationMatrix()),
        p_AB(R_WA.transpose() * (X_WB.translation - X_WA.translation)) {}

  /// A point of B (body frame) in A's frame.
  Eigen::Vector3d ToA(const Eigen::Vector3d& p_B) const { return R_AB * p_B + p_AB; }
  /// A point in A's frame in B's body frame.
  Eigen::Vector3d ToB(const Eigen::Vector3d& p_A) const { return R_AB.transpose() * (p_A - p_AB); }
};

}  // namespace sparsedyn::narrow
