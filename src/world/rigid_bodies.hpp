// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "sparsedyn/types.hpp"
#include "world/shape_table.hpp"

namespace sparsedyn {

/// What a polyhedral body has beyond its centre's path: its shape, its orientation at its
/// segment start and its angular velocity (docs/decisions/0003-rotation-model.md), and the
/// spin radius of its current segment (narrow::SpinRadius, kept because it is O(vertices)).
/// Empty in a World of spheres.
class RigidBodies {
 public:
  explicit RigidBodies(RotationModel model) : shapes_(model) {}

  bool Any() const { return !shape_.empty(); }
  ShapeTable& shapes() { return shapes_; }
  const BodyShape& ShapeOf(std::uint32_t i) const { return shapes_[shape_[i]]; }
  const Eigen::Quaterniond& Orientation0(std::uint32_t i) const { return q0_[i]; }
  const Vec3& Omega(std::uint32_t i) const { return omega_[i]; }
  double SpinRadius(std::uint32_t i) const { return spin_radius_[i]; }

  /// Body i's rotation from its new segment's start on.
  void SetRotation(std::uint32_t i, const Eigen::Quaterniond& q0, const Vec3& omega) {
    q0_[i] = q0;
    omega_[i] = omega;
  }
  void SetOrientation0(std::uint32_t i, const Eigen::Quaterniond& q0) { q0_[i] = q0; }
  void SetSpinRadius(std::uint32_t i, double radius) { spin_radius_[i] = radius; }

  /// A new polyhedral body (the spin radius is set once its path is known).
  void Append(std::uint32_t shape, const Eigen::Quaterniond& q0, const Vec3& omega) {
    shape_.push_back(shape);
    q0_.push_back(q0);
    omega_.push_back(omega);
    spin_radius_.push_back(0.0);
  }

  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    if (!Any()) return;
    permute(shape_);
    permute(q0_);
    permute(omega_);
    permute(spin_radius_);
  }

  std::size_t MemoryBytes() const {
    return shape_.capacity() * sizeof(std::uint32_t) +
           q0_.capacity() * sizeof(Eigen::Quaterniond) + omega_.capacity() * sizeof(Vec3) +
           spin_radius_.capacity() * sizeof(double);
  }

 private:
  ShapeTable shapes_;
  std::vector<std::uint32_t> shape_;     // per body, into shapes_
  std::vector<Eigen::Quaterniond> q0_;   // per body: orientation at its segment start
  std::vector<Vec3> omega_;              // per body: angular velocity, world frame
  std::vector<double> spin_radius_;      // per body: SpinRadius of its current segment
};

}  // namespace sparsedyn
