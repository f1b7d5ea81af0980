// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "sparsedyn/types.hpp"
#include "world/shape_table.hpp"

namespace sparsedyn {

/// What a body has beyond its centre's path once rotation is tracked: its shape (polyhedra; a
/// sphere has none), its orientation at its segment start and its angular velocity
/// (docs/decisions/0003-rotation-model.md), and the spin radius of its current segment
/// (narrow::SpinRadius, kept because it is O(vertices); 0 for a sphere, whose turning moves no
/// surface). Rotation is tracked once a World has a polyhedron, or a sphere that spins or has
/// friction; a gas of frictionless spheres keeps none of it.
class RigidBodies {
 public:
  explicit RigidBodies(RotationModel model) : shapes_(model) {}

  /// Whether rotation is tracked (every body then has an entry).
  bool Tracked() const { return tracked_; }
  /// Whether some body is a polyhedron.
  bool AnyPolyhedron() const { return polyhedra_ > 0; }
  bool IsPolyhedron(std::uint32_t i) const { return tracked_ && shape_[i] != kNoIndex; }

  ShapeTable& shapes() { return shapes_; }
  const ShapeTable& shapes() const { return shapes_; }
  const BodyShape& ShapeOf(std::uint32_t i) const { return shapes_[shape_[i]]; }
  std::uint32_t ShapeIndexOf(std::uint32_t i) const { return shape_[i]; }
  const Eigen::Quaterniond& Orientation0(std::uint32_t i) const { return q0_[i]; }
  const Vec3& Omega(std::uint32_t i) const { return omega_[i]; }
  double SpinRadius(std::uint32_t i) const { return spin_radius_[i]; }

  /// Starts tracking rotation: the `count` bodies there are so far are spheres at rest.
  void Track(std::size_t count) {
    if (tracked_) return;
    tracked_ = true;
    shape_.assign(count, kNoIndex);
    q0_.assign(count, Eigen::Quaterniond::Identity());
    omega_.assign(count, Vec3::Zero());
    spin_radius_.assign(count, 0.0);
  }

  /// Body i's rotation from its new segment's start on.
  void SetRotation(std::uint32_t i, const Eigen::Quaterniond& q0, const Vec3& omega) {
    q0_[i] = q0;
    omega_[i] = omega;
  }
  void SetOrientation0(std::uint32_t i, const Eigen::Quaterniond& q0) { q0_[i] = q0; }
  void SetSpinRadius(std::uint32_t i, double radius) { spin_radius_[i] = radius; }

  /// A new body (rotation tracked): `shape` kNoIndex for a sphere. The spin radius is set once
  /// its path is known.
  void Append(std::uint32_t shape, const Eigen::Quaterniond& q0, const Vec3& omega) {
    shape_.push_back(shape);
    q0_.push_back(q0);
    omega_.push_back(omega);
    spin_radius_.push_back(0.0);
    if (shape != kNoIndex) ++polyhedra_;
  }
  /// The bodies were renumbered (or some removed): new body e is old body old_of_new[e].
  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    if (!tracked_) return;
    permute(shape_);
    permute(q0_);
    permute(omega_);
    permute(spin_radius_);
    polyhedra_ = static_cast<std::uint32_t>(
        std::count_if(shape_.begin(), shape_.end(), [](std::uint32_t s) { return s != kNoIndex; }));
  }

  std::size_t MemoryBytes() const {
    return shape_.capacity() * sizeof(std::uint32_t) +
           q0_.capacity() * sizeof(Eigen::Quaterniond) + omega_.capacity() * sizeof(Vec3) +
           spin_radius_.capacity() * sizeof(double);
  }

 private:
  ShapeTable shapes_;
  bool tracked_ = false;
  std::uint32_t polyhedra_ = 0;
  std::vector<std::uint32_t> shape_;     // per body, into shapes_ (kNoIndex: a sphere)
  std::vector<Eigen::Quaterniond> q0_;   // per body: orientation at its segment start
  std::vector<Vec3> omega_;              // per body: angular velocity, world frame
  std::vector<double> spin_radius_;      // per body: SpinRadius of its current segment
};

}  // namespace sparsedyn
