// SPDX-License-Identifier: MIT
#pragma once
// The thesis scene (scenes/thesis.hpp) as a Bullet btDiscreteDynamicsWorld: what
// docs/lab/measurements.md "The thesis scene against Bullet" measures our engine against.

#include <memory>
#include <vector>

#include "sparsedyn/geometry/pose.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn::bench {

/// A Bullet world built from a SceneDescription of polyhedra in a walled box: btDbvtBroadphase,
/// the sequential impulse solver, one shared btConvexHullShape per distinct scene shape with
/// collision margin 0 (so Bullet collides the very polyhedron we measure, not one inflated by the
/// margin), six static planes as walls, restitution 1 (at every approach speed), friction 0, no
/// damping, no sleeping, no gravity. Mass and inertia come from the scene: the body's mass and
/// the polyhedron's own inertia tensor at its density, diagonalised so that the Bullet body frame
/// is the principal frame (Bullet keeps a diagonal local inertia).
class BulletThesisWorld {
 public:
  explicit BulletThesisWorld(const SceneDescription& scene);
  ~BulletThesisWorld();
  BulletThesisWorld(const BulletThesisWorld&) = delete;
  BulletThesisWorld& operator=(const BulletThesisWorld&) = delete;

  /// One stepSimulation of exactly dt seconds (no substeps, no interpolation).
  void Step(double dt);

  /// Translational + rotational kinetic energy, J.
  double KineticEnergy() const;
  /// Pose of scene body i's own body frame (the scene shape's frame, centroid at the origin).
  Pose PoseOf(std::size_t i) const;
  std::size_t BodyCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sparsedyn::bench
