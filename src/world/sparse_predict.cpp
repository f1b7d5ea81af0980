// SPDX-License-Identifier: MIT
// The sparse phase's hot path: a full prediction, or one after a cell crossing against the new
// cells only, with the straight lines' branch-free forms (one file with the scans it inlines).
#include "world/sparse_phase.hpp"

#include "world/phase_timer.hpp"
#include "world/static_leave.hpp"
#include "world/wall_contacts.hpp"

namespace sparsedyn {

// Inline in PredictWith, as Schedule below: a call of each was 1.2% and 1.6% of the
// instructions at N = 10^4 (saving and restoring registers around a few dozen instructions).
[[gnu::always_inline]] inline SparsePhase::Crossing SparsePhase::PredictLinearCrossing(
    std::uint32_t i, const Grid::Place& place) const {
  const PathStart& start = core_.bodies.paths.Start(i);
  const double now = core_.Now();
  Crossing crossing{0.0, 0, 1};
  const double dt = grid_->PredictLinearCrossing(start.p0, start.v0, place, now - start.t0,
                                                 crossing.axis, crossing.direction);
  crossing.time = MaxOf(now, EventTime(start.t0, dt));
  return crossing;
}

Event SparsePhase::FinishLinearPrediction(std::uint32_t i, const Candidate& best,
                                          const Crossing& next) {
  // FinishPrediction for straight lines in a periodic or open box (the gas): the earlier of the
  // crossing and the meeting, with selects instead of branches (which of the two comes first
  // is a coin toss after every event of a gas).
  static_cast<Candidate&>(PredictionOf(i)) = best;  // the kind is set by Schedule
  const double crossing_time = next.time;
  const int axis = next.axis, direction = next.direction;
  const bool crossing = crossing_time < best.time;
  const bool meeting = best.time != kInfinity;
  Event event;
  event.time = MinOf(crossing_time, best.time);
  const std::uint32_t keep = crossing ? 0u : ~0u;
  // crossing ? kCellCrossing (0) : meeting ? kSphereMeet (2) : kNone, as arithmetic: GCC
  // branches on the `?:` form.
  static_assert(static_cast<int>(EventKind::kCellCrossing) == 0 &&
                static_cast<int>(EventKind::kSphereMeet) == 2);
  constexpr auto kNoneKind = static_cast<std::uint32_t>(EventKind::kNone);
  event.kind = static_cast<EventKind>(
      (kNoneKind - (kNoneKind - 2u) * static_cast<std::uint32_t>(meeting)) & keep);
  event.aux = static_cast<std::uint8_t>((axis * 2 + (direction > 0 ? 1 : 0)) & ~keep);
  event.target = (best.target & keep) | (kNoIndex & ~keep);
  event.target_version = best.target_version & keep;
  return event;
}

[[gnu::always_inline]] inline void SparsePhase::Schedule(std::uint32_t i, const Event& event) {
  const PhaseTimer timer(core_.settings.profile_phases, core_.observers.stats().seconds_queue);
  PredictionOf(i).kind = event.kind;
  PredictionOf(i).aux = event.aux;
  if (event.kind == EventKind::kNone) {
    queue_.Erase(i);
  } else {
    queue_.Set(i, event.time, event.kind);
  }
}

double SparsePhase::PredictWall(const Mover& mi, std::uint8_t& wall) const {
  double best = kInfinity;
  wall = 0;
  if (!core_.Walled()) return best;
  for (int w = 0; w < 6; ++w) {
    const WallPlane plane = BoxWall(core_.settings.container, w);
    const double dt = PredictWallMeeting(mi, plane.normal, plane.offset);
    if (dt < best) {
      best = dt;
      wall = static_cast<std::uint8_t>(w);
    }
  }
  return best;
}

Event SparsePhase::FinishPrediction(std::uint32_t i, const Candidate& best) {
  static_cast<Candidate&>(PredictionOf(i)) = best;  // the kind is set by Schedule
  Event event;
  event.time = best.time;
  event.kind = best.time == kInfinity ? EventKind::kNone : EventKind::kSphereMeet;
  event.target = best.target;
  event.target_version = best.target_version;

  // Walls and the cell boundary are met by the body itself (exact and static: no envelope
  // applies), predicted from the segment start so that the time does not depend on when the
  // prediction is made (a periodic wrap then happens at the same time whichever broad phase
  // predicts it), but never before now.
  const double now = core_.Now();
  const double t0 = core_.bodies.paths.Start(i).t0;
  const Mover m0 = core_.bodies.BodyMoverOf(i, t0);
  const bool polyhedra = core_.bodies.IsPolyhedron(i);
  // A god object goes where it is driven: walls and statics do not stop it.
  const bool god = core_.bodies.IsGod(i);
  const DragMotions& drags = core_.bodies.paths.drags();
  if (!polyhedra && !god) {  // a polyhedron meets the walls after its cell crossing is known
    std::uint8_t wall = 0;
    // A body with drag: its true motion's contact, up to its check (which predicts again).
    const double wall_time =
        drags.Has(i) ? (core_.Walled() ? drag_walls_.FirstWallContact(
                                             i, std::min(event.time, drags.CheckTime(i)), wall)
                                       : kInfinity)
                     : std::max(now, EventTime(t0, PredictWall(m0, wall)));
    if (wall_time < event.time) {
      event = Event{wall_time, EventKind::kWallMeet, wall, kNoIndex, 0};
    }
  }
  int axis = 0, direction = 1;
  const double crossing_dt =
      grid_ ? grid_->PredictCrossing(m0, grid_->CellOf(i), now - t0, axis, direction)
            : all_pairs_->PredictCrossing(m0, 0, now - t0, axis, direction);
  const double crossing_time = MaxOf(now, EventTime(t0, crossing_dt));
  if (crossing_time < event.time) {
    event = Event{crossing_time, EventKind::kCellCrossing,
                  static_cast<std::uint8_t>(axis * 2 + (direction > 0 ? 1 : 0)), kNoIndex, 0};
  }
  if (!core_.bodies.statics.Empty() && !god) event = PredictStaticEntry(i, event);
  // The walls are the detailed phase's business for a polyhedron, and only up to the element's
  // next event (after which it predicts again).
  if (polyhedra && !god && core_.Walled()) event = walls_->PredictPolyhedron(i, event);
  // A change of its thrust at a given time (its schedule), a god object's next piece, and the
  // check at the end of a drag segment's horizon, are the body's own events.
  // A body held on a static's face also leaves it at a time of its own (StaticLeaveTime).
  double timer = god ? core_.bodies.gods.NextSwitch(i)
                     : std::min(core_.bodies.thrusts.NextTime(i), drags.CheckTime(i));
  if (!god && core_.bodies.paths.accelerations().OnStatic(i)) {
    timer = std::min(timer, StaticLeaveTime(core_.bodies, i));
  }
  if (timer < event.time) event = Event{MaxOf(now, timer), EventKind::kBodyTimer, 0, kNoIndex, 0};
  return event;
}

template <typename Scan>
void SparsePhase::PredictWith(std::uint32_t i, Candidate best, const Grid::Place* place,
                              Scan&& scan) {
  Event event;
  {
    const PhaseTimer timer(core_.settings.profile_phases, core_.observers.stats().seconds_sparse);
    if (linear_finish_) {
      // The crossing first: its time (or the kept meeting's, if earlier) is where the event is
      // likely to go, and that bucket's head is a cache miss beyond the caches, which the scan
      // then hides.
      const Crossing crossing = PredictLinearCrossing(i, *place);
      if (fetch_ahead_) queue_.PrefetchListOf(MinOf(crossing.time, best.time));
      scan(best);
      event = FinishLinearPrediction(i, best, crossing);
    } else {
      scan(best);
      event = FinishPrediction(i, best);
    }
  }
  Schedule(i, event);
}

void SparsePhase::PredictFull(std::uint32_t i) {
  ++core_.observers.stats().predictions;
  if (!grid_) {
    // A meeting after i's next wrap in a periodic box is never its event: the wrap predicts
    // again in full. (A Grid keeps the meeting across its crossings: no such limit there.)
    scan_.SetLimit(WrapTime(i));
    PredictWith(i, Candidate{}, nullptr, [&](Candidate& best) {
      if (core_.bodies.paths.StraightLines()) {
        scan_.ScanNeighbors(i, best, [&](auto&& fn) { all_pairs_->ForEachNeighbor(i, fn); });
      } else {
        all_pairs_->ForEachOther(i, [&](std::uint32_t j) { scan_.ConsiderImages(i, j, best); });
      }
    });
    scan_.SetLimit(kInfinity);
    return;
  }
  const Grid::Place place = grid_->PlaceOf(i);
  if (batch_tests_) {
    // Most cells are interior (no wrap, fixed offsets); the outer layer has the same test with
    // each neighbour's image shift (at N = 10^4 a seventh of the cells).
    PredictWith(i, Candidate{}, &place, [&](Candidate& best) {
      if (grid_->Interior(place)) {
        scan_.TestGatheredOf<false>(i, place, /*around=*/true, best, [&](auto&& fn) {
          grid_->ForEachGatheredAround(place, scan_.gathered(), fn);
        });
      } else {
        scan_.TestGatheredOf<true>(i, place, /*around=*/true, best, [&](auto&& fn) {
          grid_->ForEachGatheredAroundWrapped(place, scan_.gathered(), fn);
        });
      }
    });
    return;
  }
  PredictWith(i, Candidate{}, &place, [&](Candidate& best) {
    scan_.ScanNeighbors(i, best, [&](auto&& fn) { grid_->ForEachNeighbor(i, place, fn); });
  });
}

void SparsePhase::PredictAfterCrossing(std::uint32_t i, const Grid::Place& place, int axis,
                                       int direction) {
  // The meeting kept since the last full prediction bounds the meeting of every old neighbour
  // whose path has not changed since, and a neighbour whose path changed predicted then: only
  // the 9 new cells need a look (docs/sparse-phase.md#cell-crossings). Also when the kept
  // target itself changed path: its meeting is still no later than the others', and if it
  // stays i's event it comes up target-absent and i predicts in full then (§4.2, lazily: the
  // check here was a cache miss per crossing for 2% of them).
  const Candidate& kept = PredictionOf(i);
  ++core_.observers.stats().partial_predictions;
  if (batch_tests_) {
    PredictWith(i, kept, &place, [&](Candidate& best) {
      if (grid_->Interior(place)) {
        scan_.TestGatheredOf<false>(i, place, /*around=*/false, best, [&](auto&& fn) {
          grid_->ForEachGatheredNew(place, axis, direction, scan_.gathered(), fn);
        });
      } else {
        scan_.TestGatheredOf<true>(i, place, /*around=*/false, best, [&](auto&& fn) {
          grid_->ForEachGatheredNewWrapped(place, axis, direction, scan_.gathered(), fn);
        });
      }
    });
    return;
  }
  PredictWith(i, kept, &place, [&](Candidate& best) {
    scan_.ScanNeighbors(i, best, [&](auto&& fn) {
      grid_->ForEachNewNeighbor(i, place, axis, direction, fn);
    });
  });
}

}  // namespace sparsedyn
