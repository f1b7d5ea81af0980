// SPDX-License-Identifier: MIT
// FindClosestFeatureToPoint: the Lin-Canny walk of closest_features.cpp with one side a point.
// The point's zone tests and the closest points of features are the pair walk's own
// (zone_check.hpp, feature_distance.hpp); docs/narrow-phase.md explains the rules.
#include "narrow/point_features.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "narrow/feature_distance.hpp"
#include "narrow/tables.hpp"
#include "narrow/zone_check.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

using narrow::FaceVerdict;
using narrow::Move;

// Round-off allowance of a lower step, relative to the polyhedron's scale(): the pair walk's
// (two formulas for the same distance agree to a few ulps of the coordinates).
constexpr double kRoundOff = 64.0 * std::numeric_limits<double>::epsilon();

// A feature and its closest point to the query point q (body frame).
struct Candidate {
  FeatureId feature;
  Vec3 point = Vec3::Zero();
  double distance = 0.0;
  int slot = -1;                                // face: FacePoint::edge_slot
  FaceVerdict verdict = FaceVerdict::kUnknown;  // face: its zone test, decided by the point
};

class PointWalk {
 public:
  PointWalk(const TrackedPolyhedron& polyhedron, const Vec3& q,
            const ClosestFeaturesOptions& options)
      : poly_(polyhedron.polyhedron()),
        tables_(options.use_angle_tables ? &polyhedron.tables() : nullptr),
        q_(q),
        max_steps_(options.max_steps),
        // Distances are differences of coordinates as large as the point's and the
        // vertices' (a point far from a small polyhedron has a large distance's round-off).
        tolerance_(kRoundOff * (poly_.scale() + poly_.centroid().norm() + q.norm())) {}

  // The answer, in the body frame (PointClosest's fields with body-frame point and normal).
  PointClosest Run(FeatureId start) {
    current_ = Evaluate(start);
    best_ = current_.distance;
    while (true) {
      if (steps_ >= max_steps_) return BruteForce();
      const narrow::ZoneTest test =
          narrow::TestZone(poly_, tables_, current_.feature, q_, current_.slot, current_.verdict);
      if (test.result == narrow::ZoneTest::Result::kInZone) return Outside(current_);
      narrow::Moves moves;
      if (test.result == narrow::ZoneTest::Result::kOneMove) {
        moves.Add(test.move);
      } else {
        moves = narrow::ZoneMoves(poly_, tables_, current_.feature, q_, current_.slot,
                                  current_.verdict);
      }
      const Step step = TakeStep(moves);
      if (step == Step::kNone) return Outside(current_);
      if (step == Step::kInside) return Inside(escape_face_, escape_height_);
      if (step == Step::kGiveUp) return BruteForce();
      ++steps_;
    }
  }

 private:
  enum class Step : std::uint8_t { kMoved, kNone, kInside, kGiveUp };

  Candidate Evaluate(FeatureId f) const {
    Candidate c{f};
    if (f.type == FeatureType::kVertex) {
      c.point = poly_.vertex(f.index);
    } else if (f.type == FeatureType::kEdge) {
      const Edge& e = poly_.edge(f.index);
      c.point = narrow::ClosestSegmentSegment(poly_.vertex(e.vertices[0]),
                                              poly_.vertex(e.vertices[1]), q_, q_)
                    .p;
    } else {
      const narrow::FacePoint p = narrow::ClosestPointOnFace(
          poly_, f.index, tables_ == nullptr ? nullptr : tables_->face(f.index), q_);
      c.point = p.point;
      c.slot = p.edge_slot;
      c.verdict = p.edge_slot >= 0 ? FaceVerdict::kBeside
                                   : (p.height < 0.0 ? FaceVerdict::kBehind : FaceVerdict::kInZone);
    }
    c.distance = (q_ - c.point).norm();
    return c;
  }

  // The first of the proposed moves that keeps the potential (a higher step strictly below the
  // best distance seen, a lower one within round-off of it), or an escape. A higher step
  // refused improved the distance by less than the round-off, so stopping there is within
  // round-off of the answer; a lower step keeps the distance in exact arithmetic, so one
  // refused means round-off beyond the allowance, and the search of every face decides.
  Step TakeStep(const narrow::Moves& moves) {
    bool lower_refused = false;
    for (int i = 0; i < moves.count; ++i) {
      const Move& move = moves.list[static_cast<std::size_t>(i)];
      if (move.kind == Move::Kind::kBehindFace) return Escape();
      const Candidate candidate = Evaluate(move.to);
      const bool accept = move.kind == Move::Kind::kHigher
                              ? candidate.distance < best_
                              : candidate.distance <= best_ + tolerance_;
      if (accept) {
        current_ = candidate;
        best_ = std::min(best_, candidate.distance);
        return Step::kMoved;
      }
      lower_refused |= move.kind == Move::Kind::kLower;
    }
    return lower_refused ? Step::kGiveUp : Step::kNone;
  }

  // Over a face but behind its plane: the point is inside (no face plane has it strictly in
  // front), or the walk is at V-Clip's local minimum and jumps to the face whose plane has the
  // point farthest in front, restarting the potential there (the pair walk's rule, also in
  // not escaping within round-off of touching). Argmax is deterministic, so a repeated target
  // would repeat the walk: the search of every face ends it instead.
  Step Escape() {
    // Behind the face by no more than round-off: the point is on the surface (to round-off),
    // and |height| is its distance within twice that; no escape, which could only bounce
    // between faces that round-off puts on either side of the point.
    if (current_.distance <= tolerance_) {
      escape_face_ = current_.feature.index;
      escape_height_ = -current_.distance;
      return Step::kInside;
    }
    int face = 0;
    double height = -std::numeric_limits<double>::infinity();
    for (int f = 0; f < poly_.face_count(); ++f) {
      const double h = poly_.face(f).plane.SignedDistance(q_);
      if (h > height) {
        height = h;
        face = f;
      }
    }
    if (height <= 0.0) {
      escape_face_ = face;
      escape_height_ = height;
      return Step::kInside;
    }
    if (std::find(escaped_.begin(), escaped_.end(), face) != escaped_.end()) return Step::kGiveUp;
    escaped_.push_back(face);
    current_ = Evaluate(FeatureId::Face(face));
    best_ = current_.distance;
    return Step::kMoved;
  }

  // Inside: the distance to the boundary is the distance to the nearest face plane, and the
  // projection there lies on that face (the ball of that radius about q is inside every
  // half-space, so its touching point on the plane is in the polyhedron).
  PointClosest Inside(int face, double height) const {
    const Vec3& n = poly_.face(face).plane.normal;
    return {FeatureId::Face(face), height, q_ - height * n, n, steps_, brute_force_};
  }

  PointClosest Outside(const Candidate& c) const {
    const Vec3 normal = c.distance > 0.0 ? Vec3((q_ - c.point) / c.distance) : OutwardNormal(c);
    return {c.feature, c.distance, c.point, normal, steps_, brute_force_};
  }

  // A feature's outward normal, for a point exactly on the surface.
  Vec3 OutwardNormal(const Candidate& c) const {
    if (c.feature.type == FeatureType::kFace) return poly_.face(c.feature.index).plane.normal;
    Vec3 sum = Vec3::Zero();
    if (c.feature.type == FeatureType::kEdge) {
      for (const int f : poly_.edge(c.feature.index).faces) sum += poly_.face(f).plane.normal;
    } else {
      for (const int f : poly_.VertexFaces(c.feature.index)) sum += poly_.face(f).plane.normal;
    }
    return sum.normalized();
  }

  // Every face's closest point: the nearest names the answer (its boundary edge, or the vertex
  // at that edge's end, when the point is on the boundary); inside when behind every face.
  PointClosest BruteForce() {
    brute_force_ = true;
    int inside_face = 0;
    double inside_height = -std::numeric_limits<double>::infinity();
    Candidate best{FeatureId::Face(0), Vec3::Zero(), std::numeric_limits<double>::infinity()};
    for (int f = 0; f < poly_.face_count(); ++f) {
      const double h = poly_.face(f).plane.SignedDistance(q_);
      if (h > inside_height) {
        inside_height = h;
        inside_face = f;
      }
      const Candidate c = Evaluate(FeatureId::Face(f));
      if (c.distance < best.distance) best = c;
    }
    if (inside_height <= 0.0) return Inside(inside_face, inside_height);
    if (best.slot >= 0) {
      const int e = poly_.FaceEdges(best.feature.index)[static_cast<std::size_t>(best.slot)];
      best = Evaluate(FeatureId::Edge(e));
      for (const int v : poly_.edge(e).vertices) {
        if (poly_.vertex(v) == best.point) best = Evaluate(FeatureId::Vertex(v));
      }
    }
    return Outside(best);
  }

  const ConvexPolyhedron& poly_;
  const TrackedPolyhedron::Tables* tables_;
  Vec3 q_;
  int max_steps_;
  double tolerance_;
  Candidate current_;
  double best_ = 0.0;
  int steps_ = 0;
  bool brute_force_ = false;
  std::vector<int> escaped_;  // faces escaped to since the start (almost always 0 or 1)
  int escape_face_ = 0;
  double escape_height_ = 0.0;
};

bool IsFeatureOf(const ConvexPolyhedron& poly, FeatureId f) {
  const int count = f.type == FeatureType::kVertex ? poly.vertex_count()
                    : f.type == FeatureType::kEdge ? poly.edge_count()
                    : f.type == FeatureType::kFace ? poly.face_count()
                                                   : 0;
  return f.index >= 0 && f.index < count;
}

}  // namespace

PointClosest FindClosestFeatureToPoint(const TrackedPolyhedron& polyhedron, const Pose& X_WA,
                                       const Vec3& p_W, std::optional<FeatureId> start,
                                       const ClosestFeaturesOptions& options) {
  const ConvexPolyhedron& poly = polyhedron.polyhedron();
  // Subtract before rotating, so a point far from the origin keeps its offset's precision.
  const Vec3 q = X_WA.ToBody(p_W);
  FeatureId first = FeatureId::Vertex(0);
  if (start) {
    SPARSEDYN_ASSERT(IsFeatureOf(poly, *start),
                     "FindClosestFeatureToPoint: start is not a feature of the polyhedron");
    first = *start;
  } else if (options.use_direction_table) {
    const Vec3 direction = q - poly.centroid();
    if (direction.squaredNorm() > 0.0) first = polyhedron.StartingFeature(direction);
  }
  PointClosest out = PointWalk(polyhedron, q, options).Run(first);
  out.point = X_WA.ToWorld(out.point);
  out.normal = X_WA.rotation * out.normal;
  return out;
}

}  // namespace sparsedyn
