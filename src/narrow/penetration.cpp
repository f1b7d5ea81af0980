// SPDX-License-Identifier: MIT
#include "narrow/penetration.hpp"

#include <limits>
#include <vector>

#include "narrow/feature_distance.hpp"

namespace sparsedyn::narrow {
namespace {

// Index of the point with the smallest projection on `direction` (lowest index on ties).
std::size_t MinAlong(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& direction) {
  std::size_t best = 0;
  double best_value = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double value = direction.dot(points[i]);
    if (value < best_value) {
      best_value = value;
      best = i;
    }
  }
  return best;
}

// Gauss-map arcs a-b (A's edge: normals of its two faces) and c-d (B's edge, normals negated for
// the Minkowski difference A - B) cross: c and d on opposite sides of the plane of a, b; a and b
// on opposite sides of the plane of c, d; and on the same hemisphere.
bool IsMinkowskiFace(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     const Eigen::Vector3d& d) {
  const Eigen::Vector3d b_x_a = b.cross(a), d_x_c = d.cross(c);
  const double cba = c.dot(b_x_a), dba = d.dot(b_x_a), adc = a.dot(d_x_c), bdc = b.dot(d_x_c);
  return cba * dba < 0.0 && adc * bdc < 0.0 && cba * bdc > 0.0;
}

}  // namespace

SeparatingAxis DeepestSeparatingAxis(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                     const PairFrame& frame) {
  std::vector<Eigen::Vector3d> b_in_a, a_in_b;
  b_in_a.reserve(static_cast<std::size_t>(b.vertex_count()));
  for (const Eigen::Vector3d& p : b.vertices()) b_in_a.push_back(frame.ToA(p));
  a_in_b.reserve(static_cast<std::size_t>(a.vertex_count()));
  for (const Eigen::Vector3d& p : a.vertices()) a_in_b.push_back(frame.ToB(p));

  SeparatingAxis best;
  best.separation = -std::numeric_limits<double>::infinity();
  // Face normals of A: B's deepest vertex against the face plane.
  for (int f = 0; f < a.face_count(); ++f) {
    const Plane& plane = a.face(f).plane;
    const std::size_t v = MinAlong(b_in_a, plane.normal);
    const double separation = plane.SignedDistance(b_in_a[v]);
    if (separation > best.separation) {
      best = {separation, plane.normal,       b_in_a[v] - separation * plane.normal,
              b_in_a[v],  FeatureId::Face(f), FeatureId::Vertex(static_cast<std::int32_t>(v))};
    }
  }
  // Face normals of B (the normal from A to B is minus B's outward normal).
  for (int f = 0; f < b.face_count(); ++f) {
    const Plane& plane = b.face(f).plane;
    const std::size_t v = MinAlong(a_in_b, plane.normal);
    const double separation = plane.SignedDistance(a_in_b[v]);
    if (separation > best.separation) {
      const Eigen::Vector3d normal_a = frame.R_AB * plane.normal;
      const Eigen::Vector3d& p_a = a.vertex(static_cast<int>(v));
      best = {separation,
              -normal_a,
              p_a,
              p_a - separation * normal_a,
              FeatureId::Vertex(static_cast<std::int32_t>(v)),
              FeatureId::Face(f)};
    }
  }
  // Edge pairs that form a face of the Minkowski difference.
  std::vector<Eigen::Vector3d> b_normals;
  b_normals.reserve(static_cast<std::size_t>(b.face_count()));
  for (const Face& face : b.faces()) b_normals.push_back(frame.R_AB * face.plane.normal);
  for (int ea = 0; ea < a.edge_count(); ++ea) {
    const Edge& edge_a = a.edge(ea);
    const Eigen::Vector3d& na0 = a.face(edge_a.faces[0]).plane.normal;
    const Eigen::Vector3d& na1 = a.face(edge_a.faces[1]).plane.normal;
    const Eigen::Vector3d& a0 = a.vertex(edge_a.vertices[0]);
    const Eigen::Vector3d& a1 = a.vertex(edge_a.vertices[1]);
    for (int eb = 0; eb < b.edge_count(); ++eb) {
      const Edge& edge_b = b.edge(eb);
      const Eigen::Vector3d& nb0 = b_normals[static_cast<std::size_t>(edge_b.faces[0])];
      const Eigen::Vector3d& nb1 = b_normals[static_cast<std::size_t>(edge_b.faces[1])];
      if (!IsMinkowskiFace(na0, na1, -nb0, -nb1)) continue;
      const Eigen::Vector3d& b0 = b_in_a[static_cast<std::size_t>(edge_b.vertices[0])];
      const Eigen::Vector3d& b1 = b_in_a[static_cast<std::size_t>(edge_b.vertices[1])];
      Eigen::Vector3d axis = (a1 - a0).cross(b1 - b0);
      const double length = axis.norm();
      // Parallel edges: that direction is already a face normal of A or B.
      if (!(length > 1e-12 * (a1 - a0).norm() * (b1 - b0).norm())) continue;
      axis /= length;
      // Outward from A: A's edge faces both lie on the inner side.
      if (axis.dot(na0 + na1) < 0.0) axis = -axis;
      const double separation = axis.dot(b0 - a0);
      if (separation > best.separation) {
        const SegmentClosest c = ClosestSegmentSegment(a0, a1, b0, b1);
        best = {separation, axis, c.p, c.q, FeatureId::Edge(ea), FeatureId::Edge(eb)};
      }
    }
  }
  return best;
}

}  // namespace sparsedyn::narrow
