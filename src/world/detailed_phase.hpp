// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "dynamics/rigid_collision.hpp"
#include "events/calendar_queue.hpp"
#include "events/engagements.hpp"
#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

class SphereContacts;
class PolyhedronContacts;
class SpherePolyhedronContacts;
class StaticContacts;

/// The kinds of engaged pairs, each watched by its own contact model.
enum class PairKind : std::uint8_t {
  kSpheres,     // two spheres with envelopes (the bodies are the element spheres themselves)
  kPolyhedra,   // two convex polyhedra: closest-feature tracking (§5.2)
  kSpherePolyhedron,  // a sphere and a convex polyhedron: the feature closest to the centre
  kStatic,      // a moving body and a static one (b is the static's key)
  kInert,       // two god objects: both of infinite mass, they pass through each other
};

/// The detailed phase (§3.3, §5.2): the engaged pairs, each with one slot in the engagement
/// queue holding its next detail event (a contact, the end of the engagement, or a checkpoint
/// of an unfinished prediction). The kind of the pair chooses the contact model that predicts
/// and handles its events.
class DetailedPhase {
 public:
  DetailedPhase(WorldCore& core, SparsePhase& sparse) : core_(core), sparse_(sparse) {}
  void SetModels(SphereContacts* spheres, PolyhedronContacts* polyhedra,
                 SpherePolyhedronContacts* mixed, StaticContacts* statics) {
    spheres_ = spheres;
    polyhedra_ = polyhedra;
    mixed_ = mixed;
    statics_ = statics;
  }

  PairKind KindOf(std::uint32_t a, std::uint32_t b) const;
  /// Engages a and b (their element spheres met or overlap) unless they are, and predicts.
  void Engage(std::uint32_t a, std::uint32_t b);
  /// Predicts engagement k's next detail event.
  void Predict(std::uint32_t k);
  /// Handles engagement k's detail event.
  void Handle(std::uint32_t k);
  /// Schedules engagement k's next event at `time` (none at infinity).
  void Schedule(std::uint32_t k, double time);
  /// The element spheres separate: the engagement ends and a looks for its next meeting (which
  /// may be with b again).
  void End(std::uint32_t k);
  /// After the rigid impulse of engaged a and b (their paths already changed): the collision
  /// counted and reported, then both bodies' elements and engagements predict again.
  void AfterRigidCollision(std::uint32_t a, std::uint32_t b, const ContactGeometry& contact,
                           const RigidImpulseResult& result);
  /// Predicts all of i's engagements again, except the one with `done_partner` (a pair that
  /// collided has its engagement predicted once, from its first body).
  void PredictEngagementsOf(std::uint32_t i, std::uint32_t done_partner = kNoIndex);
  /// Engages every pair whose element spheres overlap at the start.
  void EngageOverlapping();
  /// Ends every engagement.
  void Clear();

  Engagements& engagements() { return engagements_; }
  const Engagements& engagements() const { return engagements_; }
  CalendarQueue& queue() { return queue_; }
  const CalendarQueue& queue() const { return queue_; }
  std::size_t MemoryBytes() const { return queue_.MemoryBytes(); }

 private:
  /// An inert pair's only event: its element spheres separate.
  void PredictSeparation(std::uint32_t k);

  WorldCore& core_;
  SparsePhase& sparse_;
  SphereContacts* spheres_ = nullptr;
  PolyhedronContacts* polyhedra_ = nullptr;
  SpherePolyhedronContacts* mixed_ = nullptr;
  StaticContacts* statics_ = nullptr;
  Engagements engagements_;
  CalendarQueue queue_;  // one slot per engagement
};

}  // namespace sparsedyn
