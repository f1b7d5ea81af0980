// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "narrow/point_features.hpp"
#include "world/detailed_phase.hpp"
#include "world/drag_contacts.hpp"
#include "world/path_changes.hpp"
#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// The contact model of a sphere and a convex polyhedron (issue #36): the polyhedron's feature
/// closest to the sphere's centre is tracked (narrow/point_features.hpp, warm-started) and the
/// contact predicted by narrow/sphere_contact.hpp (exact while the polyhedron does not rotate,
/// conservative while it does); a contact gets the rigid impulse at the one contact point, with
/// both bodies' rotation (the sphere solid, I = 2/5 m r^2), restitution and Coulomb friction.
class SpherePolyhedronContacts {
 public:
  SpherePolyhedronContacts(WorldCore& core, SparsePhase& sparse, DetailedPhase& detailed,
                           PathChanges& changes)
      : core_(core), sparse_(sparse), detailed_(detailed), changes_(changes), drag_(core) {}

  void PredictEngagement(std::uint32_t k);
  /// Engagement k's contact event (DetailedPhase::Handle takes checkpoints and ends).
  void HandleContact(std::uint32_t k);

  /// The closest feature of polyhedron p to sphere s's centre (its image nearest to p) now.
  PointClosest Closest(std::uint32_t p, std::uint32_t s, std::optional<FeatureId> warm) const;

 private:
  /// The engagement's polyhedron and sphere.
  struct Pair {
    std::uint32_t polyhedron;
    std::uint32_t sphere;
  };
  Pair PairOf(std::uint32_t k) const;
  /// The collision of p and s touching at `closest`: false when no point approaches.
  bool Collide(const Pair& pair, const PointClosest& closest);

  WorldCore& core_;
  SparsePhase& sparse_;
  DetailedPhase& detailed_;
  PathChanges& changes_;
  DragContacts drag_;  // pairs with drag, on their true motions
};

}  // namespace sparsedyn
