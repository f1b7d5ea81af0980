// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sparsedyn {

/// A rigid placement X_WB of a body frame B in the world W: p_W = rotation * p_B + translation.
struct Pose {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< unit
  /// Where B's origin is in W, m.
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  /// A point given in B, in W.
  Eigen::Vector3d ToWorld(const Eigen::Vector3d& p_B) const { return rotation * p_B + translation; }
  /// A point given in W, in B.
  Eigen::Vector3d ToBody(const Eigen::Vector3d& p_W) const {
    return rotation.conjugate() * (p_W - translation);
  }
};

}  // namespace sparsedyn
