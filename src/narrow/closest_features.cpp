// SPDX-License-Identifier: MIT
// The closest-feature walk (thesis §5.1; Lin & Canny 1991, made robust as in Mirtich's V-Clip
// 1998) and the tracker that warm-starts it. docs/narrow-phase.md explains the rules.
#include "sparsedyn/narrow/closest_features.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "narrow/feature_distance.hpp"
#include "narrow/pair_frame.hpp"
#include "narrow/penetration.hpp"
#include "narrow/tables.hpp"
#include "narrow/zone_check.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

using narrow::FeatureClosest;
using narrow::Move;

// Round-off allowance, relative to the larger polyhedron's scale(): two computations of the same
// feature-pair distance by different formulas agree to a few ulps of the coordinates; 64 ulps
// leaves room for the transform between the frames.
constexpr double kRoundOff = 64.0 * std::numeric_limits<double>::epsilon();

enum class WalkEnd : std::uint8_t {
  kTerminal,   // no zone plane violated: the pair is closest (or touching, if distance ~ 0)
  kContact,    // the current features meet (distance 0, or within round-off at a local minimum)
  kContained,  // a closest point lies inside the other polyhedron
  kCap,        // options.max_steps reached
};

class Walk {
 public:
  Walk(const TrackedPolyhedron& a, const TrackedPolyhedron& b, const narrow::PairFrame& frame,
       const ClosestFeaturesOptions& options)
      : a_(a.polyhedron()),
        b_(b.polyhedron()),
        tables_a_(options.use_angle_tables ? &a.tables() : nullptr),
        tables_b_(options.use_angle_tables ? &b.tables() : nullptr),
        frame_(frame),
        max_steps_(options.max_steps),
        tolerance_(kRoundOff * std::max(a_.scale(), b_.scale())) {}

  double tolerance() const { return tolerance_; }

  // Walks from `start` until no zone plane is violated (or contact / containment / the cap).
  WalkEnd Run(FeaturePair start) {
    pair_ = start;
    Closest(pair_.a, pair_.b, closest_);
    best_ = closest_.distance;
    while (true) {
      if (closest_.distance == 0.0) return WalkEnd::kContact;
      if (steps_ >= max_steps_) return WalkEnd::kCap;
      // A's zone against B's closest point, then B's zone against A's.
      Outcome outcome = StepOnA();
      if (outcome == Outcome::kNone) outcome = StepOnB();
      if (outcome == Outcome::kContained) return WalkEnd::kContained;
      if (outcome == Outcome::kTouching) return WalkEnd::kContact;
      if (outcome == Outcome::kNone) return WalkEnd::kTerminal;
      ++steps_;
    }
  }

  const FeaturePair& pair() const { return pair_; }
  const FeatureClosest& closest() const { return closest_; }
  int steps() const { return steps_; }

 private:
  enum class Outcome : std::uint8_t { kNone, kMoved, kContained, kTouching };

  void Closest(FeatureId fa, FeatureId fb, FeatureClosest& out) const {
    narrow::ClosestPointsOfFeatures(a_, tables_a_, fa, b_, tables_b_, fb, frame_, out);
  }

  // The V-Clip potential, made safe for round-off: a step that raises the dimension must lower
  // the smallest distance seen so far; a step that lowers the dimension (which keeps the
  // distance in exact arithmetic) may exceed it by the round-off tolerance only. The smallest
  // distance strictly decreases at every higher step and the dimension sum at every lower one,
  // so no pair repeats between two face escapes.
  bool Accept(Move::Kind kind, double distance) const {
    if (kind == Move::Kind::kHigher) return distance < best_;
    return distance <= best_ + tolerance_;
  }

  void Take(FeaturePair pair, const FeatureClosest& closest) {
    pair_ = pair;
    closest_ = closest;
    best_ = std::min(best_, closest.distance);
  }

  // The face of `polyhedron` whose plane q is farthest in front of (V-Clip's escape from a local
  // minimum); nullopt when q is behind or on every face plane, i.e. inside the polyhedron.
  static std::optional<int> FaceInFrontOf(const ConvexPolyhedron& polyhedron,
                                          const Eigen::Vector3d& q) {
    int best_face = -1;
    double best_distance = 0.0;
    for (int f = 0; f < polyhedron.face_count(); ++f) {
      const double d = polyhedron.face(f).plane.SignedDistance(q);
      if (d > best_distance) {
        best_distance = d;
        best_face = f;
      }
    }
    if (best_face < 0) return std::nullopt;
    return best_face;
  }

  Outcome StepOnA() {
    // A face against a vertex was tested by Closest already (closest_.verdict_a).
    const narrow::ZoneTest test =
        narrow::TestZone(a_, tables_a_, pair_.a, closest_.p_b, closest_.slot_a, closest_.verdict_a);
    if (test.result == narrow::ZoneTest::Result::kInZone) return Outcome::kNone;
    narrow::Moves moves;
    if (test.result == narrow::ZoneTest::Result::kOneMove) {
      moves.Add(test.move);
    } else {
      moves = narrow::ZoneMoves(a_, tables_a_, pair_.a, closest_.p_b, closest_.slot_a,
                                closest_.verdict_a);
    }
    for (int i = 0; i < moves.count; ++i) {
      const Move& move = moves.list[static_cast<std::size_t>(i)];
      if (move.kind == Move::Kind::kBehindFace) {
        if (closest_.distance <= tolerance_) return Outcome::kTouching;
        const std::optional<int> face = FaceInFrontOf(a_, closest_.p_b);
        if (!face) return Outcome::kContained;
        Escape({FeatureId::Face(*face), pair_.b});
        return Outcome::kMoved;
      }
      FeatureClosest candidate;
      Closest(move.to, pair_.b, candidate);
      if (Accept(move.kind, candidate.distance)) {
        Take({move.to, pair_.b}, candidate);
        return Outcome::kMoved;
      }
    }
    return Outcome::kNone;
  }

  Outcome StepOnB() {
    // A's vertex in the zone of B's face: known without the vertex in B's frame.
    if (closest_.verdict_b == narrow::FaceVerdict::kInZone) return Outcome::kNone;
    const Eigen::Vector3d q = frame_.ToB(closest_.p_a);
    const narrow::ZoneTest test =
        narrow::TestZone(b_, tables_b_, pair_.b, q, closest_.slot_b, closest_.verdict_b);
    if (test.result == narrow::ZoneTest::Result::kInZone) return Outcome::kNone;
    narrow::Moves moves;
    if (test.result == narrow::ZoneTest::Result::kOneMove) {
      moves.Add(test.move);
    } else {
      moves = narrow::ZoneMoves(b_, tables_b_, pair_.b, q, closest_.slot_b, closest_.verdict_b);
    }
    for (int i = 0; i < moves.count; ++i) {
      const Move& move = moves.list[static_cast<std::size_t>(i)];
      if (move.kind == Move::Kind::kBehindFace) {
        if (closest_.distance <= tolerance_) return Outcome::kTouching;
        const std::optional<int> face = FaceInFrontOf(b_, q);
        if (!face) return Outcome::kContained;
        Escape({pair_.a, FeatureId::Face(*face)});
        return Outcome::kMoved;
      }
      FeatureClosest candidate;
      Closest(pair_.a, move.to, candidate);
      if (Accept(move.kind, candidate.distance)) {
        Take({pair_.a, move.to}, candidate);
        return Outcome::kMoved;
      }
    }
    return Outcome::kNone;
  }

  // Leaving a local minimum may raise the distance: the potential starts afresh from there.
  // Never within round-off of touching (the callers' kTouching): there a point "behind" a face
  // is touching it, and escapes that restart the potential can cycle (seen on a random hull
  // touching a tetrahedron: face -> escape -> edge -> face ... at distances of 1e-16).
  void Escape(FeaturePair pair) {
    pair_ = pair;
    Closest(pair.a, pair.b, closest_);
    best_ = closest_.distance;
  }

  const ConvexPolyhedron& a_;
  const ConvexPolyhedron& b_;
  const TrackedPolyhedron::Tables* tables_a_;
  const TrackedPolyhedron::Tables* tables_b_;
  const narrow::PairFrame& frame_;
  int max_steps_;
  double tolerance_;
  FeaturePair pair_;
  FeatureClosest closest_;  // written in place by Closest: no copy of a returned answer
  double best_ = 0.0;
  int steps_ = 0;
};

bool IsValidFeature(const ConvexPolyhedron& polyhedron, FeatureId feature) {
  switch (feature.type) {
    case FeatureType::kVertex:
      return feature.index >= 0 && feature.index < polyhedron.vertex_count();
    case FeatureType::kEdge:
      return feature.index >= 0 && feature.index < polyhedron.edge_count();
    case FeatureType::kFace:
      return feature.index >= 0 && feature.index < polyhedron.face_count();
    case FeatureType::kNone:
      break;
  }
  return false;
}

// The cold start: J.1.2 looks up each polyhedron's feature facing the other's centroid.
FeaturePair ColdStart(const TrackedPolyhedron& a, const TrackedPolyhedron& b,
                      const narrow::PairFrame& frame, bool use_direction_table) {
  if (!use_direction_table) return {FeatureId::Vertex(0), FeatureId::Vertex(0)};
  const Eigen::Vector3d toward_b = frame.ToA(b.polyhedron().centroid()) - a.polyhedron().centroid();
  const Eigen::Vector3d toward_a = frame.ToB(a.polyhedron().centroid()) - b.polyhedron().centroid();
  return {a.StartingFeature(toward_b), b.StartingFeature(toward_a)};
}

// FindClosestFeatures writing into `out` (every field is set on every path), so that the tracker
// fills its cached answer in place instead of copying a fresh one over it at every update.
// Inlined into both callers: the call's register saves are ~1% of a warm update.
[[gnu::always_inline]] inline void FindClosestFeaturesInto(
    const TrackedPolyhedron& a, const Pose& X_WA, const TrackedPolyhedron& b, const Pose& X_WB,
    const FeaturePair* start, const ClosestFeaturesOptions& options, ClosestFeatures& out) {
  const narrow::PairFrame frame(X_WA, X_WB);
  FeaturePair first;
  if (start != nullptr) {
    SPARSEDYN_ASSERT(
        IsValidFeature(a.polyhedron(), start->a) && IsValidFeature(b.polyhedron(), start->b),
        "FindClosestFeatures: start pair is not a feature of each polyhedron");
    first = *start;
  } else {
    first = ColdStart(a, b, frame, options.use_direction_table);
  }
  Walk walk(a, b, frame, options);
  const WalkEnd end = walk.Run(first);

  const Eigen::Matrix3d& R_WA = frame.R_WA;
  out.steps = walk.steps();
  out.features = walk.pair();
  const FeatureClosest& closest = walk.closest();
  auto set_points = [&](const Eigen::Vector3d& p_a, const Eigen::Vector3d& p_b,
                        const Eigen::Vector3d& normal_A) {
    out.point_a = R_WA * p_a + X_WA.translation;
    out.point_b = R_WA * p_b + X_WA.translation;
    out.normal = R_WA * normal_A;
  };
  // The separated answer, the common one: B's witness is A's plus the gap, and the normal the
  // gap over the distance (two rotations and one division instead of three and three).
  auto set_separated = [&] {
    out.point_a = R_WA * closest.p_a + X_WA.translation;
    const Eigen::Vector3d gap_W = R_WA * (closest.p_b - closest.p_a);
    out.point_b = out.point_a + gap_W;
    out.normal = gap_W * (1.0 / closest.distance);
  };
  const Eigen::Vector3d gap = closest.p_b - closest.p_a;
  if (end == WalkEnd::kCap) {
    out.status = ClosestFeatures::Status::kIterationCap;
    out.distance = closest.distance;
    set_points(closest.p_a, closest.p_b,
               closest.distance > 0.0 ? Eigen::Vector3d(gap / closest.distance)
                                      : Eigen::Vector3d::UnitX());
    return;
  }
  if (end == WalkEnd::kTerminal && closest.distance > walk.tolerance()) {
    out.status = ClosestFeatures::Status::kSeparated;
    out.distance = closest.distance;
    set_separated();
    return;
  }
  // Contact, containment or a terminal pair within round-off of touching: the separating axis
  // test decides, and gives the depth of a penetration.
  const narrow::SeparatingAxis axis =
      narrow::DeepestSeparatingAxis(a.polyhedron(), b.polyhedron(), frame);
  if (end == WalkEnd::kTerminal && axis.separation > 0.0) {
    out.status = ClosestFeatures::Status::kSeparated;
    out.distance = closest.distance;
    set_separated();
    return;
  }
  // Touching counts as penetrating with depth 0 (a round-off positive separation of features
  // that meet is not a gap).
  out.status = ClosestFeatures::Status::kPenetrating;
  out.distance = std::min(axis.separation, 0.0);
  out.features = {axis.feature_a, axis.feature_b};
  set_points(axis.p_a, axis.p_b, axis.normal);
  // Witnesses: where the two touch once B is pushed out by the depth along the axis (plus a
  // margin so that the walk sees a gap); the walk there also names the touching features.
  const double margin = 1e-6 * std::max(a.polyhedron().scale(), b.polyhedron().scale());
  narrow::PairFrame pushed = frame;
  const Eigen::Vector3d shift = (margin - out.distance) * axis.normal;
  pushed.p_AB += shift;
  Walk witness_walk(a, b, pushed, options);
  if (witness_walk.Run({axis.feature_a, axis.feature_b}) == WalkEnd::kTerminal) {
    out.steps += witness_walk.steps();
    out.features = witness_walk.pair();
    set_points(witness_walk.closest().p_a, witness_walk.closest().p_b - shift, axis.normal);
  }
}

}  // namespace

ClosestFeatures FindClosestFeatures(const TrackedPolyhedron& a, const Pose& X_WA,
                                    const TrackedPolyhedron& b, const Pose& X_WB,
                                    std::optional<FeaturePair> start,
                                    const ClosestFeaturesOptions& options) {
  ClosestFeatures out;
  FindClosestFeaturesInto(a, X_WA, b, X_WB, start ? &*start : nullptr, options, out);
  return out;
}

ClosestFeatureTracker::ClosestFeatureTracker(const TrackedPolyhedron& a, const TrackedPolyhedron& b,
                                             ClosestFeaturesOptions options)
    : a_(&a), b_(&b), options_(options) {}

const ClosestFeatures& ClosestFeatureTracker::Update(const Pose& X_WA, const Pose& X_WB) {
  // The start by pointer, not std::optional: copying through the optional cost ~16 of the
  // ~850 instructions of an update. `previous` outlives the overwrite of last_.features.
  const FeaturePair previous = last_.features;
  const bool warm = has_last_;
  FindClosestFeaturesInto(*a_, X_WA, *b_, X_WB, warm ? &previous : nullptr, options_, last_);
  has_last_ = true;
  ++calls_;
  steps_ += static_cast<std::uint64_t>(last_.steps);
  if (last_.status == ClosestFeatures::Status::kIterationCap) {
    ++cap_failures_;
    last_failure_ = DescribeQuery(*a_, X_WA, *b_, X_WB,
                                  warm ? std::optional<FeaturePair>(previous) : std::nullopt);
  }
  return last_;
}

}  // namespace sparsedyn
