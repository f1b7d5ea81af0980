// SPDX-License-Identifier: MIT
// ContactFromFeatures: where two touching polyhedra touch, from their closest feature pair: a
// point, or the overlap of parallel features projected on the contact plane (docs/dynamics.md).
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

#include <Eigen/Geometry>

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

  // The feature's vertices in the world: 1, 2 (an edge) or a face loop.
  std::vector<Vec3> Points(FeatureId f) const {
    std::vector<Vec3> out;
    if (f.type == FeatureType::kVertex) out.push_back(Vertex(f.index));
    if (f.type == FeatureType::kEdge) {
      for (const int v : poly.edge(f.index).vertices) out.push_back(Vertex(v));
    }
    if (f.type == FeatureType::kFace) {
      for (const int v : poly.FaceVertices(f.index)) out.push_back(Vertex(v));
    }
    return out;
  }

  // The feature's vertices and their neighbours: by convexity the polyhedron lies in the cone
  // they span from the feature, so a plane with all of them on one side has it all there.
  std::vector<Vec3> Neighbourhood() const {
    std::vector<std::int32_t> vertices;
    if (feature.type == FeatureType::kVertex) vertices = {feature.index};
    if (feature.type == FeatureType::kEdge) {
      vertices.assign(poly.edge(feature.index).vertices.begin(),
                      poly.edge(feature.index).vertices.end());
    }
    if (feature.type == FeatureType::kFace) {
      const auto loop = poly.FaceVertices(feature.index);
      vertices.assign(loop.begin(), loop.end());
    }
    std::vector<Vec3> out;
    for (const int v : vertices) {
      out.push_back(Vertex(v));
      for (const int e : poly.VertexEdges(v)) out.push_back(Vertex(poly.OtherVertex(e, v)));
    }
    return out;
  }

  // The faces that contain the feature (itself for a face).
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
      if (FaceAlong(f, n) &&
          Flush(FeatureId::Face(f), n, witness, tolerance)) {
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

// The normal from A towards B: a face's normal, else the crossing edges' cross product (turned
// away from A's centroid), else the witness normal. Faces and edges keep it well defined when
// the distance is ~0 or negative, where the witness points do not.
Vec3 ContactNormal(const Side& a, const Side& b, const Vec3& witness_a, const Vec3& fallback) {
  if (a.feature.type == FeatureType::kFace) return a.FaceNormal(a.feature.index);
  if (b.feature.type == FeatureType::kFace) return -b.FaceNormal(b.feature.index);
  if (CrossingEdges(a, b)) {
    const Vec3 n =
        a.EdgeDirection(a.feature.index).cross(b.EdgeDirection(b.feature.index)).normalized();
    return n.dot(witness_a - a.X.ToWorld(a.poly.centroid())) >= 0.0 ? n : Vec3(-n);
  }
  return fallback;
}

// Without a face or crossing edges in the pair, the witness normal is noise when the distance
// is ~0: a face next to either feature whose plane has the other body on its far side (within
// `tolerance`) is a true separating plane, and its normal is used instead.
std::optional<Vec3> SeparatingFaceNormal(const Side& a, const Side& b, const Vec3& wa,
                                         const Vec3& wb, double tolerance) {
  auto separates = [&](const Side& other, const Vec3& n, const Vec3& origin) {
    for (const Vec3& p : other.Neighbourhood()) {
      if (n.dot(p - origin) < -tolerance) return false;
    }
    return true;
  };
  for (const int f : a.Faces()) {
    if (separates(b, a.FaceNormal(f), wa)) return a.FaceNormal(f);
  }
  for (const int f : b.Faces()) {
    if (separates(a, b.FaceNormal(f), wb)) return Vec3(-b.FaceNormal(f));
  }
  return std::nullopt;
}

// Sutherland & Hodgman 1974: clips `subject` (a polygon, or a segment as 2 points) by the
// convex polygon `clip` of either orientation, grown by `slack` so that features that only
// touch along a line (within the tolerance) still give that line.
std::vector<Vec2> Clip(std::vector<Vec2> subject, const std::vector<Vec2>& clip, double slack) {
  double area = 0.0;
  for (std::size_t i = 0; i < clip.size(); ++i) area += Cross2(clip[i], clip[(i + 1) % clip.size()]);
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

  // Widen each feature to a parallel, flush neighbour; a face found on A fixes the normal that
  // B is widened against, and the other way round.
  Vec3 n = ContactNormal(side_a, side_b, wa, features.normal);
  if (side_a.feature.type != FeatureType::kFace && side_b.feature.type != FeatureType::kFace &&
      !CrossingEdges(side_a, side_b)) {
    n = SeparatingFaceNormal(side_a, side_b, wa, wb, tolerance).value_or(n);
  }
  side_a.feature = side_a.Widened(n, wa, tolerance);
  n = ContactNormal(side_a, side_b, wa, n);
  side_b.feature = side_b.Widened(-n, wb, tolerance);
  n = ContactNormal(side_a, side_b, wa, n);
  side_a.feature = side_a.Widened(n, wa, tolerance);
  out.normal = ContactNormal(side_a, side_b, wa, n);
  n = out.normal;

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
