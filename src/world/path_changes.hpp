// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// Changes of a body's path at the current time (a collision, a wall's hold): the new segment
/// starts where the old one has the body now, the body's version goes up (its partners'
/// predictions against it become stale, §4.2) and the OnSegment observers hear of it. What
/// predicts again afterwards is the caller's business.
class PathChanges {
 public:
  PathChanges(WorldCore& core, SparsePhase& sparse) : core_(core), sparse_(sparse) {}

  /// A sphere's new velocity. Inline, as ReportSegment: twice in every collision of a gas.
  void SetVelocity(std::uint32_t i, const Vec3& v) {
    ElementPaths& paths = core_.bodies.paths;
    paths.SetStart(i, PathStart{paths.PositionNow(i), v, paths.Now()});
    ReportSegment(i);
  }
  /// A polyhedron's new velocity and angular velocity (world frame).
  void SetMotion(std::uint32_t i, const Vec3& v, const Vec3& omega);
  /// Sphere i held by the walls `walls` (bits; 0 releases it), moving at `v` otherwise: its
  /// velocity and acceleration into the held walls become zero.
  void SetHeld(std::uint32_t i, std::uint8_t walls, Vec3 v);

 private:
  void ReportSegment(std::uint32_t i) {
    const std::uint32_t version = ++sparse_.PredictionOf(i).version;
    if (core_.observers.WantsSegments()) {
      const ElementPaths& paths = core_.bodies.paths;
      const PathStart& s = paths.Start(i);
      core_.observers.Segment(MotionSegment{paths.Now(), core_.bodies.ids.IdOf(i), s.p0, s.v0,
                                            paths.PathOf(i).a, version});
    }
  }

  WorldCore& core_;
  SparsePhase& sparse_;
};

}  // namespace sparsedyn
