// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>

#include "base/huge_pages.hpp"
#include "broadphase/all_pairs.hpp"
#include "broadphase/grid.hpp"
#include "events/calendar_queue.hpp"
#include "events/engagements.hpp"
#include "events/event.hpp"
#include "math/event_time.hpp"
#include "sparse/meeting.hpp"
#include "world/drag_contacts.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// The earliest meeting found by a prediction: when, with which element, and that element's
/// version then (so that a meeting whose target changed path since is recognised, §4.2).
struct Candidate {
  double time = kInfinity;
  std::uint32_t target = kNoIndex;
  std::uint32_t target_version = 0;
};

/// Each element's one outstanding prediction (§4): the kind of its queued event (the queue
/// holds the time) and the meeting its last prediction found, which a crossing keeps and a
/// kSphereMeet event is with; and the element's version (§4.2), which its path changes bump and
/// its partners' predictions copy. One 24-byte record, as every event reads them all; it lives
/// in the element's queue entry (its payload), so that the lines the queue's walks fetch hold it.
struct Prediction : Candidate {
  EventKind kind = EventKind::kNone;
  std::uint8_t aux = 0;  // kWallMeet: the wall; kCellCrossing: axis * 2 + (1 if upwards)
  std::uint32_t version = 0;  // the element's own path changes so far (in the padding)
  // A kCellCrossing's face, from `aux`: the axis, and +1 or -1 (arithmetic: no branch).
  int CrossingAxis() const { return aux / 2; }
  int CrossingDirection() const { return 2 * (aux & 1) - 1; }
};
static_assert(sizeof(Prediction) == 24);

/// The element queue: one slot per element, carrying its prediction.
using ElementQueue = BasicCalendarQueue<Prediction>;

/// The pair tests of a prediction: an actor against the candidates the broad phase visits,
/// keeping the earliest meeting (Offer). The general test (ConsiderMeeting: any paths and
/// envelopes, with a distance bound that skips pairs apart for long enough) and the straight
/// lines' fast forms (ScanNeighbors, TestGathered) give the same numbers.
class MeetingScan {
 public:
  MeetingScan(WorldCore& core, const ElementQueue& queue, const Engagements& engagements,
              const std::optional<Grid>& grid, const std::optional<AllPairs>& all_pairs)
      : core_(core),
        queue_(queue),
        engagements_(engagements),
        grid_(grid),
        all_pairs_(all_pairs),
        drag_(core) {}

  /// While a scan runs: the time after which no meeting can become the actor's event (its next
  /// wrap in a periodic AllPairs box), else infinity. Pairs apart so long are skipped.
  void SetLimit(double limit) { scan_limit_ = limit; }

  /// i against j's image at `shift`, any paths.
  void ConsiderMeeting(std::uint32_t i, std::uint32_t j, const Vec3& shift, Candidate& best);
  /// ConsiderMeeting for each of AllPairs' images of j.
  void ConsiderImages(std::uint32_t i, std::uint32_t j, Candidate& best);
  /// Keeps the earlier meeting (ties to the lower index, so that both broad phases agree).
  void Offer(Candidate& best, double t, std::uint32_t j) const {
    if (t < best.time || (t == best.time && j < best.target)) {
      best = Candidate{t, j, queue_.PayloadOf(j).version};
    }
  }

  /// For the elements `visit(fn)` presents: the straight-line test inlined (no call per pair)
  /// when every path is straight, else ConsiderMeeting.
  template <typename VisitNeighbors>
  void ScanNeighbors(std::uint32_t i, Candidate& best, VisitNeighbors&& visit);
  /// ScanNeighbors for straight lines over what `gather(fn)` visits (a Grid gather near i's
  /// cell at `place`: the 27 `around` it, i included, or the 9 new ones; kWrapped: one that may
  /// wrap, with image shifts), without branches on the data. TestGatheredOf picks the form.
  template <bool kWrapped, typename Gather>
  void TestGatheredOf(std::uint32_t i, const Grid::Place& place, bool around, Candidate& best,
                      Gather&& gather);

  /// The gathers' work list, then TestGathered's hits.
  BigVector<std::uint32_t>& gathered() { return gathered_; }
  std::size_t MemoryBytes() const { return gathered_.capacity() * sizeof(std::uint32_t); }

 private:
  template <bool kOneMaterial, bool kWrapped, typename Gather>
  void TestGathered(std::uint32_t i, const Grid::Place& place, bool around, Candidate& best,
                    Gather&& gather);
  // Whether an engagement tracks the pair (the sparse phase then leaves it); the time a pair is
  // predicted from; the test of one image, given the two movers at that time.
  bool EngagedPair(std::uint32_t i, std::uint32_t j) const;
  double PairReference(std::uint32_t i, std::uint32_t j) const;
  void ConsiderImage(std::uint32_t i, const Mover& a, const Mover& b,
                     const std::optional<ApartBound>& bound, double reference, std::uint32_t j,
                     const Vec3& shift, Candidate& best);
  // A pair with drag whose element meeting is `dt` after now: its contact on the true motions
  // (DragContacts), offered if it comes before the earliest event found so far.
  void OfferDragContact(std::uint32_t i, std::uint32_t j, const Mover& a, const Mover& b,
                        const Vec3& shift, double dt, Candidate& best);
  // ScanNeighbors' rare step, out of the cell walk: certifies a root of LinearMeetingRoot.
  [[gnu::noinline]] void OfferLinearMeeting(const PathStart& pi, std::uint32_t j,
                                            const Vec3& shift, double reach, double dt,
                                            Candidate& best);

  WorldCore& core_;
  const ElementQueue& queue_;
  const Engagements& engagements_;
  const std::optional<Grid>& grid_;
  const std::optional<AllPairs>& all_pairs_;
  BigVector<std::uint32_t> gathered_;
  double scan_limit_ = kInfinity;
  DragContacts drag_;
};

namespace scan_detail {

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

}  // namespace scan_detail

template <typename VisitNeighbors>
void MeetingScan::ScanNeighbors(std::uint32_t i, Candidate& best, VisitNeighbors&& visit) {
  const ElementPaths& paths = core_.bodies.paths;
  if (!paths.StraightLines()) {
    visit([&](std::uint32_t j, const Vec3& shift) { ConsiderMeeting(i, j, shift, best); });
    return;
  }
  // The hot path: straight lines, no envelopes, no engagements: the same numbers as
  // ConsiderMeeting (MoverOf + PredictMeeting), with the actor's data read once. Inlined into
  // the cell walk: a call per pair cost a fifth of the test. The GNU spelling after the
  // parameters applies to the call operator with GCC and clang alike; [[gnu::always_inline]]
  // there applies to the lambda's type: GCC 12 drops it (silently, in a template), clang 14
  // warns (an error here). GCC -O2 makes the same code either way.
  const PathStart pi = paths.Start(i);
  const BodyMaterials& materials = core_.bodies.materials;
  // One material (a gas): no per-body look-up, which is a cache miss at N = 10^6.
  const bool one_material = materials.table().size() == 1;
  const double ri = one_material ? materials.table()[0].radius : materials.Radius(i);
  std::uint64_t tests = 0;
  visit([&](std::uint32_t j, const Vec3& shift) __attribute__((always_inline)) {
    ++tests;
    const scan_detail::RelativeMotion m = scan_detail::RelativeMotionOf(pi, paths.Start(j), shift);
    const auto reach = [&] { return ri + (one_material ? ri : materials.Radius(j)); };
    const double dt = LinearMeetingRoot(m.dp_xy, m.dp_z, m.dv_xy, m.dv_z, reach);
    if (dt != kInfinity) OfferLinearMeeting(pi, j, shift, reach(), dt, best);
  });
  core_.observers.stats().pair_tests += tests;
}

template <bool kOneMaterial, bool kWrapped, typename Gather>
void MeetingScan::TestGathered(std::uint32_t i, const Grid::Place& place, bool around,
                               Candidate& best, Gather&& gather) {
  // ScanNeighbors' straight-line test, the same numbers, over the elements a Grid gather
  // visits, without a branch on the data: whether a pair approaches, and then whether it passes
  // wide, are coin tosses in a gas, and a mispredicted branch costs more than testing both.
  // The pairs that meet are noted (in the gather's used entries) and have their root computed
  // and certified after the visit, so that the visit makes no call and keeps i's data in
  // registers. When the gather is `around` i's cell, i itself is among them (once: a grid has
  // at least 3 cells per axis): with dp = dv = 0 it does not approach.
  const ElementPaths& paths = core_.bodies.paths;
  const BodyMaterials& body_materials = core_.bodies.materials;
  const PathStart pi = paths.Start(i);
  const double ri =
      kOneMaterial ? body_materials.table()[0].radius : body_materials.Radius(i);
  const ElementPaths::Record* starts = paths.Records().data();
  const std::uint32_t* material = body_materials.PerBody();
  const Material* materials = body_materials.table().data();
  std::uint32_t visited = 0, hits = 0;
  gather([&](std::uint32_t j, const Vec3& shift) __attribute__((always_inline)) {
    ++visited;
    // One material (a gas): no per-body look-up, a cache miss per pair at N = 10^6.
    const double reach = ri + (kOneMaterial ? ri : materials[material[j]].radius);
    const scan_detail::RelativeMotion m =
        kWrapped ? scan_detail::RelativeMotionOf(pi, starts[j], shift)
                 : scan_detail::RelativeMotionOf(pi, starts[j]);
    gathered_[hits] = j;  // an entry the gather is done with (hits < visited)
    hits += LinearMeetingFound(m.dp_xy, m.dp_z, m.dv_xy, m.dv_z, reach) ? 1u : 0u;
  });
  core_.observers.stats().pair_tests += visited - (around ? 1u : 0u);
  for (std::uint32_t h = 0; h < hits; ++h) {
    const std::uint32_t j = gathered_[h];
    const double reach = ri + (kOneMaterial ? ri : body_materials.Radius(j));
    // The shift the visit had for j (interior cells: none).
    const Vec3 shift = kWrapped ? grid_->ImageShift(place, j) : Vec3::Zero();
    const scan_detail::RelativeMotion m = scan_detail::RelativeMotionOf(pi, paths.Start(j), shift);
    const double dt =
        LinearMeetingRoot(m.dp_xy, m.dp_z, m.dv_xy, m.dv_z, [reach] { return reach; });
    OfferLinearMeeting(pi, j, shift, reach, dt, best);
  }
}

template <bool kWrapped, typename Gather>
void MeetingScan::TestGatheredOf(std::uint32_t i, const Grid::Place& place, bool around,
                                 Candidate& best, Gather&& gather) {
  if (core_.bodies.materials.table().size() == 1) {
    TestGathered<true, kWrapped>(i, place, around, best, gather);
  } else {
    TestGathered<false, kWrapped>(i, place, around, best, gather);
  }
}

}  // namespace sparsedyn
