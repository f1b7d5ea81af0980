// SPDX-License-Identifier: MIT
// The event loop: the earliest event of the element and engagement queues, dispatched by kind
// to the part that handles it, and the check that the clock keeps moving.
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

#include "world/world_impl.hpp"

namespace sparsedyn {

static_assert(std::tuple_size_v<decltype(Statistics::events_by_kind)> == kEventKindCount,
              "a counter per event kind");

namespace {

// Stall detection: every kStallWindow events the clock must have moved by more than a relative
// kStallProgress, else the loop is stuck (inelastic collapse, a Zeno sequence).
constexpr double kStallProgress = 1e-12;

}  // namespace

Status World::Impl::AdvanceTo(double t) {
  if (!std::isfinite(t)) return Error{"AdvanceTo: time must be finite"};
  if (core_.observers.Breached()) return breach_;  // the World stopped at a broken invariant
  if (!started_) Start();
  ElementQueue& queue = sparse_.queue();
  CalendarQueue& engagement_queue = detailed_.queue();
  ProgressWindow window{0, core_.Now(), core_.observers.stats().collapse_guarded};
  while (true) {
    const bool has_element = !queue.Empty();
    const bool has_engagement = !engagement_queue.Empty();
    if (!has_element && !has_engagement) break;
    // The earlier of the two queue heads; equal times go to the element queue.
    bool engagement = !has_element;
    if (has_element && has_engagement) {
      engagement = engagement_queue.Top().time < queue.Top().time;
    }
    const QueueTop top = engagement ? engagement_queue.Top() : queue.Top();
    if (top.time > t) break;

    if (++window.events >= core_.settings.stall_event_limit) {
      if (Status progress = CheckProgress(top, engagement, window); !progress) return progress;
    }
    core_.bodies.paths.SetNow(top.time);
    Dispatch(top, engagement);
    if (core_.observers.Breached()) [[unlikely]] {
      breach_ = BreachError(top, engagement);
      return breach_;
    }
    memory_.CountEvent();
    if (sparse_.FetchesAhead()) look_ahead_.Fetch();
  }
  core_.bodies.paths.SetNow(std::max(core_.Now(), t));
  return Status::Ok();
}

void World::Impl::Dispatch(const QueueTop& top, bool engagement) {
  Statistics& stats = core_.observers.stats();
  ++stats.events;
  ++stats.events_by_kind[static_cast<std::size_t>(top.kind)];
  if (engagement) {
    detailed_.Handle(top.slot);
    return;
  }
  switch (top.kind) {
    case EventKind::kSphereMeet:
      HandleMeeting(top.slot);
      break;
    case EventKind::kWallMeet:
      walls_.Handle(top.slot);
      break;
    case EventKind::kCellCrossing:
      sparse_.HandleCrossing(top.slot);
      break;
    case EventKind::kBodyTimer:
      HandleBodyTimer(top.slot);
      break;
    case EventKind::kStaticMeet:
      HandleStaticMeet(top.slot);
      break;
    case EventKind::kEngagement:
    case EventKind::kNone:
      SPARSEDYN_ASSERT(false, "element queue holds an event of the wrong kind");
  }
}

void World::Impl::HandleMeeting(std::uint32_t i) {
  const Prediction event = sparse_.PredictionOf(i);
  const std::uint32_t j = event.target;
  Statistics& stats = core_.observers.stats();
  if (sparse_.PredictionOf(j).version != event.target_version) {
    // Target-absent (§4.2): the target changed path since; the actor looks again.
    ++stats.stale_target_absent;
    sparse_.PredictFull(i);
    return;
  }
  ++stats.meetings;
  if (core_.bodies.Engages(i, j)) {
    // The element spheres meet; the bodies inside may not: engage (§3.3) and let the detailed
    // phase watch the pair while the actor looks for its next sparse meeting.
    detailed_.Engage(i, j);
    sparse_.PredictFull(i);
    return;
  }
  Vec3 normal;
  double gap = 0;
  if (!spheres_.TouchingAndApproaching(i, j, normal, gap)) {
    // Predicted early (conservative) or touching while separating: look again from here.
    const BodyMaterials& materials = core_.bodies.materials;
    if (gap > core_.settings.contact_tolerance * (materials.Radius(i) + materials.Radius(j))) {
      ++stats.early_events;
    }
    sparse_.PredictFull(i);
    return;
  }
  spheres_.Collide(i, j, normal, gap);
}

void World::Impl::HandleStaticMeet(std::uint32_t i) {
  const std::uint32_t s = sparse_.PredictionOf(i).target;
  ++core_.observers.stats().meetings;
  if (core_.bodies.statics.Alive(s)) detailed_.Engage(i, StaticBodies::KeyOf(s));
  sparse_.PredictFull(i);  // the next static it reaches, or its next meeting
}

std::string World::Impl::DescribeEvent(const QueueTop& top, bool engagement) const {
  std::ostringstream out;
  out << EventKindName(static_cast<int>(top.kind)) << " of "
      << (engagement ? "engagement " : "body ")
      << (engagement ? top.slot : core_.bodies.ids.PublicOf(top.slot));
  return out.str();
}

Error World::Impl::BreachError(const QueueTop& top, bool engagement) const {
  std::ostringstream message;
  message.precision(17);
  const Observers& observers = core_.observers;
  message << "no-penetration invariant broken at t = " << top.time << ": a contact overlapped by "
          << observers.BreachDepth() << " m, beyond its contact band of "
          << observers.BreachBand() << " m (contact_tolerance times the radii; event "
          << DescribeEvent(top, engagement) << "); the World stops here";
  return Error{message.str()};
}

Status World::Impl::CheckProgress(const QueueTop& top, bool engagement,
                                  ProgressWindow& window) const {
  const Statistics& stats = core_.observers.stats();
  const auto last_event = [&] { return "last event " + DescribeEvent(top, engagement); };
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
  // A crawl: the clock moves, but a quarter or more of the events are collisions slower than
  // the collapse guard, more of them than even every body bouncing at that speed could make
  // (once every 2 v / a per body, a the largest acceleration of a surface point, turning
  // included): bodies in lasting contact that no wall holds, rocking and bouncing ever faster
  // (a polyhedron on an edge, a pile, or turning bodies pressed together without gravity after
  // an inelastic collision).
  const std::uint64_t guarded = stats.collapse_guarded - window.guarded;
  const std::uint32_t n = core_.bodies.Size();
  if (4 * guarded >= window.events) {
    const double most = core_.bodies.MaxSurfaceAcceleration(n);
    const double bounce = most > 0.0 ? 2.0 * core_.settings.elastic_below_speed / most : 0.0;
    const double elapsed = top.time - window.start;
    if (elapsed < static_cast<double>(guarded) * bounce /
                      static_cast<double>(std::max<std::size_t>(n, 1))) {
      message << "event loop crawling: " << guarded << " of the last " << window.events
              << " events were collisions slower than elastic_below_speed (" << std::setprecision(6)
              << core_.settings.elastic_below_speed << std::setprecision(17)
              << " m/s) while the clock moved from t = " << window.start << " to " << top.time
              << " (bodies in lasting contact that no wall holds: resting contact of polyhedra "
              << "on an edge or a vertex, of bodies on each other, and turning bodies pressed "
              << "together, is not supported; " << last_event() << ")";
      return Error{message.str()};
    }
  }
  window = ProgressWindow{0, top.time, stats.collapse_guarded};
  return Status::Ok();
}

}  // namespace sparsedyn
