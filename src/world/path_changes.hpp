// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>

#include "dynamics/god_plan.hpp"
#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// Changes of a body's path at the current time (a collision, a wall's hold, a drag check):
/// the new segment
/// starts where the old one has the body now, the body's version goes up (its partners'
/// predictions against it become stale, §4.2) and the OnSegment observers hear of it. What
/// predicts again afterwards is the caller's business.
class PathChanges {
 public:
  PathChanges(WorldCore& core, SparsePhase& sparse) : core_(core), sparse_(sparse) {}

  /// A body's new velocity (its spin kept). Inline, as ReportSegment: twice in every collision
  /// of a gas (GCC kept it out of line, with a frame for its rare branches).
  [[gnu::always_inline]] void SetVelocity(std::uint32_t i, const Vec3& v) {
    if (core_.bodies.rigid.Tracked()) {
      SetMotion(i, v, core_.bodies.rigid.Omega(i));
      return;
    }
    ElementPaths& paths = core_.bodies.paths;
    paths.SetStart(i, PathStart{paths.PositionNow(i), v, paths.Now()});
    ReportSegment(i);
  }
  /// A body's new velocity and angular velocity (world frame); rotation is tracked.
  void SetMotion(std::uint32_t i, const Vec3& v, const Vec3& omega);
  /// A collision's new motion: first a hold on i ends (the wall or the static takes it up
  /// again if it still rests there), then SetMotion.
  void SetCollidedMotion(std::uint32_t i, const Vec3& v, const Vec3& omega) {
    if (core_.bodies.paths.accelerations().Held(i)) SetHeld(i, Hold{}, v);
    SetMotion(i, v, omega);
  }
  /// Whatever holds body i lets it go, its motion kept (a push from outside: SetVelocity,
  /// ApplyImpulse; what still holds it takes it up again).
  void Release(std::uint32_t i) {
    const ElementPaths& paths = core_.bodies.paths;
    if (paths.accelerations().Held(i)) SetHeld(i, Hold{}, paths.VelocityNow(i));
  }
  /// The static's hold on body i ends (its walls' stay), its motion kept.
  void ReleaseStatic(std::uint32_t i) {
    const ElementPaths& paths = core_.bodies.paths;
    Hold hold = paths.accelerations().HoldOf(i);
    hold.on_static = kNoIndex;
    SetHeld(i, hold, paths.VelocityNow(i));
  }
  /// A body's new free acceleration (gravity plus a new thrust), its velocity kept; a wall's
  /// hold ends (the wall takes it up again if the body still rests on it).
  void SetAcceleration(std::uint32_t i, const Vec3& free_acceleration);
  /// A god object's next piece: its plan's state at now, exact, so that round-off does not
  /// gather from piece to piece (a move ends at rest at exactly zero velocity).
  void SetPiece(std::uint32_t i, const GodState& state);
  /// A body moved at once to `position` with `orientation`, moving at v and omega (a teleport).
  void SetPose(std::uint32_t i, const Vec3& position, const Eigen::Quaterniond& orientation);
  /// Body i held by `hold` (walls and a static face; Hold{} releases it), moving at `v`
  /// otherwise: its velocity and acceleration into what holds it become zero. A polyhedron
  /// held on a face turns at `omega` from now (its spin about the normal); a sphere keeps its
  /// spin.
  void SetHeld(std::uint32_t i, const Hold& hold, Vec3 v,
               const std::optional<Vec3>& omega = std::nullopt);

 private:
  // A tracked body's orientation at its new segment's start (now).
  void RebaseRotation(std::uint32_t i);
  // The segment just set begins: a body with drag starts its new DragMotion and Taylor path
  // there (App. H.2), then the version goes up and the observers hear of it. The rare steps
  // out of line: inlined, they gave SetVelocity a 0x128-byte frame and 6 saved registers
  // (twice the instructions of a collision's SetVelocity at N = 10^4).
  void ReportSegment(std::uint32_t i) {
    if (core_.bodies.HasDrag(i)) StartDragSegment(i);
    const std::uint32_t version = ++sparse_.PredictionOf(i).version;
    if (core_.observers.WantsSegments()) AnnounceSegment(i, version);
  }
  [[gnu::noinline]] void StartDragSegment(std::uint32_t i);
  [[gnu::noinline]] void AnnounceSegment(std::uint32_t i, std::uint32_t version);

  WorldCore& core_;
  SparsePhase& sparse_;
};

}  // namespace sparsedyn
