// SPDX-License-Identifier: MIT
// ContactFromFeatures: where two touching polyhedra touch, from their closest feature pair: a
// point, or the overlap of parallel features projected on the contact plane (docs/dynamics.md).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <span>

#include "dynamics/rigid_collision.hpp"

namespace sparsedyn {
namespace {

// Features count as parallel within this angle (radians): far above the round-off of rotated
// unit normals (~1e-15), yet a tilt of 1e-6 rad already makes a point contact.
constexpr double kParallelAngle = 1e-8;

// Relative round-off of projected coordinates (times the polyhedra's scale): the slack that
// lets features meeting along a line keep that line.
constexpr double kRoundOff = 1e-12;

using Vec2 = Eigen::Vector2d;

double Cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// One body's side of the contact: the polyhedron, its pose and the feature in question.
struct Side {
  const ConvexPolyhedron& poly;
  const Pose& X;
  FeatureId feature;

  Vec3 Vertex(int v) const { return X.ToWorld(poly.vertex(v)); }
  Vec3 FaceNormal(int f) const { return X.rotation * poly.face(f).plane.normal; }
  // Face f's outward normal within kParallelAngle of n (by the sine: a cosine cannot resolve it).
  bool FaceAlong(int f, const Vec3& n) const {
    const Vec3 normal = FaceNormal(f);
    return normal.dot(n) > 0.0 && normal.cross(n).norm() <= std::sin(kParallelAngle);
  }
  Vec3 EdgeDirection(int e) const {
    return (Vertex(poly.edge(e).vertices[1]) - Vertex(poly.edge(e).vertices[0])).normalized();
  }

  // Indices of a feature's vertices: 1, 2 (an edge) or a face loop.
  std::vector<std::int32_t> VertexIndices(FeatureId f) const {
    if (f.type == FeatureType::kVertex) return {f.index};
    if (f.type == FeatureType::kEdge) {
      return {poly.edge(f.index).vertices[0], poly.edge(f.index).vertices[1]};
    }
    const auto loop = poly.FaceVertices(f.index);
    return {loop.begin(), loop.end()};
  }

  // The feature's vertices in the world.
  std::vector<Vec3> Points(FeatureId f) const {
    std::vector<Vec3> out;
    for (const int v : VertexIndices(f)) out.push_back(Vertex(v));
    return out;
  }

  // The feature's vertices and their neighbours: by convexity the polyhedron lies in the cone
  // they span from the feature, so a plane with all of them on one side has it all there.
  std::vector<Vec3> Neighbourhood() const {
    std::vector<Vec3> out;
    for (const int v : VertexIndices(feature)) {
      out.push_back(Vertex(v));
      for (const int e : poly.VertexEdges(v)) out.push_back(Vertex(poly.OtherVertex(e, v)));
    }
    return out;
  }

  // The lowest-dimensional feature of this one that holds the witness point w (within
  // `tolerance`): a face touched at its corner is a vertex contact, whose separating normals are
  // bounded by the faces and edges around that corner, not by the face's.
  FeatureId Narrowest(const Vec3& w, double tolerance) const {
    if (feature.type == FeatureType::kVertex) return feature;
    for (const int v : VertexIndices(feature)) {
      if ((Vertex(v) - w).norm() <= tolerance) return FeatureId::Vertex(v);
    }
    if (feature.type == FeatureType::kEdge) return feature;
    for (const int e : poly.FaceEdges(feature.index)) {
      const Vec3 p0 = Vertex(poly.edge(e).vertices[0]), d = Vertex(poly.edge(e).vertices[1]) - p0;
      const double t = std::clamp(d.dot(w - p0) / d.squaredNorm(), 0.0, 1.0);
      if ((p0 + t * d - w).norm() <= tolerance) return FeatureId::Edge(e);
    }
    return feature;
  }

  // The faces that contain a vertex or an edge (none for a face: nothing is wider).
  std::span<const std::int32_t> Faces() const {
    if (feature.type == FeatureType::kVertex) return poly.VertexFaces(feature.index);
    if (feature.type == FeatureType::kEdge) return poly.edge(feature.index).faces;
    return {};
  }

  // Every vertex of f within `tolerance` of the support plane through `witness` (outward n).
  bool Flush(FeatureId f, const Vec3& n, const Vec3& witness, double tolerance) const {
    for (const Vec3& p : Points(f)) {
      if (std::abs(n.dot(p - witness)) > tolerance) return false;
    }
    return true;
  }

  // The walk returns one closest pair among equally close ones: a face or edge containing the
  // feature that is parallel to the contact plane (outward normal n) and flush with it touches
  // as well, and gives the larger contact.
  FeatureId Widened(const Vec3& n, const Vec3& witness, double tolerance) const {
    for (const int f : Faces()) {
      if (FaceAlong(f, n) && Flush(FeatureId::Face(f), n, witness, tolerance)) {
        return FeatureId::Face(f);
      }
    }
    if (feature.type != FeatureType::kVertex) return feature;
    for (const int e : poly.VertexEdges(feature.index)) {
      if (std::abs(EdgeDirection(e).dot(n)) <= std::sin(kParallelAngle) &&
          Flush(FeatureId::Edge(e), n, witness, tolerance)) {
        return FeatureId::Edge(e);
      }
    }
    return feature;
  }

  // Whether the feature lies in the contact plane (outward normal n), so it can give a region.
  bool Flat(const Vec3& n) const {
    if (feature.type == FeatureType::kFace) {
      return FaceAlong(feature.index, n);
    }
    if (feature.type == FeatureType::kEdge) {
      return std::abs(EdgeDirection(feature.index).dot(n)) <= std::sin(kParallelAngle);
    }
    return false;
  }
};

bool CrossingEdges(const Side& a, const Side& b) {
  if (a.feature.type != FeatureType::kEdge || b.feature.type != FeatureType::kEdge) return false;
  return a.EdgeDirection(a.feature.index).cross(b.EdgeDirection(b.feature.index)).norm() >
         std::sin(kParallelAngle);
}

// The contact normal (A towards B) must be a separating direction: the plane through A's
// witness has A's feature and its neighbouring vertices below it and the plane through B's has
// B's above (within `tolerance`). By convexity that separates the whole bodies.
class NormalChooser {
 public:
  NormalChooser(const Side& a, const Side& b, const Vec3& wa, const Vec3& wb, double tolerance)
      : near_a_(a.Neighbourhood()),
        near_b_(b.Neighbourhood()),
        wa_(wa),
        wb_(wb),
        tolerance_(tolerance) {}

  bool Separates(const Vec3& n) const {
    for (const Vec3& p : near_a_) {
      if (n.dot(p - wa_) > tolerance_) return false;
    }
    for (const Vec3& p : near_b_) {
      if (n.dot(p - wb_) < -tolerance_) return false;
    }
    return true;
  }

 private:
  std::vector<Vec3> near_a_, near_b_;
  Vec3 wa_, wb_;
  double tolerance_;
};

// Edges that contain a vertex, an edge itself, or a face's boundary.
std::vector<std::int32_t> Edges(const Side& side) {
  const FeatureId f = side.feature;
  if (f.type == FeatureType::kVertex) {
    const auto ring = side.poly.VertexEdges(f.index);
    return {ring.begin(), ring.end()};
  }
  if (f.type == FeatureType::kEdge) return {f.index};
  const auto loop = side.poly.FaceEdges(f.index);
  return {loop.begin(), loop.end()};
}

// The first separating normal of, best first: a face of the pair, the walk's normal, a face
// next to either feature, the cross product of two edges at the features (every extreme
// direction of the cone of separating normals is one of the last two). When the distance is ~0
// the walk may name a face that touches only at its boundary and its witness normal is noise,
// so every candidate is checked. None separates only for a deep penetration: the walk's normal.
Vec3 SeparatingNormal(const Side& a, const Side& b, const Vec3& wa, const Vec3& wb,
                      const Vec3& walk_normal, double tolerance) {
  const NormalChooser chooser(a, b, wa, wb, tolerance);
  std::vector<Vec3> candidates;
  if (a.feature.type == FeatureType::kFace) candidates.push_back(a.FaceNormal(a.feature.index));
  if (b.feature.type == FeatureType::kFace) candidates.push_back(-b.FaceNormal(b.feature.index));
  candidates.push_back(walk_normal);
  for (const int f : a.Faces()) candidates.push_back(a.FaceNormal(f));
  for (const int f : b.Faces()) candidates.push_back(-b.FaceNormal(f));
  for (const Vec3& n : candidates) {
    if (chooser.Separates(n)) return n;
  }
  for (const int ea : Edges(a)) {
    for (const int eb : Edges(b)) {
      const Vec3 cross = a.EdgeDirection(ea).cross(b.EdgeDirection(eb));
      if (cross.norm() <= std::sin(kParallelAngle)) continue;
      const Vec3 n = cross.normalized();
      if (chooser.Separates(n)) return n;
      if (chooser.Separates(-n)) return -n;
    }
  }
  return walk_normal;
}

// Sutherland & Hodgman 1974: clips `subject` (a polygon, or a segment as 2 points) by the
// convex polygon `clip` of either orientation, grown by `slack` so that features that only
// touch along a line (up to round-off) still give that line.
std::vector<Vec2> Clip(std::vector<Vec2> subject, const std::vector<Vec2>& clip, double slack) {
  double area = 0.0;
  for (std::size_t i = 0; i < clip.size(); ++i) {
    area += Cross2(clip[i], clip[(i + 1) % clip.size()]);
  }
  const double orientation = area >= 0.0 ? 1.0 : -1.0;
  const bool segment = subject.size() == 2;
  for (std::size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    const Vec2& c0 = clip[i];
    const Vec2 edge = (clip[(i + 1) % clip.size()] - c0).normalized();
    auto inside = [&](const Vec2& p) { return orientation * Cross2(edge, p - c0) + slack; };
    std::vector<Vec2> kept;
    // A segment is an open chain: its closing edge back to the start is not part of it.
    const std::size_t edges = segment ? 1 : subject.size();
    if (segment && inside(subject[0]) >= 0.0) kept.push_back(subject[0]);
    for (std::size_t k = 0; k < edges; ++k) {
      const Vec2& p = subject[k];
      const Vec2& q = subject[(k + 1) % subject.size()];
      const double sp = inside(p), sq = inside(q);
      if ((sp >= 0.0) != (sq >= 0.0)) kept.push_back(p + (sp / (sp - sq)) * (q - p));
      if (sq >= 0.0) kept.push_back(q);
    }
    subject = std::move(kept);
  }
  return subject;
}

// Drops points that coincide with their predecessor (within `eps`), cyclically.
std::vector<Vec2> Deduplicated(const std::vector<Vec2>& points, double eps) {
  std::vector<Vec2> out;
  for (const Vec2& p : points) {
    if (out.empty() || (p - out.back()).norm() > eps) out.push_back(p);
  }
  while (out.size() > 1 && (out.front() - out.back()).norm() <= eps) out.pop_back();
  return out;
}

// The overlap of two flat features projected on the plane with unit normal n (2D, basis u, v).
std::vector<Vec2> Overlap(const std::vector<Vec3>& pa, const std::vector<Vec3>& pb, const Vec3& u,
                          const Vec3& v, double slack) {
  auto project = [&](const std::vector<Vec3>& points) {
    std::vector<Vec2> out;
    for (const Vec3& p : points) out.emplace_back(u.dot(p), v.dot(p));
    return out;
  };
  const std::vector<Vec2> a = project(pa), b = project(pb);
  if (a.size() >= 3) return Clip(b, a, slack);
  if (b.size() >= 3) return Clip(a, b, slack);
  // Two parallel segments: A's segment cut to the range of B's along A's direction.
  const Vec2 d = a[1] - a[0];
  const double length2 = d.squaredNorm();
  if (!(length2 > 0.0)) return {};
  const double tb0 = d.dot(b[0] - a[0]) / length2, tb1 = d.dot(b[1] - a[0]) / length2;
  const double lo = std::max(0.0, std::min(tb0, tb1)), hi = std::min(1.0, std::max(tb0, tb1));
  if (lo > hi + slack / std::sqrt(length2)) return {};
  if (lo > hi) return {a[0] + 0.5 * (lo + hi) * d};
  return {a[0] + lo * d, a[0] + hi * d};
}

}  // namespace

ContactGeometry ContactFromFeatures(const ConvexPolyhedron& a, const Pose& X_WA,
                                    const ConvexPolyhedron& b, const Pose& X_WB,
                                    const ClosestFeatures& features, double tolerance) {
  Side side_a{a, X_WA, features.features.a};
  Side side_b{b, X_WB, features.features.b};
  const Vec3& wa = features.point_a;
  const Vec3& wb = features.point_b;
  ContactGeometry out;
  out.distance = features.distance;

  // The features that really hold the witness points: their neighbourhoods bound the normal.
  side_a.feature = side_a.Narrowest(wa, tolerance);
  side_b.feature = side_b.Narrowest(wb, tolerance);

  // A separating normal first; then each feature widens to a parallel, flush neighbour, and a
  // face found fixes the normal exactly (it is within kParallelAngle of it).
  Vec3 n = SeparatingNormal(side_a, side_b, wa, wb, features.normal, tolerance);
  side_a.feature = side_a.Widened(n, wa, tolerance);
  if (side_a.Flat(n) && side_a.feature.type == FeatureType::kFace) {
    n = side_a.FaceNormal(side_a.feature.index);
  }
  side_b.feature = side_b.Widened(-n, wb, tolerance);
  if (side_b.Flat(-n) && side_b.feature.type == FeatureType::kFace &&
      side_a.feature.type != FeatureType::kFace) {
    n = -side_b.FaceNormal(side_b.feature.index);
  }
  out.normal = n;

  // Point contacts (a vertex, crossing edges, a feature not parallel to the plane): the
  // midpoint of the witness points.
  const Vec3 midpoint = 0.5 * (wa + wb);
  if (!side_a.Flat(n) || !side_b.Flat(-n) || CrossingEdges(side_a, side_b)) {
    out.points = {midpoint};
    return out;
  }

  // A region: the overlap of both features projected on the plane, lifted to its mid-height.
  const Vec3 u = n.unitOrthogonal();
  const Vec3 v = n.cross(u);
  // Exact clipping first (points closer than the tolerance are one); features that meet only
  // along a line, where round-off may leave nothing, are clipped again with round-off slack:
  // the sliver that gives collapses to the line.
  const double round_off = kRoundOff * std::max(a.scale(), b.scale());
  const double eps = std::max(tolerance, round_off);
  const std::vector<Vec3> pa = side_a.Points(side_a.feature), pb = side_b.Points(side_b.feature);
  std::vector<Vec2> region = Deduplicated(Overlap(pa, pb, u, v, 0.0), eps);
  if (region.empty()) region = Deduplicated(Overlap(pa, pb, u, v, round_off), eps);
  if (region.empty()) {
    out.points = {midpoint};
    return out;
  }
  const double height = n.dot(midpoint);
  for (const Vec2& p : region) out.points.push_back(p.x() * u + p.y() * v + height * n);
  return out;
}

}  // namespace sparsedyn
