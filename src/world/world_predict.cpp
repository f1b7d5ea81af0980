// SPDX-License-Identifier: MIT
// The sparse phase (§3-§4): each element predicts its earliest event against its broad-phase
// candidates, the container walls and its cell boundary, and keeps exactly one queue entry.
#include <array>
#include <cmath>
#include <optional>

#include "world/world_impl.hpp"

namespace sparsedyn {
namespace {

// The time span a scan may skip a pair for: up to `limit` (the earliest event found so far, or
// the scan's limit) from the pair's `reference` time, widened by a few ulps so that the meetings
// skipped are certainly later (ties with the limit still count).
double SkipSpan(double limit, double reference) {
  return (limit - reference) * (1 + 0x1p-40) + 0x1p-50 * std::abs(limit);
}

}  // namespace

Mover World::Impl::MoverOf(std::uint32_t i, double t) const {
  if (has_envelopes_) return MoverAt(PathOf(i), Radius(i), envelope_[i], t);
  return MoverAt(PathOf(i), Radius(i), t);
}

Mover World::Impl::BodyMoverOf(std::uint32_t i, double t) const {
  return MoverAt(PathOf(i), Radius(i), t);
}

void World::Impl::ConsiderMeeting(std::uint32_t i, std::uint32_t j, const Vec3& shift,
                                  Candidate& best) {
  if (EngagedPair(i, j)) return;
  const double reference = PairReference(i, j);
  const Mover a = MoverOf(i, reference), b = MoverOf(j, reference);
  // The bound only where ConsiderImage can use it (a limit to skip by).
  const bool bounded = MinOf(best.time, scan_limit_) != kInfinity && !OnStraightLines(a, b);
  const std::optional<ApartBound> bound =
      bounded ? std::optional<ApartBound>(std::in_place, a, b) : std::nullopt;
  ConsiderImage(a, b, bound, reference, j, shift, best);
}

void World::Impl::ConsiderImages(std::uint32_t i, std::uint32_t j, Candidate& best) {
  // ConsiderMeeting for every image AllPairs sees j at, the movers worked out once. The
  // nearest image first: its meeting, if any, is the likeliest to be the earliest, and the
  // sooner `best` is finite, the more of the other 26 the distance bound skips. The result
  // does not depend on the order (Offer keeps the earliest, ties to the lower index, and a
  // skipped image cannot meet before `best`).
  if (EngagedPair(i, j)) return;
  const double reference = PairReference(i, j);
  const Mover a = MoverOf(i, reference), b = MoverOf(j, reference);
  const std::optional<ApartBound> bound =
      OnStraightLines(a, b) ? std::nullopt : std::optional<ApartBound>(std::in_place, a, b);
  const std::vector<Vec3>& shifts = all_pairs_->ImageShifts();
  const std::size_t nearest = all_pairs_->NearestImage(b.p - a.p);
  ConsiderImage(a, b, bound, reference, j, shifts[nearest], best);
  if (shifts.size() == 1) return;
  // The other 26 images by slabs: an image whose shift along some axis leaves the pair apart
  // along that axis alone (ApartBound::ApartAlongEach, 9 tests for all 26) is skipped without a
  // test of its own. The limit only falls as images are tested, so the slabs stay apart.
  ApartBound::SlabVerdicts apart{};  // [axis][step along it]
  const double limit = MinOf(best.time, scan_limit_);
  if (bound && limit != kInfinity) {
    apart = bound->ApartAlongEach(all_pairs_->StepShifts(), all_pairs_->LargestShift(),
                                  SkipSpan(limit, reference));
    // All 26 at once, the common case for a pair across the box.
    if (OtherImagesApart(apart, nearest)) {
      stats_.pair_tests += shifts.size() - 1;
      stats_.pairs_skipped += shifts.size() - 1;
      return;
    }
  }
  for (std::size_t r = 0; r < shifts.size(); ++r) {
    if (r == nearest) continue;
    if (ImageApart(apart, r)) {
      ++stats_.pair_tests;
      ++stats_.pairs_skipped;
      continue;
    }
    ConsiderImage(a, b, bound, reference, j, shifts[r], best);
  }
}

bool World::Impl::EngagedPair(std::uint32_t i, std::uint32_t j) const {
  // An engaged pair is tracked by its engagement, not by the sparse phase.
  return EngagesOnMeet() && engagements_.HasAny(i) && engagements_.Engaged(i, j);
}

double World::Impl::PairReference(std::uint32_t i, std::uint32_t j) const {
  // Predict from the later of the two segment starts, not from `now`: the result then depends
  // only on the two paths, so a prediction kept across cell crossings, or made by another broad
  // phase at another time, is bit-identical (determinism across broad phases). Not for engaging
  // elements: their spheres may have met and separated since, on unchanged paths, and that past
  // meeting must not come back as one now.
  return EngagesOnMeet() ? now_ : std::max(starts_[i].t0, starts_[j].t0);
}

void World::Impl::ConsiderImage(const Mover& a, const Mover& b,
                                const std::optional<ApartBound>& bound, double reference,
                                std::uint32_t j, const Vec3& shift, Candidate& best) {
  ++stats_.pair_tests;
  // A pair on curved paths or with envelopes costs a root isolation (microseconds). A meeting
  // after the earliest event found so far (or after the scan's limit) cannot become i's event:
  // skip the pairs whose distance keeps them apart that long (`bound`, the pair's ApartBound;
  // none on straight lines, or where no limit applied when the pair was taken up).
  const double limit = MinOf(best.time, scan_limit_);
  if (limit != kInfinity && bound) {
    if (bound->Within(shift, SkipSpan(limit, reference))) {
      ++stats_.pairs_skipped;
      return;
    }
  }
  const double dt = PredictMeeting(a, b, shift);
  if (dt != kInfinity) Offer(best, std::max(now_, EventTime(reference, dt)), j);
}

double World::Impl::WrapTime(std::uint32_t i) const {
  // As FinishPrediction predicts the crossing (from the segment start, never before now).
  const double t0 = starts_[i].t0;
  int axis = 0, direction = 1;
  const double dt = all_pairs_->PredictCrossing(BodyMoverOf(i, t0), 0, now_ - t0, axis, direction);
  return MaxOf(now_, EventTime(t0, dt));
}

void World::Impl::Offer(Candidate& best, double t, std::uint32_t j) const {
  // Ties go to the lower target index so that both broad phases choose the same event.
  if (t < best.time || (t == best.time && j < best.target)) {
    best = Candidate{t, j, PredictionOf(j).version};
  }
}

namespace {

// The straight-line pair test's relative position and velocity of j's image (j's position plus
// `shift`) seen from i, both moved to the later of their segment starts (MaxOf: which started
// later is a coin toss). x and y as one SSE2 pair, z apart; every sum as ConsiderMeeting's
// movers make it (x + 0 v = x up to the sign of a zero coordinate, which no dot product of the
// test can see), so both scans give PredictMeeting's numbers.
struct RelativeMotion {
  Eigen::Vector2d dp_xy, dv_xy;
  double dp_z, dv_z;
};
// Both positions at the later segment start: i's at (a_xy, a_z), j's at (b_xy, b_z).
struct LaterStartPositions {
  Eigen::Vector2d a_xy, b_xy;
  double a_z, b_z;
};
[[gnu::always_inline]] inline LaterStartPositions AtLaterStart(const PathStart& pi,
                                                               const PathStart& pj) {
  const double reference = MaxOf(pi.t0, pj.t0);
  const double since_i = reference - pi.t0, since_j = reference - pj.t0;
  return {pi.p0.head<2>() + since_i * pi.v0.head<2>(), pj.p0.head<2>() + since_j * pj.v0.head<2>(),
          pi.p0[2] + since_i * pi.v0[2], pj.p0[2] + since_j * pj.v0[2]};
}
[[gnu::always_inline]] inline RelativeMotion RelativeMotionOf(const PathStart& pi,
                                                              const PathStart& pj,
                                                              const Vec3& shift) {
  const LaterStartPositions at = AtLaterStart(pi, pj);
  return {(at.b_xy + shift.head<2>()) - at.a_xy, pj.v0.head<2>() - pi.v0.head<2>(),
          (at.b_z + shift[2]) - at.a_z, pj.v0[2] - pi.v0[2]};
}
// The same without a shift (interior cells): adding a zero shift changes only the sign of a
// zero coordinate, which no test of the motion can see, so the decisions are the same.
[[gnu::always_inline]] inline RelativeMotion RelativeMotionOf(const PathStart& pi,
                                                              const PathStart& pj) {
  const LaterStartPositions at = AtLaterStart(pi, pj);
  return {at.b_xy - at.a_xy, pj.v0.head<2>() - pi.v0.head<2>(), at.b_z - at.a_z,
          pj.v0[2] - pi.v0[2]};
}

}  // namespace

template <typename VisitNeighbors>
void World::Impl::ScanNeighbors(std::uint32_t i, Candidate& best, VisitNeighbors&& visit) {
  if (!straight_lines_) {
    visit([&](std::uint32_t j, const Vec3& shift) { ConsiderMeeting(i, j, shift, best); });
    return;
  }
  // The hot path: straight lines, no envelopes, no engagements: the same numbers as
  // ConsiderMeeting (MoverOf + PredictMeeting), with the actor's data read once. Inlined into
  // the cell walk: a call per pair cost a fifth of the test.
  const PathStart pi = starts_[i];
  // One material (a gas): no per-body look-up, which is a cache miss at N = 10^6.
  const bool one_material = materials_.size() == 1;
  const double ri = one_material ? materials_[0].radius : Radius(i);
  std::uint64_t tests = 0;
  visit([&](std::uint32_t j, const Vec3& shift) [[gnu::always_inline]] {
    ++tests;
    const RelativeMotion m = RelativeMotionOf(pi, starts_[j], shift);
    const auto reach = [&] { return ri + (one_material ? ri : Radius(j)); };
    const double dt = LinearMeetingRoot(m.dp_xy, m.dp_z, m.dv_xy, m.dv_z, reach);
    if (dt != kInfinity) OfferLinearMeeting(pi, j, shift, reach(), dt, best);
  });
  stats_.pair_tests += tests;
}

template <bool kOneMaterial, bool kWrapped, typename Gather>
void World::Impl::TestGathered(std::uint32_t i, const Grid::Place& place, bool around,
                               Candidate& best, Gather&& gather) {
  // ScanNeighbors' straight-line test, the same numbers, over the elements a Grid gather
  // visits, without a branch on the data: whether a pair approaches, and then whether it passes
  // wide, are coin tosses in a gas, and a mispredicted branch costs more than testing both.
  // The pairs that meet are noted (in the gather's used entries) and have their root computed
  // and certified after the visit, so that the visit makes no call and keeps i's data in
  // registers. When the gather is `around` i's cell, i itself is among them (once: a grid has
  // at least 3 cells per axis): with dp = dv = 0 it does not approach.
  const PathStart pi = starts_[i];
  const double ri = kOneMaterial ? materials_[0].radius : Radius(i);
  const ElementStart* starts = starts_.data();
  const std::uint32_t* material = material_.data();
  const Material* materials = materials_.data();
  std::uint32_t visited = 0, hits = 0;
  gather([&](std::uint32_t j, const Vec3& shift) [[gnu::always_inline]] {
    ++visited;
    // One material (a gas): no per-body look-up, a cache miss per pair at N = 10^6.
    const double reach = ri + (kOneMaterial ? ri : materials[material[j]].radius);
    const RelativeMotion m =
        kWrapped ? RelativeMotionOf(pi, starts[j], shift) : RelativeMotionOf(pi, starts[j]);
    gathered_[hits] = j;  // an entry the gather is done with (hits < visited)
    hits += LinearMeetingFound(m.dp_xy, m.dp_z, m.dv_xy, m.dv_z, reach) ? 1u : 0u;
  });
  stats_.pair_tests += visited - (around ? 1u : 0u);
  for (std::uint32_t h = 0; h < hits; ++h) {
    const std::uint32_t j = gathered_[h];
    const double reach = ri + (kOneMaterial ? ri : Radius(j));
    // The shift the visit had for j (interior cells: none).
    const Vec3 shift = kWrapped ? grid_->ImageShift(place, j) : Vec3::Zero();
    const RelativeMotion m = RelativeMotionOf(pi, starts_[j], shift);
    const double dt =
        LinearMeetingRoot(m.dp_xy, m.dp_z, m.dv_xy, m.dv_z, [reach] { return reach; });
    OfferLinearMeeting(pi, j, shift, reach, dt, best);
  }
}

template <bool kWrapped, typename Gather>
void World::Impl::TestGatheredOf(std::uint32_t i, const Grid::Place& place, bool around,
                                 Candidate& best, Gather&& gather) {
  if (materials_.size() == 1) {
    TestGathered<true, kWrapped>(i, place, around, best, gather);
  } else {
    TestGathered<false, kWrapped>(i, place, around, best, gather);
  }
}

void World::Impl::OfferLinearMeeting(const PathStart& pi, std::uint32_t j, const Vec3& shift,
                                     double reach, double dt, Candidate& best) {
  // The positions exactly as ConsiderMeeting's movers have them, for the certification.
  const PathStart& pj = starts_[j];
  const double reference = std::max(pi.t0, pj.t0);
  const Vec3 pa = pi.t0 == reference ? pi.p0 : Vec3(pi.p0 + (reference - pi.t0) * pi.v0);
  const Vec3 pb = pj.t0 == reference ? pj.p0 : Vec3(pj.p0 + (reference - pj.t0) * pj.v0);
  dt = FinishLinearMeeting(pa, pi.v0, pb, pj.v0, shift, reach, dt);
  if (dt != kInfinity) Offer(best, MaxOf(now_, EventTime(reference, dt)), j);
}

double World::Impl::PredictWall(const Mover& mi, std::uint8_t& wall) const {
  double best = kInfinity;
  wall = 0;
  if (settings_.container.kind != Container::Kind::kWalledBox) return best;
  for (int w = 0; w < 6; ++w) {
    const WallPlane plane = BoxWall(settings_.container, w);
    const double dt = PredictWallMeeting(mi, plane.normal, plane.offset);
    if (dt < best) {
      best = dt;
      wall = static_cast<std::uint8_t>(w);
    }
  }
  return best;
}

Event World::Impl::FinishPrediction(std::uint32_t i, const Candidate& best) {
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
  const PathStart& start = starts_[i];
  const double t0 = start.t0;
  const Mover m0 = BodyMoverOf(i, t0);
  if (!polyhedra_) {  // a polyhedron meets the walls after its cell crossing is known
    std::uint8_t wall = 0;
    const double wall_time = std::max(now_, EventTime(t0, PredictWall(m0, wall)));
    if (wall_time < event.time) {
      event = Event{wall_time, EventKind::kWallMeet, wall, kNoIndex, 0};
    }
  }
  int axis = 0, direction = 1;
  const double crossing_dt =
      grid_ ? grid_->PredictCrossing(m0, grid_->CellOf(i), now_ - t0, axis, direction)
            : all_pairs_->PredictCrossing(m0, 0, now_ - t0, axis, direction);
  const double crossing_time = MaxOf(now_, EventTime(t0, crossing_dt));
  if (crossing_time < event.time) {
    event = Event{crossing_time, EventKind::kCellCrossing,
                  static_cast<std::uint8_t>(axis * 2 + (direction > 0 ? 1 : 0)), kNoIndex, 0};
  }
  // The walls are the detailed phase's business for a polyhedron, and only up to the element's
  // next event (after which it predicts again).
  if (polyhedra_ && settings_.container.kind == Container::Kind::kWalledBox) {
    event = PredictPolyhedronWalls(i, event);
  }
  return event;
}

// Inline in PredictWith, as Schedule below: a call of each was 1.2% and 1.6% of the
// instructions at N = 10^4 (saving and restoring registers around a few dozen instructions).
[[gnu::always_inline]] inline World::Impl::Crossing World::Impl::PredictLinearCrossing(
    std::uint32_t i, const Grid::Place& place) const {
  const PathStart& start = starts_[i];
  Crossing crossing{0.0, 0, 1};
  const double dt = grid_->PredictLinearCrossing(start.p0, start.v0, place, now_ - start.t0,
                                                 crossing.axis, crossing.direction);
  crossing.time = MaxOf(now_, EventTime(start.t0, dt));
  return crossing;
}

Event World::Impl::FinishLinearPrediction(std::uint32_t i, const Candidate& best,
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
  // crossing ? kCellCrossing (0) : meeting ? kSphereMeet (2) : kNone (4), as arithmetic: GCC
  // branches on the `?:` form.
  static_assert(static_cast<int>(EventKind::kCellCrossing) == 0 &&
                static_cast<int>(EventKind::kSphereMeet) == 2 &&
                static_cast<int>(EventKind::kNone) == 4);
  event.kind = static_cast<EventKind>((4u - 2u * static_cast<std::uint32_t>(meeting)) & keep);
  event.aux = static_cast<std::uint8_t>((axis * 2 + (direction > 0 ? 1 : 0)) & ~keep);
  event.target = (best.target & keep) | (kNoIndex & ~keep);
  event.target_version = best.target_version & keep;
  return event;
}

[[gnu::always_inline]] inline void World::Impl::Schedule(std::uint32_t i, const Event& event) {
  const PhaseTimer timer(settings_.profile_phases, stats_.seconds_queue);
  PredictionOf(i).kind = event.kind;
  PredictionOf(i).aux = event.aux;
  if (event.kind == EventKind::kNone) {
    queue_.Erase(i);
  } else {
    queue_.Set(i, event.time, event.kind);
  }
}

template <typename Scan>
void World::Impl::PredictWith(std::uint32_t i, Candidate best, const Grid::Place* place,
                              Scan&& scan) {
  Event event;
  {
    const PhaseTimer timer(settings_.profile_phases, stats_.seconds_sparse);
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

void World::Impl::PredictFull(std::uint32_t i) {
  ++stats_.predictions;
  if (!grid_) {
    // A meeting after i's next wrap in a periodic box is never its event: the wrap predicts
    // again in full. (A Grid keeps the meeting across its crossings: no such limit there.)
    scan_limit_ = WrapTime(i);
    PredictWith(i, Candidate{}, nullptr, [&](Candidate& best) {
      if (straight_lines_) {
        ScanNeighbors(i, best, [&](auto&& fn) { all_pairs_->ForEachNeighbor(i, fn); });
      } else {
        all_pairs_->ForEachOther(i, [&](std::uint32_t j) { ConsiderImages(i, j, best); });
      }
    });
    scan_limit_ = kInfinity;
    return;
  }
  const Grid::Place place = grid_->PlaceOf(i);
  if (batch_tests_) {
    // Most cells are interior (no wrap, fixed offsets); the outer layer has the same test with
    // each neighbour's image shift (at N = 10^4 a seventh of the cells).
    PredictWith(i, Candidate{}, &place, [&](Candidate& best) {
      if (grid_->Interior(place)) {
        TestGatheredOf<false>(i, place, /*around=*/true, best, [&](auto&& fn) {
          grid_->ForEachGatheredAround(place, gathered_, fn);
        });
      } else {
        TestGatheredOf<true>(i, place, /*around=*/true, best, [&](auto&& fn) {
          grid_->ForEachGatheredAroundWrapped(place, gathered_, fn);
        });
      }
    });
    return;
  }
  PredictWith(i, Candidate{}, &place, [&](Candidate& best) {
    ScanNeighbors(i, best, [&](auto&& fn) { grid_->ForEachNeighbor(i, place, fn); });
  });
}

void World::Impl::PredictAfterCrossing(std::uint32_t i, const Grid::Place& place, int axis,
                                       int direction) {
  // The meeting kept since the last full prediction bounds the meeting of every old neighbour
  // whose path has not changed since, and a neighbour whose path changed predicted then: only
  // the 9 new cells need a look (docs/sparse-phase.md#cell-crossings). Also when the kept
  // target itself changed path: its meeting is still no later than the others', and if it
  // stays i's event it comes up target-absent and i predicts in full then (§4.2, lazily: the
  // check here was a cache miss per crossing for 2% of them).
  const Candidate& kept = PredictionOf(i);
  ++stats_.partial_predictions;
  if (batch_tests_) {
    PredictWith(i, kept, &place, [&](Candidate& best) {
      if (grid_->Interior(place)) {
        TestGatheredOf<false>(i, place, /*around=*/false, best, [&](auto&& fn) {
          grid_->ForEachGatheredNew(place, axis, direction, gathered_, fn);
        });
      } else {
        TestGatheredOf<true>(i, place, /*around=*/false, best, [&](auto&& fn) {
          grid_->ForEachGatheredNewWrapped(place, axis, direction, gathered_, fn);
        });
      }
    });
    return;
  }
  PredictWith(i, kept, &place, [&](Candidate& best) {
    ScanNeighbors(i, best,
                  [&](auto&& fn) { grid_->ForEachNewNeighbor(i, place, axis, direction, fn); });
  });
}

void World::Impl::PredictEngagement(std::uint32_t k) {
  if (polyhedra_) {
    PredictPolyhedralEngagement(k);
    return;
  }
  Engagements::Engagement& e = engagements_[k];
  // The periodic image of b nearest to a (zero shift outside periodic boxes).
  const Vec3 d = PathOf(e.b).PositionAt(now_) - PathOf(e.a).PositionAt(now_);
  const Vec3 shift = MinimumImage(d) - d;
  // Contact of the bodies themselves (the detailed phase for spheres) or separation of the
  // element spheres, whichever comes first.
  const double contact = PredictMeeting(BodyMoverOf(e.a, now_), BodyMoverOf(e.b, now_), shift);
  const double separation = PredictSeparation(MoverOf(e.a, now_), MoverOf(e.b, now_), shift);
  e.contact_next = contact <= separation;
  const double dt = std::min(contact, separation);
  if (dt == kInfinity) {
    engagement_queue_.Erase(k);
  } else {
    engagement_queue_.Set(k, EventTime(now_, dt), EventKind::kEngagement);
  }
}

void World::Impl::PredictEngagementsOf(std::uint32_t i, std::uint32_t done_partner) {
  if (!EngagesOnMeet() || !engagements_.HasAny(i)) return;
  for (const std::uint32_t k : engagements_.Of(i)) {
    const Engagements::Engagement& e = engagements_[k];
    if (e.a != done_partner && e.b != done_partner) PredictEngagement(k);
  }
}

}  // namespace sparsedyn
