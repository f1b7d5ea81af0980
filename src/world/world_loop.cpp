// SPDX-License-Identifier: MIT
// The event loop: a short dispatcher over event kinds and one handler per kind.
#include <cmath>
#include <iomanip>
#include <sstream>

#include "dynamics/sphere_collision.hpp"
#include "world/world_impl.hpp"

namespace sparsedyn {
namespace {

// Stall detection: every kStallWindow events the clock must have moved by more than a relative
// kStallProgress, else the loop is stuck (inelastic collapse, a Zeno sequence).
constexpr double kStallProgress = 1e-12;

}  // namespace

Status World::Impl::AdvanceTo(double t) {
  if (!std::isfinite(t)) return Error{"AdvanceTo: time must be finite"};
  if (!started_) Start();
  ProgressWindow window{0, now_, stats_.collapse_guarded};
  while (true) {
    const bool has_element = !queue_.Empty();
    const bool has_engagement = !engagement_queue_.Empty();
    if (!has_element && !has_engagement) break;
    // The earlier of the two queue heads; equal times go to the element queue (kinds < 3).
    bool engagement = !has_element;
    if (has_element && has_engagement) {
      engagement = engagement_queue_.Top().time < queue_.Top().time;
    }
    const QueueTop top = engagement ? engagement_queue_.Top() : queue_.Top();
    if (top.time > t) break;

    if (++window.events >= settings_.stall_event_limit) {
      if (Status progress = CheckProgress(top, engagement, window); !progress) return progress;
    }
    now_ = top.time;
    Dispatch(top, engagement);
    MaybeReorder();
    if (fetch_ahead_) FetchAhead();
  }
  now_ = std::max(now_, t);
  return Status::Ok();
}

Status World::Impl::CheckProgress(const QueueTop& top, bool engagement,
                                  ProgressWindow& window) const {
  const auto last_event = [&] {
    std::ostringstream out;
    out << "last event " << EventKindName(static_cast<int>(top.kind)) << " of "
        << (engagement ? "engagement " : "body ") << (engagement ? top.slot : public_of_[top.slot]);
    return out.str();
  };
  std::ostringstream message;
  message.precision(17);
  // A stall: the clock stands still.
  if (top.time - window.start <= kStallProgress * std::max(1.0, std::abs(top.time))) {
    message << "event loop stalled: " << window.events << " events without time advancing"
            << " past t = " << top.time << " (inelastic collapse, bodies coming to rest on "
            << "each other (only walls hold bodies at rest) or a stuck configuration; "
            << last_event() << ")";
    return Error{message.str()};
  }
  // A crawl: the clock moves, but nearly every event is a collision slower than the collapse
  // guard, and faster than even every body bouncing at that speed under the largest
  // acceleration could make them (one every 2 v / a per body): bodies at rest that no wall
  // holds, rocking and bouncing on it ever faster (a polyhedron on the floor, a pile).
  const std::uint64_t guarded = stats_.collapse_guarded - window.guarded;
  const double most = MaxFreeAcceleration();
  if (10 * guarded >= 9 * window.events && most > 0.0) {
    const double bounce = 2.0 * settings_.elastic_below_speed / most;
    const double elapsed = top.time - window.start;
    if (elapsed < static_cast<double>(window.events) * bounce /
                      static_cast<double>(std::max<std::size_t>(starts_.size(), 1))) {
      message << "event loop crawling: " << guarded << " of the last " << window.events
              << " events were collisions slower than elastic_below_speed (" << std::setprecision(6)
              << settings_.elastic_below_speed << std::setprecision(17)
              << " m/s) while the clock moved from t = " << window.start << " to " << top.time
              << " (bodies coming to rest that no wall "
              << "holds: resting contact of polyhedra, and of bodies on each other, is not "
              << "supported; " << last_event() << ")";
      return Error{message.str()};
    }
  }
  window = ProgressWindow{0, top.time, stats_.collapse_guarded};
  return Status::Ok();
}

double World::Impl::MaxFreeAcceleration() const {
  if (!own_accelerations_) return uniform_acceleration_.norm();
  double most = 0.0;
  for (std::uint32_t i = 0; i < starts_.size(); ++i)
    most = std::max(most, FreeAcceleration(i).norm());
  return most;
}

void World::Impl::FetchElement(std::uint32_t e) const {
  Prefetch(&starts_[e]);  // one line: the path start and the grid links
  queue_.Prefetch(e);     // the queue entry with its prediction, both its lines
}

std::uint32_t World::Impl::CellAhead(std::uint32_t e) const {
  // The cell e's next event will scan around: the one it crosses into, or its own.
  const Prediction& event = PredictionOf(e);
  const std::uint32_t cell = grid_->CellOf(e);
  if (event.kind != EventKind::kCellCrossing) return cell;
  return grid_->CellAcross(cell, event.CrossingAxis(), event.CrossingDirection());
}

void World::Impl::FetchAhead() const {
  // A pipeline over the coming events, so that each step's cache misses have events' time to
  // arrive before the step that needs them: the fourth-next element's own entries; the
  // third-next's cell heads and its meeting partner's entries (its event, fetched one event
  // earlier, names the partner); the second-next crossing's new neighbours (their heads are
  // the ones fetched one event earlier), or the second-next meeting's partner's cell heads
  // (Collide then fetches its neighbours while the actor predicts). The queue only guesses
  // the order; a wrong guess costs the fetches. One event further ahead measured the same,
  // one event less 4% slower at N = 10^6; the partner's entries one stage earlier (a wait for
  // the event), slower. The last stage for every event's 27 cells was 13% slower at 10^5 (27
  // head loads, which wait when the heads have not arrived); for the 9 new cells of crossings
  // only, +2.5% at 10^5 and +7.3% at 10^6; a meeting's actor's 27 as well, even
  // (docs/benchmarks.md, twenty-first measurement).
  std::uint32_t next[4];
  const int count = queue_.Upcoming(next, 4);
  if (count >= 3) {
    grid_->FetchAround(CellAhead(next[2]));
    const Prediction& event = PredictionOf(next[2]);
    if (event.kind == EventKind::kSphereMeet) FetchElement(event.target);
  }
  if (count >= 4) FetchElement(next[3]);
  if (count >= 2) {
    const Prediction& event = PredictionOf(next[1]);
    if (event.kind == EventKind::kCellCrossing) {
      grid_->FetchNewFirsts(CellAhead(next[1]), event.CrossingAxis(), event.CrossingDirection());
    } else if (event.kind == EventKind::kSphereMeet) {
      grid_->FetchAround(grid_->CellOf(event.target));
    }
  }
}

void World::Impl::Dispatch(const QueueTop& top, bool engagement) {
  ++stats_.events;
  ++stats_.events_by_kind[static_cast<std::size_t>(top.kind)];
  if (engagement) {
    HandleEngagement(top.slot);
    return;
  }
  switch (top.kind) {
    case EventKind::kSphereMeet:
      HandleSphereMeet(top.slot);
      break;
    case EventKind::kWallMeet:
      HandleWallMeet(top.slot);
      break;
    case EventKind::kCellCrossing:
      HandleCellCrossing(top.slot);
      break;
    case EventKind::kEngagement:
    case EventKind::kNone:
      SPARSEDYN_ASSERT(false, "element queue holds an event of the wrong kind");
  }
}

void World::Impl::HandleCellCrossing(std::uint32_t i) {
  const Prediction event = PredictionOf(i);
  const int axis = event.CrossingAxis();
  const int direction = event.CrossingDirection();
  // A periodic wrap shifts the position: the same motion, seen in the box.
  if (!grid_) {
    starts_[i].p0 += all_pairs_->Move(i, axis, direction);
    PredictFull(i);
    return;
  }
  Vec3 shift;
  const Grid::Place place = grid_->Move(i, axis, direction, shift);
  starts_[i].p0 += shift;
  PredictAfterCrossing(i, place, axis, direction);
}

bool World::Impl::TouchingAndApproaching(std::uint32_t i, std::uint32_t j, Vec3& normal,
                                         double& gap) const {
  const Vec3 d = MinimumImage(PositionNow(j) - PositionNow(i));
  const double reach = Radius(i) + Radius(j);
  const double distance = d.norm();
  gap = distance - reach;
  normal = d / distance;
  const Vec3 dv = VelocityNow(j) - VelocityNow(i);
  return gap <= settings_.contact_tolerance * reach && d.dot(dv) < 0;
}

void World::Impl::HandleSphereMeet(std::uint32_t i) {
  const Prediction event = PredictionOf(i);
  const std::uint32_t j = event.target;
  if (PredictionOf(j).version != event.target_version) {
    // Target-absent (§4.2): the target changed path since; the actor looks again.
    ++stats_.stale_target_absent;
    PredictFull(i);
    return;
  }
  ++stats_.meetings;
  if (EngagesOnMeet()) {
    // The element spheres meet; the bodies inside may not: engage (§3.3) and let the detailed
    // phase watch the pair while the actor looks for its next sparse meeting.
    if (!engagements_.Engaged(i, j)) {
      const std::uint32_t k = engagements_.Add(i, j);
      ++stats_.engagements_started;
      PredictEngagement(k);
    }
    PredictFull(i);
    return;
  }
  Vec3 normal;
  double gap = 0;
  if (!TouchingAndApproaching(i, j, normal, gap)) {
    // Predicted early (conservative) or touching while separating: look again from here.
    if (gap > settings_.contact_tolerance * (Radius(i) + Radius(j))) ++stats_.early_events;
    PredictFull(i);
    return;
  }
  Collide(i, j, normal, gap);
}

void World::Impl::NotePenetration(double gap) {
  if (-gap > max_penetration_) max_penetration_ = -gap;
}

void World::Impl::SetVelocity(std::uint32_t i, const Vec3& v) {
  SetStart(i, PathStart{PositionNow(i), v, now_});
  ReportSegment(i);
}

void World::Impl::ReportSegment(std::uint32_t i) {
  ++PredictionOf(i).version;
  if (on_segment_) {
    const PathStart& s = starts_[i];
    on_segment_(MotionSegment{now_, PublicId(i), s.p0, s.v0, PathOf(i).a, PredictionOf(i).version});
  }
}

void World::Impl::SetHeld(std::uint32_t i, std::uint8_t walls, Vec3 v) {
  const Vec3 p = PositionNow(i);  // on the path so far
  if (held_by_.empty()) {
    // The first hold: every body gets its own acceleration, and its free one is kept.
    if (!own_accelerations_) acceleration_.assign(starts_.size(), uniform_acceleration_);
    own_accelerations_ = true;
    free_acceleration_ = acceleration_;
    held_by_.assign(starts_.size(), 0);
  }
  held_by_[i] = walls;
  Vec3 a = free_acceleration_[i];
  for (int w = 0; w < 6; ++w) {
    if ((walls >> w & 1u) != 0) {
      a[w / 2] = 0.0;  // the walls are axis-aligned: exact zeros, so the gap stays as it is
      v[w / 2] = 0.0;
    }
  }
  acceleration_[i] = a;
  SetStart(i, PathStart{p, v, now_});
  ReportSegment(i);
}

bool World::Impl::HoldAgainstWall(std::uint32_t i, int w, const Vec3& normal, const Vec3& v,
                                  double gap) {
  // Coming to rest: touching, moving to or from the wall slower than the collapse guard, and
  // pressed into it by gravity or thrust. Bounces would follow ever faster (the guard keeps
  // them elastic; below the time's resolution they would stall the clock), so the wall holds
  // the body instead: its velocity and acceleration into the wall become zero (the normal
  // force) until a collision with another body moves it.
  if (gap > settings_.contact_tolerance * Radius(i)) return false;
  const double approach = normal.dot(v);
  if (!(std::abs(approach) < settings_.elastic_below_speed) ||
      !(normal.dot(FreeAcceleration(i)) < 0.0)) {
    return false;
  }
  const std::uint8_t walls = held_by_.empty() ? 0 : held_by_[i];
  SetHeld(i, static_cast<std::uint8_t>(walls | 1u << w), v);
  // A wall collision like any other (its segment comes with one), with the impulse that stops
  // the body's approach.
  NotePenetration(gap);
  ++stats_.wall_holds;
  ++stats_.wall_collisions;
  if (on_collision_) {
    on_collision_(CollisionEvent{now_, PublicId(i), BodyId{}, w,
                                 PositionNow(i) - Radius(i) * normal, -normal,
                                 std::max(-approach, 0.0) / InvMass(i)});
  }
  PredictFull(i);
  PredictEngagementsOf(i);
  return true;
}

void World::Impl::Collide(std::uint32_t i, std::uint32_t j, const Vec3& normal, double gap) {
  NotePenetration(gap);
  ImpulseResult result;
  {
    const PhaseTimer timer(settings_.profile_phases, stats_.seconds_response);
    result = SphereImpulse(VelocityNow(i), VelocityNow(j), InvMass(i), InvMass(j), normal,
                           Restitution(i) * Restitution(j), settings_.elastic_below_speed);
    if (held_by_.empty()) {
      SetVelocity(i, result.v_a);
      SetVelocity(j, result.v_b);
    } else {
      // A collision with another body ends a wall's hold (the wall takes it up again if the
      // body is still at rest against it).
      SetHeld(i, 0, result.v_a);
      SetHeld(j, 0, result.v_b);
    }
  }
  ++stats_.collisions;
  if (result.guarded) ++stats_.collapse_guarded;
  if (on_collision_) {
    const Vec3 p_i = starts_[i].p0;
    on_collision_(CollisionEvent{now_, PublicId(i), PublicId(j), -1, p_i + Radius(i) * normal,
                                 normal, result.impulse});
  }
  // j's own prediction is superseded: the actor-absent event of §4.2, removed in place.
  const Prediction& pending = PredictionOf(j);
  if (pending.kind != EventKind::kNone &&
      !(pending.kind == EventKind::kSphereMeet && pending.target == i)) {
    ++stats_.stale_actor_absent;
  }
  // j's neighbours, fetched while i predicts (FetchAhead fetched their heads an event ago).
  if (fetch_ahead_) grid_->FetchAroundFirsts(grid_->CellOf(j));
  PredictFull(i);
  PredictFull(j);
  if (!EngagesOnMeet()) return;  // a gas: no engagements, and no call to find that out
  PredictEngagementsOf(i);
  PredictEngagementsOf(j, /*done_partner=*/i);
}

void World::Impl::HandleWallMeet(std::uint32_t i) {
  if (polyhedra_) {
    HandlePolyhedronWall(i);
    return;
  }
  const Prediction event = PredictionOf(i);
  const WallPlane plane = BoxWall(settings_.container, event.aux);
  const Vec3 p = PathOf(i).PositionAt(now_);
  const Vec3 v = PathOf(i).VelocityAt(now_);
  const double gap = plane.normal.dot(p) - plane.offset - Radius(i);
  const double approach = plane.normal.dot(v);
  if (HoldAgainstWall(i, event.aux, plane.normal, v, gap)) return;
  if (gap > settings_.contact_tolerance * Radius(i) || approach >= 0) {
    if (gap > settings_.contact_tolerance * Radius(i)) ++stats_.early_events;
    PredictFull(i);
    return;
  }
  NotePenetration(gap);
  ImpulseResult result;
  {
    // A static wall has infinite mass: the body's normal velocity is reversed and scaled by e.
    const PhaseTimer timer(settings_.profile_phases, stats_.seconds_response);
    result = SphereImpulse(v, Vec3::Zero(), InvMass(i), 0.0, -plane.normal, Restitution(i),
                           settings_.elastic_below_speed);
    SetVelocity(i, result.v_a);
  }
  ++stats_.wall_collisions;
  if (result.guarded) ++stats_.collapse_guarded;
  if (on_collision_) {
    on_collision_(CollisionEvent{now_, PublicId(i), BodyId{}, event.aux,
                                 p - Radius(i) * plane.normal, -plane.normal, result.impulse});
  }
  PredictFull(i);
  PredictEngagementsOf(i);
}

void World::Impl::HandleEngagement(std::uint32_t k) {
  if (polyhedra_) {
    HandlePolyhedralEngagement(k);
    return;
  }
  const Engagements::Engagement e = engagements_[k];
  if (e.contact_next) {
    Vec3 normal;
    double gap = 0;
    if (TouchingAndApproaching(e.a, e.b, normal, gap)) {
      Collide(e.a, e.b, normal, gap);
      return;
    }
    if (gap > settings_.contact_tolerance * (Radius(e.a) + Radius(e.b))) ++stats_.early_events;
    PredictEngagement(k);
    return;
  }
  // The element spheres separate: the engagement ends and a looks for its next meeting, which
  // may be with b again.
  engagement_queue_.Erase(k);
  engagements_.Remove(k);
  ++stats_.engagements_ended;
  PredictFull(e.a);
}

}  // namespace sparsedyn
