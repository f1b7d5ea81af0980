// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include "events/event.hpp"
#include "world/detailed_phase.hpp"
#include "world/drag_contacts.hpp"
#include "world/path_changes.hpp"
#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// The contact model of a body and the walls of a walled box (static, immovable: the body's
/// own restitution and friction apply). A sphere meets a wall when its element does (the
/// sparse phase predicts it); a polyhedron's contact with the walls is predicted by the
/// detailed phase up to the element's next event. A sphere that comes to rest against a wall
/// is held by it (docs/sparse-phase.md#coming-to-rest).
class WallContacts {
 public:
  WallContacts(WorldCore& core, SparsePhase& sparse, DetailedPhase& detailed,
               PathChanges& changes)
      : core_(core), sparse_(sparse), detailed_(detailed), changes_(changes), drag_(core) {}

  /// Body i's wall event (kWallMeet, the wall in its prediction's aux).
  void Handle(std::uint32_t i);
  /// The earlier of `event` (body i's element event) and i's first contact with a wall
  /// before it; i is a polyhedron.
  Event PredictPolyhedron(std::uint32_t i, Event event);

 private:
  void HandleSphere(std::uint32_t i);
  void HandlePolyhedron(std::uint32_t i);
  /// PredictPolyhedron for a polyhedron with drag, on its true motion.
  Event PredictDragPolyhedron(std::uint32_t i, Event event);
  bool HoldAgainstWall(std::uint32_t i, int w, const Vec3& normal, const Vec3& v, double gap);
  /// Polyhedron i, on `path` now, touching wall w (normal into the box) at `contact`'s points
  /// (in order around their mean): held on that face if it comes to rest there.
  bool HoldPolyhedron(std::uint32_t i, int w, const Vec3& normal, const RigidPath& path,
                      const ContactGeometry& contact);
  /// The hold just set on body i by wall w (normal into the box), its gap and contact point,
  /// reported and predicted from: `approach` is the normal velocity the hold stopped.
  void ReportHold(std::uint32_t i, int w, double gap, const Vec3& point, const Vec3& normal,
                  double approach);

  WorldCore& core_;
  SparsePhase& sparse_;
  DetailedPhase& detailed_;
  PathChanges& changes_;
  DragContacts drag_;  // polyhedra with drag, on their true motions
  // Set while a body that touched a wall without approaching it predicts again: that wall is
  // then left alone for the time the body needs to close the tolerance band.
  std::optional<std::pair<std::uint32_t, int>> band_skip_;
};

}  // namespace sparsedyn
