// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "world/detailed_phase.hpp"
#include "world/drag_contacts.hpp"
#include "world/path_changes.hpp"
#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// The contact model of two spheres (§6): a frictionless impulse along the line of centres
/// with the product of the restitutions and the collapse guard. Spheres without envelopes
/// collide when their elements meet (the sparse phase's meeting is the contact); spheres with
/// envelopes are engaged first, and the engagement predicts the contact of the bodies.
class SphereContacts {
 public:
  SphereContacts(WorldCore& core, SparsePhase& sparse, DetailedPhase& detailed,
                 PathChanges& changes)
      : core_(core), sparse_(sparse), detailed_(detailed), changes_(changes), drag_(core) {}

  /// Whether i and j touch (within the tolerance) and approach each other now; sets the
  /// normal from i to j and the gap (negative: overlap).
  bool TouchingAndApproaching(std::uint32_t i, std::uint32_t j, Vec3& normal, double& gap) const;
  /// The collision of touching, approaching i and j: the impulse, then both predict again.
  void Collide(std::uint32_t i, std::uint32_t j, const Vec3& normal, double gap);
  /// Engagement k of two spheres: their contact, or the separation of their elements.
  void PredictEngagement(std::uint32_t k);
  /// Engagement k's contact event (DetailedPhase::Handle takes checkpoints and ends).
  void HandleContact(std::uint32_t k);

 private:
  /// Collide() for spheres that rub (both have friction): with their spins.
  void CollideWithFriction(std::uint32_t i, std::uint32_t j, const Vec3& normal, double gap);

  WorldCore& core_;
  SparsePhase& sparse_;
  DetailedPhase& detailed_;
  PathChanges& changes_;
  DragContacts drag_;  // the contact of an engaged pair with drag, on the true motions
};

}  // namespace sparsedyn
