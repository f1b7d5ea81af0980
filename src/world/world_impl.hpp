// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "sparsedyn/world.hpp"
#include "world/admission.hpp"
#include "world/detailed_phase.hpp"
#include "world/look_ahead.hpp"
#include "world/memory_order.hpp"
#include "world/path_changes.hpp"
#include "world/polyhedron_contacts.hpp"
#include "world/sparse_phase.hpp"
#include "world/sphere_contacts.hpp"
#include "world/sphere_polyhedron_contacts.hpp"
#include "world/static_contacts.hpp"
#include "world/wall_contacts.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// The World's parts, wired together: the shared state (WorldCore), the sparse phase, the
/// detailed phase with one contact model per pair kind and the walls, the path changes they
/// make, memory order, and the event loop that dispatches to them (world/event_loop.cpp).
class World::Impl {
 public:
  explicit Impl(const WorldSettings& settings);
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  // --- API (world.cpp) ---
  Result<BodyId> AddBody(const BodyDef& def);
  BodyState StateAt(std::uint32_t i, double t) const;
  double KineticEnergy() const;
  Vec3 Momentum() const;
  Vec3 AngularMomentum() const;
  std::size_t MemoryBytes() const;
  /// Checks the invariants at the current time (world/validation.cpp).
  Status Validate() const;
  /// The signed gap of bodies i and j now by their kinds (negative: overlap), m.
  double GapNow(std::uint32_t i, std::uint32_t j) const;
  /// Element i against the static bodies whose boxes its sphere overlaps (Validate).
  std::optional<Error> CheckAgainstStatics(std::uint32_t i) const;
  /// The signed gap of body i and wall `wall` (BoxWall's numbering) now, m.
  double WallGapNow(std::uint32_t i, int wall) const;

  // --- changes between AdvanceTo calls (changes.cpp) ---
  Status RemoveBody(BodyId id);
  Status SetVelocity(BodyId id, const Vec3& velocity);
  Status SetAngularVelocity(BodyId id, const Vec3& angular_velocity);
  Status ApplyImpulse(BodyId id, const Vec3& impulse, const Vec3& point);
  Status SetPose(BodyId id, const Vec3& position, const Eigen::Quaterniond& orientation);
  Status SetThrust(BodyId id, const Vec3& thrust, const std::vector<ThrustChange>& schedule);
  Status SetGodTrack(BodyId id, const GodDef& god);

  // --- the event loop (event_loop.cpp) ---
  Status AdvanceTo(double t);

  WorldCore core_;

 private:
  /// Rebases every path at the current time and predicts every element afresh (the first
  /// AdvanceTo, and AddBody while running when the broad phase or the fast forms must change).
  void Start();
  /// Inline in AdvanceTo's loop: out of line it was a frame and a spilled QueueTop per event.
  [[gnu::always_inline]] inline void Dispatch(const QueueTop& top, bool engagement);
  /// Body i's own event (kBodyTimer): its thrust changes as its schedule says, a god object
  /// goes on to its plan's next piece, or its drag segment's horizon ends (a drag check).
  void HandleBodyTimer(std::uint32_t i);
  /// God i's plan from now, from where it is, through `god` (checked).
  void Replan(std::uint32_t i, const GodDef& god);
  /// The element of `id`, or an error naming the call and the handle.
  Result<std::uint32_t> ElementOf(BodyId id, const char* call) const;
  /// ElementOf for changes that push a body: refused for a god object.
  Result<std::uint32_t> MovableOf(BodyId id, const char* call) const;
  /// After a change of body i's path between runs: i predicts again (and its engagements), or
  /// everything does when the change ends the fast forms of straight lines.
  void AfterChange(std::uint32_t i);
  /// Element i's meeting: target-absent, an engagement, or the collision of two spheres.
  void HandleMeeting(std::uint32_t i);
  /// Element i reaches a static body's box: engaged with it.
  void HandleStaticMeet(std::uint32_t i);
  /// AddBody of a static body (accepted).
  BodyId AddStatic(const BodyDef& def, const Admission::Accepted& accepted);
  /// The state of static s (at rest where it stands).
  BodyState StaticStateAt(std::uint32_t s) const;
  // The event loop's progress over windows of stall_event_limit events: a clock that stands
  // still (a stall) or crawls on collisions slower than the collapse guard ends AdvanceTo with
  // an error, never a hang.
  struct ProgressWindow {
    std::uint64_t events;   // in this window so far
    double start;           // the clock at its start
    std::uint64_t guarded;  // Statistics::collapse_guarded at its start
  };
  Status CheckProgress(const QueueTop& top, bool engagement, ProgressWindow& window) const;
  // "kind of body N" (or "of engagement K") for an event's messages.
  std::string DescribeEvent(const QueueTop& top, bool engagement) const;
  // The error of a contact that overlapped beyond its band at this event.
  Error BreachError(const QueueTop& top, bool engagement) const;

  DetailedPhase detailed_;  // before sparse_, whose scans read its engagements
  SparsePhase sparse_;
  PathChanges changes_;
  SphereContacts spheres_;
  PolyhedronContacts polyhedra_;
  SpherePolyhedronContacts mixed_;
  StaticContacts statics_;
  WallContacts walls_;
  MemoryOrder memory_;
  LookAhead look_ahead_;
  Admission admission_;
  bool started_ = false;
  double max_radius_ = 0.0;
  Error breach_;  // the broken invariant the World stopped at (Observers::Breached)

  friend class World;
};

}  // namespace sparsedyn
