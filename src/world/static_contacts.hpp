// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "dynamics/rigid_collision.hpp"
#include "motion/rigid_path.hpp"
#include "world/detailed_phase.hpp"
#include "world/drag_contacts.hpp"
#include "world/path_changes.hpp"
#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// The contact model of a moving body and a static one (issue #36 part 3), for each kind of
/// either (sphere or convex polyhedron): the engagement starts when the element's sphere
/// reaches the static's box (StaticTree) and ends when it leaves it; the contact is predicted
/// as for moving pairs (PredictContact, PredictSphereContact, PredictMeeting), the static on a
/// path that does not move; a contact gets the rigid impulse with the static's infinite mass.
/// An engagement's a is the element, b the static's key (StaticBodies::KeyOf). A sphere with
/// drag meets statics on its true motion (DragContacts::StaticContact).
class StaticContacts {
 public:
  StaticContacts(WorldCore& core, SparsePhase& sparse, DetailedPhase& detailed,
                 PathChanges& changes)
      : core_(core), sparse_(sparse), detailed_(detailed), changes_(changes), drag_(core) {}

  void PredictEngagement(std::uint32_t k);
  /// Engagement k's contact event (DetailedPhase::Handle takes checkpoints and ends).
  void HandleContact(std::uint32_t k);

  /// Where element i and static s touch now (cold-started walks): the contact geometry, whose
  /// body A is the static when `static_is_a`.
  struct Touch {
    ContactGeometry contact;
    bool static_is_a = false;
    FeaturePair features;  // the walk's answer (a sphere against a polyhedron: in .a)
  };
  Touch TouchNow(std::uint32_t i, std::uint32_t s, std::optional<FeaturePair> warm) const;
  /// The world normal of the static polyhedron's face in `touch`, if its feature is a face.
  std::optional<Vec3> StaticFaceNormal(std::uint32_t s, const Touch& touch) const;
  /// The pair's contact tolerance: relative to the element's radius and the smaller of the two
  /// (a floor slab 10^4 times a pebble's size does not widen the pebble's band).
  double Tolerance(std::uint32_t i, std::uint32_t s) const;

 private:
  RigidPath PathOfStatic(std::uint32_t s) const;
  /// When element i's sphere leaves static s's box (never early).
  double ExitTime(std::uint32_t i, std::uint32_t s) const;
  /// The end of a bounce series on static s's face (docs/sparse-phase.md#coming-to-rest):
  /// element i, touching s as `touch` says, held there if it comes to rest. False otherwise.
  bool HoldOnFace(std::uint32_t i, std::uint32_t s, const Touch& touch);
  /// The collision of i and s touching as `touch` says: false when no point approaches.
  bool Collide(std::uint32_t i, std::uint32_t s, const Touch& touch);
  /// Engagement k of a body with drag: its contact on the true motion (DragContacts) from
  /// `begin`, up to the exit or the body's drag check.
  void PredictDragEngagement(std::uint32_t k, double begin);

  WorldCore& core_;
  SparsePhase& sparse_;
  DetailedPhase& detailed_;
  PathChanges& changes_;
  DragContacts drag_;
};

}  // namespace sparsedyn
