// SPDX-License-Identifier: MIT
// The general pair tests of the sparse phase (any paths, envelopes, periodic images) and the
// certification of a straight-line meeting.
#include "world/meeting_scan.hpp"

#include <cmath>

namespace sparsedyn {
namespace {

// The time span a scan may skip a pair for: up to `limit` (the earliest event found so far, or
// the scan's limit) from the pair's `reference` time, widened by a few ulps so that the meetings
// skipped are certainly later (ties with the limit still count).
double SkipSpan(double limit, double reference) {
  return (limit - reference) * (1 + 0x1p-40) + 0x1p-50 * std::abs(limit);
}

}  // namespace

void MeetingScan::ConsiderMeeting(std::uint32_t i, std::uint32_t j, const Vec3& shift,
                                  Candidate& best) {
  if (EngagedPair(i, j)) return;
  const double reference = PairReference(i, j);
  const BodyStore& bodies = core_.bodies;
  const Mover a = bodies.MoverOf(i, reference), b = bodies.MoverOf(j, reference);
  // The bound only where ConsiderImage can use it (a limit to skip by).
  const bool bounded = MinOf(best.time, scan_limit_) != kInfinity && !OnStraightLines(a, b);
  const std::optional<ApartBound> bound =
      bounded ? std::optional<ApartBound>(std::in_place, a, b) : std::nullopt;
  ConsiderImage(i, a, b, bound, reference, j, shift, best);
}

void MeetingScan::ConsiderImages(std::uint32_t i, std::uint32_t j, Candidate& best) {
  // ConsiderMeeting for every image AllPairs sees j at, the movers worked out once. The
  // nearest image first: its meeting, if any, is the likeliest to be the earliest, and the
  // sooner `best` is finite, the more of the other 26 the distance bound skips. The result
  // does not depend on the order (Offer keeps the earliest, ties to the lower index, and a
  // skipped image cannot meet before `best`).
  if (EngagedPair(i, j)) return;
  const double reference = PairReference(i, j);
  const BodyStore& bodies = core_.bodies;
  Statistics& stats = core_.observers.stats();
  const Mover a = bodies.MoverOf(i, reference), b = bodies.MoverOf(j, reference);
  const std::optional<ApartBound> bound =
      OnStraightLines(a, b) ? std::nullopt : std::optional<ApartBound>(std::in_place, a, b);
  const std::vector<Vec3>& shifts = all_pairs_->ImageShifts();
  const std::size_t nearest = all_pairs_->NearestImage(b.p - a.p);
  ConsiderImage(i, a, b, bound, reference, j, shifts[nearest], best);
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
      stats.pair_tests += shifts.size() - 1;
      stats.pairs_skipped += shifts.size() - 1;
      return;
    }
  }
  for (std::size_t r = 0; r < shifts.size(); ++r) {
    if (r == nearest) continue;
    if (ImageApart(apart, r)) {
      ++stats.pair_tests;
      ++stats.pairs_skipped;
      continue;
    }
    ConsiderImage(i, a, b, bound, reference, j, shifts[r], best);
  }
}

bool MeetingScan::EngagedPair(std::uint32_t i, std::uint32_t j) const {
  // An engaged pair is tracked by its engagement, not by the sparse phase.
  return core_.bodies.EngagesOnMeet() && engagements_.HasAny(i) && engagements_.Engaged(i, j);
}

double MeetingScan::PairReference(std::uint32_t i, std::uint32_t j) const {
  // Predict from the later of the two segment starts, not from `now`: the result then depends
  // only on the two paths, so a prediction kept across cell crossings, or made by another broad
  // phase at another time, is bit-identical (determinism across broad phases). Not for engaging
  // elements: their spheres may have met and separated since, on unchanged paths, and that past
  // meeting must not come back as one now. Nor for bodies with drag, whose contact is looked
  // for from now on their true motions.
  const BodyStore& bodies = core_.bodies;
  const ElementPaths& paths = bodies.paths;
  const bool from_now = bodies.Engages(i, j) || (paths.drags().Any() &&
                                                 (bodies.HasDrag(i) || bodies.HasDrag(j)));
  return from_now ? paths.Now() : std::max(paths.Start(i).t0, paths.Start(j).t0);
}

void MeetingScan::ConsiderImage(std::uint32_t i, const Mover& a, const Mover& b,
                                const std::optional<ApartBound>& bound, double reference,
                                std::uint32_t j, const Vec3& shift, Candidate& best) {
  Statistics& stats = core_.observers.stats();
  ++stats.pair_tests;
  // A pair on curved paths or with envelopes costs a root isolation (microseconds). A meeting
  // after the earliest event found so far (or after the scan's limit) cannot become i's event:
  // skip the pairs whose distance keeps them apart that long (`bound`, the pair's ApartBound;
  // none on straight lines, or where no limit applied when the pair was taken up).
  const double limit = MinOf(best.time, scan_limit_);
  if (limit != kInfinity && bound) {
    if (bound->Within(shift, SkipSpan(limit, reference))) {
      ++stats.pairs_skipped;
      return;
    }
  }
  const double dt = PredictMeeting(a, b, shift);
  const BodyStore& bodies = core_.bodies;
  if (bodies.paths.drags().Any() && (bodies.HasDrag(i) || bodies.HasDrag(j)) &&
      !bodies.Engages(i, j)) {
    OfferDragContact(i, j, a, b, shift, dt, best);
    return;
  }
  if (dt != kInfinity) Offer(best, std::max(core_.Now(), EventTime(reference, dt)), j);
}

void MeetingScan::OfferDragContact(std::uint32_t i, std::uint32_t j, const Mover& a,
                                   const Mover& b, const Vec3& shift, double dt,
                                   Candidate& best) {
  // The bodies cannot touch before their elements meet; elements that overlap now may hold
  // bodies that touch at any time (PredictMeeting passes over an overlap that opens).
  const double now = core_.Now();
  const bool overlapping = (b.p + shift - a.p).norm() <= a.r0 + b.r0;
  if (!overlapping && dt == kInfinity) return;
  const double begin = overlapping ? now : std::max(now, EventTime(now, dt));
  // Up to the earliest event found so far, and no further than either body's check (which
  // predicts again with a new segment).
  const DragMotions& drags = core_.bodies.paths.drags();
  const double end = std::min({MinOf(best.time, scan_limit_), drags.CheckTime(i),
                               drags.CheckTime(j)});
  if (!(begin < end)) return;
  const double contact = drag_.PairContact(i, j, shift, begin, end);
  if (contact != kInfinity) Offer(best, contact, j);
}

void MeetingScan::OfferLinearMeeting(const PathStart& pi, std::uint32_t j, const Vec3& shift,
                                     double reach, double dt, Candidate& best) {
  // The positions exactly as ConsiderMeeting's movers have them, for the certification.
  const PathStart& pj = core_.bodies.paths.Start(j);
  const double reference = std::max(pi.t0, pj.t0);
  const Vec3 pa = pi.t0 == reference ? pi.p0 : Vec3(pi.p0 + (reference - pi.t0) * pi.v0);
  const Vec3 pb = pj.t0 == reference ? pj.p0 : Vec3(pj.p0 + (reference - pj.t0) * pj.v0);
  dt = FinishLinearMeeting(pa, pi.v0, pb, pj.v0, shift, reach, dt);
  if (dt != kInfinity) Offer(best, MaxOf(core_.Now(), EventTime(reference, dt)), j);
}

}  // namespace sparsedyn
