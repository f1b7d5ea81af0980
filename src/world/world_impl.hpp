// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <array>
#include <bit>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "broadphase/all_pairs.hpp"
#include "broadphase/grid.hpp"
#include "events/calendar_queue.hpp"
#include "events/engagements.hpp"
#include "events/event.hpp"
#include "events/heap_queue.hpp"
#include "math/huge_pages.hpp"
#include "math/two_sum.hpp"
#include "motion/path.hpp"
#include "motion/rigid_path.hpp"
#include "narrow/time_of_contact.hpp"
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
  Vec3 AngularMomentum() const;
  Status Validate() const;
  std::size_t MemoryBytes() const;

  // --- event loop (world_loop.cpp) ---
  Status AdvanceTo(double t);

  WorldSettings settings_;
  // The periodic box's side lengths (MinimumImage; zero outside periodic boxes).
  Vec3 period_ = Vec3::Zero();
  bool periodic_ = false;
  Statistics stats_;
  std::function<void(const CollisionEvent&)> on_collision_;
  std::function<void(const MotionSegment&)> on_segment_;
  double now_ = 0.0;
  double max_penetration_ = 0.0;

  // Per-element state (structure of arrays, indexed by body index).
  // A body's path start and its place in the grid's cell lists in one aligned cache line: a
  // scan reads a neighbour's start and its list successor together, and an event's element
  // its start and cell (docs/benchmarks.md, thirteenth measurement).
  struct alignas(64) ElementStart : PathStart {
    GridLinks links;
  };
  static_assert(sizeof(ElementStart) == 64, "one cache line per element");
  BigVector<ElementStart> starts_;           // the path of body i is PathOf(i)
  void SetStart(std::uint32_t i, const PathStart& start) {
    static_cast<PathStart&>(starts_[i]) = start;
  }
  // Hands the grid the links in starts_, and the queue the records its refills fetch (again
  // after starts_ moved).
  void ShareStarts() {
    if (starts_.empty()) return;
    if (grid_) {
      grid_->UseLinks(&starts_.data()->links, StrideShiftOf<ElementStart>(), starts_.size());
    }
    queue_.FetchWithRefills(starts_.data(), StrideShiftOf<ElementStart>());
  }
  std::vector<Vec3> acceleration_;          // per body once own_accelerations_
  Vec3 uniform_acceleration_ = Vec3::Zero();  // gravity: every body's, until one has a thrust
  bool own_accelerations_ = false;
  // Spheres at rest against walls (docs/sparse-phase.md#coming-to-rest): bit w of held_by_[i]
  // says that wall w holds body i, whose velocity and acceleration into the wall are then zero
  // (acceleration_ is the held one); free_acceleration_ keeps gravity plus the body's thrust for
  // its release. Both empty until the first hold.
  std::vector<std::uint8_t> held_by_;
  std::vector<Vec3> free_acceleration_;
  Vec3 FreeAcceleration(std::uint32_t i) const {
    if (!free_acceleration_.empty()) return free_acceleration_[i];
    return own_accelerations_ ? acceleration_[i] : uniform_acceleration_;
  }
  struct Material {                         // what bodies share: a gas has one
    double radius;
    double inv_mass;
    double restitution;
    double friction;
  };
  std::vector<Material> materials_;
  BigVector<std::uint32_t> material_;       // per body, into materials_
  std::map<std::array<double, 4>, std::uint32_t> material_index_;  // (r, 1/m, e, mu) -> material

  Path PathOf(std::uint32_t i) const {
    const PathStart& s = starts_[i];
    return Path{s.p0, s.v0, own_accelerations_ ? acceleration_[i] : uniform_acceleration_, s.t0};
  }
  // Body i's position and velocity now. On straight lines without the zero acceleration's terms
  // (the same numbers up to the sign of a zero) and without building its Path: a collision of a
  // gas asks for them six times.
  Vec3 PositionNow(std::uint32_t i) const {
    const PathStart& s = starts_[i];
    return straight_lines_ ? Vec3(s.p0 + (now_ - s.t0) * s.v0) : PathOf(i).PositionAt(now_);
  }
  Vec3 VelocityNow(std::uint32_t i) const {
    return straight_lines_ ? starts_[i].v0 : PathOf(i).VelocityAt(now_);
  }
  double Radius(std::uint32_t i) const { return materials_[material_[i]].radius; }
  double InvMass(std::uint32_t i) const { return materials_[material_[i]].inv_mass; }
  double Restitution(std::uint32_t i) const { return materials_[material_[i]].restitution; }
  double Friction(std::uint32_t i) const { return materials_[material_[i]].friction; }

  // --- polyhedra (issue #4; empty in a World of spheres) ---
  struct Shape {  // shared by every body of that shape
    std::shared_ptr<const ConvexPolyhedron> given;       // BodyDef::shape (keeps its address)
    std::shared_ptr<const ConvexPolyhedron> polyhedron;  // centroid at the body-frame origin
    std::shared_ptr<const TrackedPolyhedron> tracked;    // the walk's tables
    Eigen::Matrix3d unit_inertia;      // inertia per unit mass, body frame (RotationModel)
    Eigen::Matrix3d unit_inv_inertia;  // its inverse
  };
  std::vector<Shape> shapes_;
  std::map<const ConvexPolyhedron*, std::uint32_t> shape_index_;  // as given in BodyDef::shape
  std::vector<std::uint32_t> shape_;        // per body, into shapes_
  std::vector<Eigen::Quaterniond> q0_;      // per body: orientation at its segment start
  std::vector<Vec3> omega_;                 // per body: angular velocity, world frame
  std::vector<double> spin_radius_;         // per body: SpinRadius of its current segment
  bool polyhedra_ = false;
  // Set while a body that touched a wall without approaching it predicts again: that wall is
  // then left alone for the time the body needs to close the tolerance band.
  std::optional<std::pair<std::uint32_t, int>> wall_band_skip_;

  RigidPath RigidPathOf(std::uint32_t i) const {
    return RigidPath{PathOf(i), q0_[i], omega_[i]};
  }
  const Shape& ShapeOf(std::uint32_t i) const { return shapes_[shape_[i]]; }
  /// narrow::SpinRadius of body i's current segment (kept in spin_radius_ when its spin changes).
  double SpinRadiusOf(std::uint32_t i) const;
  /// Inverse inertia in the world frame at orientation q.
  Eigen::Matrix3d InvInertiaWorld(std::uint32_t i, const Eigen::Quaterniond& q) const {
    const Eigen::Matrix3d r = q.toRotationMatrix();
    return InvMass(i) * r * ShapeOf(i).unit_inv_inertia * r.transpose();
  }
  /// Elements' spheres that meet become engaged and the detailed phase watches them.
  bool EngagesOnMeet() const { return has_envelopes_ || polyhedra_; }
  std::vector<Envelope> envelope_;          // empty unless some body has an envelope
  struct Candidate {                        // the earliest meeting found by the last prediction
    double time = kInfinity;
    std::uint32_t target = kNoIndex;
    std::uint32_t target_version = 0;
  };
  // Each element's one outstanding prediction (§4): the kind of its queued event (the queue
  // holds the time) and the meeting its last prediction found, which a crossing keeps and a
  // kSphereMeet event is with; and the element's version (§4.2), which its events bump and its
  // partners' predictions copy. One 24-byte record, as every event reads them all; it lives in
  // the element's queue entry (its payload), so that the lines the queue's walks fetch hold it.
  struct Prediction : Candidate {
    EventKind kind = EventKind::kNone;
    std::uint8_t aux = 0;  // kWallMeet: the wall; kCellCrossing: axis * 2 + (1 if upwards)
    std::uint32_t version = 0;  // the element's own path changes so far (in the padding)
    // A kCellCrossing's face, from `aux`: the axis, and +1 or -1 (arithmetic: no branch).
    int CrossingAxis() const { return aux / 2; }
    int CrossingDirection() const { return 2 * (aux & 1) - 1; }
  };
  static_assert(sizeof(Prediction) == 24);
  Prediction& PredictionOf(std::uint32_t e) { return queue_.PayloadOf(e); }
  const Prediction& PredictionOf(std::uint32_t e) const { return queue_.PayloadOf(e); }
  // Internal indices follow space (Reorder); the public BodyId index is the order of AddBody.
  std::vector<std::uint32_t> public_of_;    // internal index -> public index
  std::vector<std::uint32_t> internal_of_;  // public index -> internal index
  std::uint64_t events_since_reorder_ = 0;
  std::uint64_t reorder_period_ =  // events between renumberings (none: no grid)
      std::numeric_limits<std::uint64_t>::max();

  bool started_ = false;
  bool has_envelopes_ = false;
  bool straight_lines_ = false;  // no envelopes and no acceleration: the fast meeting test
  // While a scan runs: the time after which no meeting can become the actor's event (its next
  // wrap in a periodic AllPairs box), else infinity. ConsiderMeeting skips pairs apart so long.
  double scan_limit_ = kInfinity;
  // Whether every element is a sphere without an envelope on a straight line (straight_lines_
  // as Start sets it; the fast scan also skips the engaged-pair check).
  bool StraightLines() const {
    return !has_envelopes_ && !polyhedra_ && !own_accelerations_ &&
           uniform_acceleration_.isZero(0.0);
  }
  bool batch_tests_ = false;     // straight lines, few enough elements: TestGathered
  bool fetch_ahead_ = false;     // a gas on a grid beyond the caches: FetchAhead
  bool linear_finish_ = false;   // straight lines on a grid, no walls: FinishLinearPrediction
  static constexpr std::uint32_t kBatchTestMaxElements = 1u << 18;
  static constexpr std::uint32_t kFetchAheadMinElements = 40000;
  double max_radius_ = 0.0;
  std::optional<Grid> grid_;
  std::optional<AllPairs> all_pairs_;
  BigVector<std::uint32_t> gathered_;  // the Grid gathers' work list, then TestGathered's hits
  BasicCalendarQueue<Prediction> queue_;  // one slot per element, with its prediction
  CalendarQueue engagement_queue_;  // one slot per engagement
  Engagements engagements_;
  OverlapIndex overlap_index_;  // bodies added before the start, for AddBody's overlap check

 private:
  // --- start-up and checks (world.cpp) ---
  void Start();
  std::optional<std::uint32_t> FindOverlap(const Vec3& p, double radius) const;
  // Inline: a collision of a gas checks its pair's distance through it.
  Vec3 MinimumImage(Vec3 d) const {
    if (!periodic_) return d;
    for (int k = 0; k < 3; ++k) d[k] -= period_[k] * RoundNearOne(d[k] / period_[k]);
    return d;
  }
  Vec3 WrapIntoBox(Vec3 p) const;

  // --- memory order (world_reorder.cpp) ---
  /// Counts an event and renumbers the elements when reorder_period_ of them have passed.
  void MaybeReorder() {
    if (++events_since_reorder_ < reorder_period_) return;
    events_since_reorder_ = 0;
    Reorder();
  }
  void SetReorderPeriod();  // after the element count or the broad phase changed
  void Reorder();
  BodyId PublicId(std::uint32_t i) const { return BodyId{public_of_[i], 0}; }

  // --- predictions (world_predict.cpp) ---
  Mover MoverOf(std::uint32_t i, double t) const;
  Mover BodyMoverOf(std::uint32_t i, double t) const;  // the body itself, without envelope
  void PredictFull(std::uint32_t i);
  /// After i crossed into the grid cell at `place` across (axis, direction).
  void PredictAfterCrossing(std::uint32_t i, const Grid::Place& place, int axis, int direction);
  /// Lets `scan(best)` look for meetings earlier than `best`, adds walls and the cell crossing
  /// (i's cell at `place`, null without a grid) and schedules the earliest.
  template <typename Scan>
  void PredictWith(std::uint32_t i, Candidate best, const Grid::Place* place, Scan&& scan);
  void ConsiderMeeting(std::uint32_t i, std::uint32_t j, const Vec3& shift, Candidate& best);
  // ConsiderMeeting for each of AllPairs' images of j; whether an engagement tracks the pair
  // (the sparse phase then leaves it); the time a pair is predicted from; the test of one
  // image, given the two movers at that time.
  void ConsiderImages(std::uint32_t i, std::uint32_t j, Candidate& best);
  bool EngagedPair(std::uint32_t i, std::uint32_t j) const;
  double PairReference(std::uint32_t i, std::uint32_t j) const;
  void ConsiderImage(const Mover& a, const Mover& b, const std::optional<ApartBound>& bound,
                     double reference, std::uint32_t j, const Vec3& shift, Candidate& best);
  double WrapTime(std::uint32_t i) const;  // AllPairs: i's next wrap in a periodic box
  void Offer(Candidate& best, double t, std::uint32_t j) const;  // keeps the earlier meeting
  // ScanNeighbors' rare step, out of the cell walk: certifies a root of LinearMeetingRoot.
  [[gnu::noinline]] void OfferLinearMeeting(const PathStart& pi, std::uint32_t j, const Vec3& shift,
                                            double reach, double dt, Candidate& best);
  template <typename VisitNeighbors>
  void ScanNeighbors(std::uint32_t i, Candidate& best, VisitNeighbors&& visit);
  /// ScanNeighbors for straight lines over what `gather(fn)` visits (a Grid gather near i's
  /// cell at `place`: the 27 `around` it, i included, or the 9 new ones; kWrapped: one that may
  /// wrap, with image shifts), without branches on the data. TestGatheredOf picks the form.
  template <bool kOneMaterial, bool kWrapped, typename Gather>
  void TestGathered(std::uint32_t i, const Grid::Place& place, bool around, Candidate& best,
                    Gather&& gather);
  template <bool kWrapped, typename Gather>
  void TestGatheredOf(std::uint32_t i, const Grid::Place& place, bool around, Candidate& best,
                      Gather&& gather);
  Event FinishPrediction(std::uint32_t i, const Candidate& best);
  struct Crossing {  // an element's next cell crossing: when, and across which face
    double time;
    int axis;
    int direction;
  };
  Crossing PredictLinearCrossing(std::uint32_t i, const Grid::Place& place) const;
  Event FinishLinearPrediction(std::uint32_t i, const Candidate& best, const Crossing& crossing);
  double PredictWall(const Mover& mi, std::uint8_t& wall) const;
  void Schedule(std::uint32_t i, const Event& event);
  void PredictEngagement(std::uint32_t k);
  /// Predicts all of i's engagements again, except the one with `done_partner` (a pair that
  /// collided has its engagement predicted once, from its first body).
  void PredictEngagementsOf(std::uint32_t i, std::uint32_t done_partner = kNoIndex);

  // --- the detailed phase for polyhedra (world_polyhedra.cpp) ---
  Result<std::uint32_t> AddShape(const std::shared_ptr<const ConvexPolyhedron>& shape);
  std::optional<std::uint32_t> FindPolyhedronOverlap(const BodyDef& def, std::uint32_t shape,
                                                     double& distance) const;
  Vec3 PairShift(std::uint32_t a, std::uint32_t b) const;
  double PairTolerance(std::uint32_t a, std::uint32_t b) const;
  ClosestFeatures PairFeatures(std::uint32_t a, std::uint32_t b, const Vec3& shift,
                               std::optional<FeaturePair> warm) const;
  void EngageOverlappingAtStart();
  void PredictPolyhedralEngagement(std::uint32_t k);
  void HandlePolyhedralEngagement(std::uint32_t k);
  bool CollidePolyhedra(std::uint32_t a, std::uint32_t b, const ClosestFeatures& features,
                        const Vec3& shift);
  Event PredictPolyhedronWalls(std::uint32_t i, Event event);
  void HandlePolyhedronWall(std::uint32_t i);
  void SetMotion(std::uint32_t i, const Vec3& v, const Vec3& omega);
  Status ValidatePolyhedra() const;

  // --- handlers (world_loop.cpp) ---
  void Dispatch(const QueueTop& top, bool engagement);
  // The look-ahead: fetches what the next events will read while this one is handled.
  void FetchAhead() const;
  void FetchElement(std::uint32_t e) const;
  std::uint32_t CellAhead(std::uint32_t e) const;
  void HandleSphereMeet(std::uint32_t i);
  void HandleWallMeet(std::uint32_t i);
  void HandleCellCrossing(std::uint32_t i);
  void HandleEngagement(std::uint32_t k);
  void Collide(std::uint32_t i, std::uint32_t j, const Vec3& normal, double gap);
  void SetVelocity(std::uint32_t i, const Vec3& v);
  void ReportSegment(std::uint32_t i);
  // The event loop's progress over windows of stall_event_limit events: a clock that stands
  // still (a stall) or crawls on collisions slower than the collapse guard ends AdvanceTo with
  // an error, never a hang.
  struct ProgressWindow {
    std::uint64_t events;   // in this window so far
    double start;           // the clock at its start
    std::uint64_t guarded;  // Statistics::collapse_guarded at its start
  };
  Status CheckProgress(const QueueTop& top, bool engagement, ProgressWindow& window) const;
  double MaxFreeAcceleration() const;
  bool HoldAgainstWall(std::uint32_t i, int w, const Vec3& normal, const Vec3& v, double gap);
  void SetHeld(std::uint32_t i, std::uint8_t walls, Vec3 v);
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

/// std::nextafter(t, -kInfinity) for t not NaN and not -kInfinity, without the library call
/// (it is on the path of every prediction): the next double below t.
inline double NextDown(double t) {
  if (t == 0.0) return -std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(t);
  return std::bit_cast<double>(t > 0 ? bits - 1 : bits + 1);
}

/// Absolute event time now + dt rounded down: the largest double not after the exact sum, so
/// that rounding never makes an event late. The rounding error of the sum is exact (Knuth's
/// two-sum); comparing t - now with dt instead misses the cases where t - now is rounded too.
inline double EventTime(double now, double dt) {
  if (dt == kInfinity) return kInfinity;
  const double t = now + dt;
  const double error = TwoSumError(now, dt, t);
  // Rounded up half the time: a select, not a branch the predictor would miss half the time.
  // A negative error means the exact sum is not zero, so t = 0 (NextDown's special case) can
  // only come with error >= 0 and the bit step below is NextDown's for t != 0.
  const auto bits = std::bit_cast<std::uint64_t>(t);
  const std::uint64_t down = t > 0 ? bits - 1 : bits + 1;
  return std::bit_cast<double>(error < 0 ? down : bits);
}

/// Wall planes of a walled box: inward unit normal n and offset d (n.x >= d inside).
struct WallPlane {
  Vec3 normal;
  double offset;
};
WallPlane BoxWall(const Container& box, int wall);

}  // namespace sparsedyn
