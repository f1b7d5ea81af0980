// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <cstdint>
#include <array>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "broadphase/all_pairs.hpp"
#include "broadphase/grid.hpp"
#include "events/calendar_queue.hpp"
#include "events/engagements.hpp"
#include "events/event.hpp"
#include "events/heap_queue.hpp"
#include "motion/path.hpp"
#include "sparse/meeting.hpp"
#include "sparsedyn/world.hpp"
#include "world/overlap_index.hpp"

namespace sparsedyn {

/// The World's state and event loop. Split over world.cpp (API, input checks, start-up),
/// world_predict.cpp (the sparse phase: predictions) and world_loop.cpp (the dispatcher and the
/// event handlers).
class World::Impl {
 public:
  explicit Impl(const WorldSettings& settings);

  // --- API (world.cpp) ---
  Result<BodyId> AddBody(const BodyDef& def);
  BodyState StateAt(std::uint32_t i, double t) const;
  double KineticEnergy() const;
  Vec3 Momentum() const;
  Status Validate() const;
  std::size_t MemoryBytes() const;

  // --- event loop (world_loop.cpp) ---
  Status AdvanceTo(double t);

  WorldSettings settings_;
  Statistics stats_;
  std::function<void(const CollisionEvent&)> on_collision_;
  std::function<void(const MotionSegment&)> on_segment_;
  double now_ = 0.0;
  double max_penetration_ = 0.0;

  // Per-element state (structure of arrays, indexed by body index).
  std::vector<PathStart> starts_;            // the path of body i is PathOf(i)
  std::vector<Vec3> acceleration_;          // per body once own_accelerations_
  Vec3 uniform_acceleration_ = Vec3::Zero();  // gravity: every body's, until one has a thrust
  bool own_accelerations_ = false;
  struct Material {                         // what bodies share: a gas has one
    double radius;
    double inv_mass;
    double restitution;
  };
  std::vector<Material> materials_;
  std::vector<std::uint32_t> material_;     // per body, into materials_
  std::map<std::array<double, 3>, std::uint32_t> material_index_;  // (r, 1/m, e) -> material

  Path PathOf(std::uint32_t i) const {
    const PathStart& s = starts_[i];
    return Path{s.p0, s.v0, own_accelerations_ ? acceleration_[i] : uniform_acceleration_, s.t0};
  }
  double Radius(std::uint32_t i) const { return materials_[material_[i]].radius; }
  double InvMass(std::uint32_t i) const { return materials_[material_[i]].inv_mass; }
  double Restitution(std::uint32_t i) const { return materials_[material_[i]].restitution; }
  std::vector<Envelope> envelope_;          // empty unless some body has an envelope
  std::vector<std::uint32_t> version_;      // path changes so far
  std::vector<PendingEvent> event_;         // each element's one outstanding prediction (§4)
  struct Candidate {                        // the earliest meeting found by the last prediction
    double time = kInfinity;
    std::uint32_t target = kNoIndex;
    std::uint32_t target_version = 0;
  };
  std::vector<Candidate> candidate_;
  // Internal indices follow space (Reorder); the public BodyId index is the order of AddBody.
  std::vector<std::uint32_t> public_of_;    // internal index -> public index
  std::vector<std::uint32_t> internal_of_;  // public index -> internal index
  std::uint64_t events_since_reorder_ = 0;

  bool started_ = false;
  bool has_envelopes_ = false;
  bool straight_lines_ = false;  // no envelopes and no acceleration: the fast meeting test
  double max_radius_ = 0.0;
  std::optional<Grid> grid_;
  std::optional<AllPairs> all_pairs_;
  CalendarQueue queue_;             // one slot per element
  CalendarQueue engagement_queue_;  // one slot per engagement
  Engagements engagements_;
  OverlapIndex overlap_index_;  // bodies added before the start, for AddBody's overlap check

 private:
  // --- start-up and checks (world.cpp) ---
  void Start();
  std::optional<std::uint32_t> FindOverlap(const Vec3& p, double radius) const;
  Vec3 MinimumImage(Vec3 d) const;
  Vec3 WrapIntoBox(Vec3 p) const;

  // --- memory order (world_reorder.cpp) ---
  void MaybeReorder();
  void Reorder();
  BodyId PublicId(std::uint32_t i) const { return BodyId{public_of_[i], 0}; }

  // --- predictions (world_predict.cpp) ---
  Mover MoverOf(std::uint32_t i, double t) const;
  Mover BodyMoverOf(std::uint32_t i, double t) const;  // the body itself, without envelope
  void PredictFull(std::uint32_t i);
  void PredictAfterCrossing(std::uint32_t i, int axis, int direction);
  template <typename Broadphase>
  void PredictWith(const Broadphase& broadphase, std::uint32_t i);
  template <typename Broadphase>
  void PredictNewCellsWith(const Broadphase& broadphase, std::uint32_t i, int axis, int direction);
  void ConsiderMeeting(std::uint32_t i, std::uint32_t j, const Vec3& shift, Candidate& best);
  void Offer(Candidate& best, double t, std::uint32_t j) const;  // keeps the earlier meeting
  template <typename VisitNeighbors>
  void ScanNeighbors(std::uint32_t i, Candidate& best, VisitNeighbors&& visit);
  Event FinishPrediction(std::uint32_t i, const Candidate& best);
  double PredictWall(const Mover& mi, std::uint8_t& wall) const;
  void Schedule(std::uint32_t i, const Event& event);
  void PredictEngagement(std::uint32_t k);
  void PredictEngagementsOf(std::uint32_t i);

  // --- handlers (world_loop.cpp) ---
  void Dispatch(const QueueTop& top, bool engagement);
  void HandleSphereMeet(std::uint32_t i);
  void HandleWallMeet(std::uint32_t i);
  void HandleCellCrossing(std::uint32_t i);
  void HandleEngagement(std::uint32_t k);
  void Collide(std::uint32_t i, std::uint32_t j, const Vec3& normal, double gap);
  void SetVelocity(std::uint32_t i, const Vec3& v);
  bool TouchingAndApproaching(std::uint32_t i, std::uint32_t j, Vec3& normal, double& gap) const;
  void NotePenetration(double gap);

  friend class World;
};

/// Adds the seconds of its lifetime to `sink` when `enabled` (WorldSettings::profile_phases);
/// costs nothing but a branch otherwise.
class PhaseTimer {
 public:
  PhaseTimer(bool enabled, double& sink) : sink_(enabled ? &sink : nullptr) {
    if (sink_ != nullptr) start_ = std::chrono::steady_clock::now();
  }
  ~PhaseTimer() {
    if (sink_ != nullptr) {
      *sink_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double* sink_;
  std::chrono::steady_clock::time_point start_;
};

/// Wall planes of a walled box: inward unit normal n and offset d (n.x >= d inside).
struct WallPlane {
  Vec3 normal;
  double offset;
};
WallPlane BoxWall(const Container& box, int wall);

}  // namespace sparsedyn
