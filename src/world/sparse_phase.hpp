// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>

#include "broadphase/all_pairs.hpp"
#include "broadphase/grid.hpp"
#include "events/calendar_queue.hpp"
#include "events/engagements.hpp"
#include "events/event.hpp"
#include "world/drag_contacts.hpp"
#include "world/meeting_scan.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

class WallContacts;

/// The sparse phase (§3-§4): each element keeps exactly one queued event, the earliest of its
/// meeting with another element (found by MeetingScan over the broad phase's candidates), its
/// container walls and its grid cell boundary. Owns the element queue and the broad phase.
class SparsePhase {
 public:
  SparsePhase(WorldCore& core, const Engagements& engagements);

  /// Builds the broad phase for the elements there are (a Grid when the container and the
  /// element sizes allow, else AllPairs), with every element inserted; nothing is predicted.
  /// Chooses the fast forms of the gas (straight lines) by what the bodies are.
  void Build(double max_radius);
  /// A body added while running (the broad phase as it is): inserted, then predicted.
  void AddElement(std::uint32_t i);
  /// Hands the grid the links in the element records, and the queue the records its refills
  /// fetch (again whenever the records moved).
  void ShareRecords();

  /// i's prediction against all its candidates.
  void PredictFull(std::uint32_t i);
  /// Both bodies of a collision predict again; the second one's prediction is superseded (the
  /// actor-absent event of §4.2, removed in place) unless it was this very meeting. Inline in
  /// the collision: a call was a frame and 36 instructions per collision of a gas.
  void PredictCollided(std::uint32_t i, std::uint32_t j) {
    // j's own prediction is superseded: the actor-absent event of §4.2, removed in place.
    const Prediction& pending = PredictionOf(j);
    if (pending.kind != EventKind::kNone &&
        !(pending.kind == EventKind::kSphereMeet && pending.target == i)) {
      ++core_.observers.stats().stale_actor_absent;
    }
    // j's neighbours, fetched while i predicts (LookAhead fetched their heads an event ago).
    if (fetch_ahead_) grid_->FetchAroundFirsts(grid_->CellOf(j));
    PredictFull(i);
    PredictFull(j);
  }
  /// i's centre leaves its cell (or, in a periodic AllPairs box, wraps): moved, then predicted
  /// against the new cells only.
  void HandleCrossing(std::uint32_t i);

  ElementQueue& queue() { return queue_; }
  const ElementQueue& queue() const { return queue_; }
  Prediction& PredictionOf(std::uint32_t e) { return queue_.PayloadOf(e); }
  const Prediction& PredictionOf(std::uint32_t e) const { return queue_.PayloadOf(e); }
  /// The broad phase: a Grid, or else AllPairs (one of them once built).
  const std::optional<Grid>& grid() const { return grid_; }
  std::optional<Grid>& grid() { return grid_; }
  const std::optional<AllPairs>& all_pairs() const { return all_pairs_; }
  /// Calls fn(j, shift) for the broad phase's candidates near i.
  template <typename Fn>
  void ForEachNeighbor(std::uint32_t i, Fn&& fn) const {
    if (grid_) {
      grid_->ForEachNeighbor(i, fn);
    } else {
      all_pairs_->ForEachNeighbor(i, fn);
    }
  }
  /// Whether the look-ahead (LookAhead) pays: a gas on a grid beyond the caches.
  bool FetchesAhead() const { return fetch_ahead_; }
  /// The walls' detailed phase, which predicts a polyhedron's contact with the walls.
  void SetWalls(WallContacts* walls) { walls_ = walls; }
  std::size_t MemoryBytes() const;

  static constexpr std::uint32_t kBatchTestMaxElements = 1u << 18;
  static constexpr std::uint32_t kFetchAheadMinElements = 40000;

 private:
  /// After i crossed into the grid cell at `place` across (axis, direction).
  void PredictAfterCrossing(std::uint32_t i, const Grid::Place& place, int axis, int direction);
  /// Lets `scan(best)` look for meetings earlier than `best`, adds walls and the cell crossing
  /// (i's cell at `place`, null without a grid) and schedules the earliest.
  template <typename Scan>
  void PredictWith(std::uint32_t i, Candidate best, const Grid::Place* place, Scan&& scan);
  Event FinishPrediction(std::uint32_t i, const Candidate& best);
  /// `event`, or i's entry into a static body's box if that comes first (kStaticMeet, the
  /// static's index kept as the prediction's target).
  Event PredictStaticEntry(std::uint32_t i, const Event& event);
  struct Crossing {  // an element's next cell crossing: when, and across which face
    double time;
    int axis;
    int direction;
  };
  Crossing PredictLinearCrossing(std::uint32_t i, const Grid::Place& place) const;
  Event FinishLinearPrediction(std::uint32_t i, const Candidate& best, const Crossing& crossing);
  double PredictWall(const Mover& mi, std::uint8_t& wall) const;
  void Schedule(std::uint32_t i, const Event& event);
  double WrapTime(std::uint32_t i) const;  // AllPairs: i's next wrap in a periodic box

  WorldCore& core_;
  const Engagements& engagements_;
  WallContacts* walls_ = nullptr;
  ElementQueue queue_;  // one slot per element, with its prediction
  std::optional<Grid> grid_;
  std::optional<AllPairs> all_pairs_;
  MeetingScan scan_;
  DragContacts drag_walls_;  // walls met by bodies with drag, on their true motions
  bool batch_tests_ = false;    // straight lines, few enough elements: TestGathered
  bool fetch_ahead_ = false;    // a gas on a grid beyond the caches: LookAhead
  bool linear_finish_ = false;  // straight lines on a grid, no walls: FinishLinearPrediction
};

}  // namespace sparsedyn
