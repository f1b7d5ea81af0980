// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>

#include "sparsedyn/narrow/closest_features.hpp"
#include "world/detailed_phase.hpp"
#include "world/drag_contacts.hpp"
#include "world/path_changes.hpp"
#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// The contact model of two convex polyhedra (§5.2, §6): the engaged pair's closest features
/// are tracked (Lin-Canny, warm-started) and its contact predicted (exact for translating
/// pairs, conservative for rotating ones, narrow/time_of_contact.hpp); a contact gets the
/// rigid impulse with rotation, restitution and Coulomb friction.
class PolyhedronContacts {
 public:
  PolyhedronContacts(WorldCore& core, SparsePhase& sparse, DetailedPhase& detailed,
                     PathChanges& changes)
      : core_(core), sparse_(sparse), detailed_(detailed), changes_(changes), drag_(core) {}

  void PredictEngagement(std::uint32_t k);
  /// Engagement k's contact event (DetailedPhase::Handle takes checkpoints and ends).
  void HandleContact(std::uint32_t k);

  /// The closest features of a and b's image at `shift` now.
  ClosestFeatures PairFeatures(std::uint32_t a, std::uint32_t b, const Vec3& shift,
                               std::optional<FeaturePair> warm) const;

 private:
  /// The collision of a and b touching with `features`: false when no point approaches.
  bool Collide(std::uint32_t a, std::uint32_t b, const ClosestFeatures& features,
               const Vec3& shift);

  WorldCore& core_;
  SparsePhase& sparse_;
  DetailedPhase& detailed_;
  PathChanges& changes_;
  DragContacts drag_;  // pairs with drag, on their true motions
};

}  // namespace sparsedyn
