// SPDX-License-Identifier: MIT
// The sparse phase (§3-§4): each element predicts its earliest event against its broad-phase
// candidates, the container walls and its cell boundary, and keeps exactly one queue entry.
#include "world/sparse_phase.hpp"

#include <cmath>


namespace sparsedyn {

SparsePhase::SparsePhase(WorldCore& core, const Engagements& engagements)
    : core_(core), engagements_(engagements),
      scan_(core, queue_, engagements, grid_, all_pairs_),
      drag_walls_(core) {}

void SparsePhase::Build(double max_radius) {
  const BodyStore& bodies = core_.bodies;
  const auto n = bodies.Size();
  const Container& box = core_.settings.container;
  grid_.reset();
  all_pairs_.reset();
  const bool straight_lines = bodies.paths.StraightLines();
  // The batch pair test (TestGathered) while the elements' data fit in the caches: it trades
  // mispredicted branches for instructions, a gain when the data are at hand (N = 10^4: +30%
  // collisions per CPU s) and a loss when each pair waits for main memory, where the branching
  // walk lets the processor run ahead to more misses (N = 10^6: -7%; 10^5: even). See
  // docs/lab/measurements.md#ninth-measurement.
  batch_tests_ = straight_lines && n <= kBatchTestMaxElements;

  // The grid needs a box and bounded element radii (an envelope of a body's own grows without
  // bound).
  const bool boxed = box.kind != Container::Kind::kOpen;
  // Drag's envelopes stay below their limit, which max_radius includes (World::AddBody).
  if (core_.settings.broadphase == Broadphase::kGrid && boxed && !bodies.envelopes.AnyOwn() &&
      n > 0) {
    Grid::Config config;
    config.lo = box.lo;
    config.hi = box.hi;
    config.periodic = box.kind == Container::Kind::kPeriodicBox;
    config.min_cell_size = 2 * max_radius;
    const Vec3 length = box.hi - box.lo;
    const double volume = length.prod();
    config.target_cell_size =
        std::cbrt(volume / (std::max(core_.settings.grid_cells_per_body, 1e-6) * n));
    if (Grid::Feasible(config)) grid_.emplace(config, n);
  }
  ShareRecords();
  if (!grid_) {
    AllPairs::Config config;
    config.lo = box.lo;
    config.hi = box.hi;
    config.periodic = box.kind == Container::Kind::kPeriodicBox;
    all_pairs_.emplace(config, n);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    if (grid_) grid_->Insert(i, bodies.paths.Start(i).p0);
    if (all_pairs_) all_pairs_->Insert(i, bodies.paths.Start(i).p0);
  }
  // The look-ahead (LookAhead) once the per-element data outgrow the caches: at N = 10^6 +14%
  // collisions per CPU s, at 10^5 +14%, at 6x10^4 about +10%; at 3x10^4 -5% and at 10^4 -7%,
  // where the data are at hand anyway (docs/lab/measurements.md#eleventh-measurement).
  fetch_ahead_ = straight_lines && grid_ && n >= kFetchAheadMinElements;
  linear_finish_ = straight_lines && grid_ && !core_.Walled() && bodies.statics.Empty();
}

void SparsePhase::AddElement(std::uint32_t i) {
  ShareRecords();  // the records may have moved
  const Vec3& p = core_.bodies.paths.Start(i).p0;
  if (grid_) grid_->Insert(i, p);
  if (all_pairs_) all_pairs_->Insert(i, p);
  PredictFull(i);
}

void SparsePhase::ShareRecords() {
  BigVector<ElementPaths::Record>& records = core_.bodies.paths.Records();
  if (records.empty()) return;
  if (grid_) {
    grid_->UseLinks(&records.data()->links, StrideShiftOf<ElementPaths::Record>(),
                    records.size());
  }
  queue_.FetchWithRefills(records.data(), StrideShiftOf<ElementPaths::Record>());
}

std::size_t SparsePhase::MemoryBytes() const {
  std::size_t bytes = queue_.MemoryBytes() + scan_.MemoryBytes();
  if (grid_) bytes += grid_->MemoryBytes();
  if (all_pairs_) bytes += all_pairs_->MemoryBytes();
  return bytes;
}

void SparsePhase::HandleCrossing(std::uint32_t i) {
  const Prediction event = PredictionOf(i);
  const int axis = event.CrossingAxis();
  const int direction = event.CrossingDirection();
  ElementPaths& paths = core_.bodies.paths;
  // A periodic wrap shifts the position: the same motion, seen in the box.
  if (!grid_) {
    paths.ShiftStart(i, all_pairs_->Move(i, axis, direction));
    PredictFull(i);
    return;
  }
  Vec3 shift;
  const Grid::Place place = grid_->Move(i, axis, direction, shift);
  paths.ShiftStart(i, shift);
  PredictAfterCrossing(i, place, axis, direction);
}

double SparsePhase::WrapTime(std::uint32_t i) const {
  // As FinishPrediction predicts the crossing (from the segment start, never before now).
  const double t0 = core_.bodies.paths.Start(i).t0;
  int axis = 0, direction = 1;
  const double dt = all_pairs_->PredictCrossing(core_.bodies.BodyMoverOf(i, t0), 0,
                                                core_.Now() - t0, axis, direction);
  return MaxOf(core_.Now(), EventTime(t0, dt));
}

Event SparsePhase::PredictStaticEntry(std::uint32_t i, const Event& event) {
  const double now = core_.Now();
  const StaticBodies& statics = core_.bodies.statics;
  const StaticTree::Entry entry = statics.tree().FirstEntry(
      core_.bodies.MoverOf(i, now), event.time - now,
      [&](std::uint32_t s) { return engagements_.Engaged(i, StaticBodies::KeyOf(s)); });
  if (entry.index == kNoIndex) return event;
  const double time = MaxOf(now, EventTime(now, entry.dt));
  if (!(time < event.time)) return event;
  PredictionOf(i).target = entry.index;
  return Event{time, EventKind::kStaticMeet, 0, entry.index, 0};
}

}  // namespace sparsedyn
