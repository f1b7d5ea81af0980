// SPDX-License-Identifier: MIT
// ConvexPolyhedron: derived data (rings, planes, Voronoi regions, mass properties), accessors,
// queries and copies. Construction and validation live in polyhedron_builder.cpp.
#include "sparsedyn/geometry/convex_polyhedron.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {

namespace {

std::span<const std::int32_t> Slice(const std::vector<std::int32_t>& data, std::int32_t first,
                                    std::int32_t count) {
  return std::span<const std::int32_t>(data).subspan(static_cast<std::size_t>(first),
                                                     static_cast<std::size_t>(count));
}

// Closest point to p on the segment [a, b].
Eigen::Vector3d ClosestPointOnSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                      const Eigen::Vector3d& p) {
  const Eigen::Vector3d ab = b - a;
  const double length_squared = ab.squaredNorm();
  if (length_squared == 0.0) return a;
  const double s = std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0);
  return a + s * ab;
}

// Plane through `point` with unit normal `normal`.
Plane PlaneThrough(const Eigen::Vector3d& normal, const Eigen::Vector3d& point) {
  return Plane{normal, normal.dot(point)};
}

}  // namespace

std::string ToString(FeatureId feature) {
  switch (feature.type) {
    case FeatureType::kVertex:
      return "vertex " + std::to_string(feature.index);
    case FeatureType::kEdge:
      return "edge " + std::to_string(feature.index);
    case FeatureType::kFace:
      return "face " + std::to_string(feature.index);
    case FeatureType::kNone:
      break;
  }
  return "interior";
}

std::span<const std::int32_t> ConvexPolyhedron::FaceHalfEdges(int f) const {
  return Slice(face_half_edges_, face(f).first, face(f).count);
}
std::span<const std::int32_t> ConvexPolyhedron::FaceEdges(int f) const {
  return Slice(face_edges_, face(f).first, face(f).count);
}
std::span<const std::int32_t> ConvexPolyhedron::FaceVertices(int f) const {
  return Slice(face_vertices_, face(f).first, face(f).count);
}

std::span<const std::int32_t> ConvexPolyhedron::VertexHalfEdges(int v) const {
  const std::int32_t first = vertex_first_[Index(v)];
  return Slice(vertex_half_edges_, first, vertex_first_[Index(v) + 1] - first);
}
std::span<const std::int32_t> ConvexPolyhedron::VertexEdges(int v) const {
  const std::int32_t first = vertex_first_[Index(v)];
  return Slice(vertex_edges_, first, vertex_first_[Index(v) + 1] - first);
}
std::span<const std::int32_t> ConvexPolyhedron::VertexFaces(int v) const {
  const std::int32_t first = vertex_first_[Index(v)];
  return Slice(vertex_faces_, first, vertex_first_[Index(v) + 1] - first);
}

int ConvexPolyhedron::OtherVertex(int e, int v) const {
  const Edge& ed = edge(e);
  SPARSEDYN_ASSERT(ed.vertices[0] == v || ed.vertices[1] == v, "vertex is not an end of edge");
  return ed.vertices[0] == v ? ed.vertices[1] : ed.vertices[0];
}

std::span<const VoronoiPlane> ConvexPolyhedron::VoronoiPlanes(FeatureId feature) const {
  switch (feature.type) {
    case FeatureType::kVertex:
      return VertexPlanes(feature.index);
    case FeatureType::kEdge:
      return EdgePlanes(feature.index);
    case FeatureType::kFace:
      return FacePlanes(feature.index);
    case FeatureType::kNone:
      break;
  }
  SPARSEDYN_ASSERT(false, "VoronoiPlanes() of FeatureId::Interior()");
  return {};
}

void ConvexPolyhedron::ComputeDerivedData() {
  const auto vertex_count_u = vertices_.size();

  // Scale: bounding box diagonal, the length that relative tolerances multiply.
  Eigen::Vector3d lo = vertices_.front(), hi = vertices_.front();
  for (const Eigen::Vector3d& p : vertices_) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  scale_ = (hi - lo).norm();

  // Vertex rings: walk h -> twin(prev(h)), which turns counter-clockwise seen from outside
  // (face(h) lies between h and twin(prev(h))).
  std::vector<std::int32_t> any_outgoing(vertex_count_u, -1);
  for (std::size_t h = 0; h < half_edges_.size(); ++h) {
    any_outgoing[Index(half_edges_[h].origin)] = static_cast<std::int32_t>(h);
  }
  vertex_first_.assign(vertex_count_u + 1, 0);
  vertex_half_edges_.clear();
  vertex_edges_.clear();
  vertex_faces_.clear();
  for (std::size_t v = 0; v < vertex_count_u; ++v) {
    vertex_first_[v] = static_cast<std::int32_t>(vertex_half_edges_.size());
    const std::int32_t start = any_outgoing[v];
    SPARSEDYN_ASSERT(start >= 0, "vertex without edges");
    std::int32_t h = start;
    do {
      vertex_half_edges_.push_back(h);
      vertex_edges_.push_back(h >> 1);
      vertex_faces_.push_back(half_edges_[Index(h)].face);
      h = half_edges_[Index(h)].prev ^ 1;
      SPARSEDYN_ASSERT(vertex_half_edges_.size() <= half_edges_.size(), "vertex ring not closed");
    } while (h != start);
  }
  vertex_first_[vertex_count_u] = static_cast<std::int32_t>(vertex_half_edges_.size());

  // Face planes: Newell's normal is exact for planar polygons and a least-squares-like average
  // for faces that are planar only within tolerance; the offset averages over the vertices.
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto loop = FaceVertices(static_cast<int>(f));
    // Relative to the first vertex, so that a face far from the origin keeps its precision.
    const Eigen::Vector3d& o = vertices_[Index(loop[0])];
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      newell += (vertices_[Index(loop[i])] - o).cross(vertices_[Index(loop[i + 1])] - o);
    }
    const Eigen::Vector3d normal = newell.normalized();
    double offset = 0.0;
    for (const std::int32_t v : loop) offset += normal.dot(vertices_[Index(v)]);
    faces_[f].plane = Plane{normal, offset / static_cast<double>(loop.size())};
  }

  // Voronoi regions (Lin & Canny 1991; Mirtich 1998, V-Clip, section 3): every normal points
  // into the region it bounds.
  voronoi_planes_.clear();
  vertex_plane_first_.assign(vertex_count_u + 1, 0);
  for (std::size_t v = 0; v < vertex_count_u; ++v) {
    vertex_plane_first_[v] = static_cast<std::int32_t>(voronoi_planes_.size());
    const Eigen::Vector3d& p = vertices_[v];
    for (const std::int32_t e : VertexEdges(static_cast<int>(v))) {
      // Through v, normal along the edge pointing away from it: the vertex side.
      const Eigen::Vector3d& q = vertices_[Index(OtherVertex(e, static_cast<int>(v)))];
      voronoi_planes_.push_back({PlaneThrough((p - q).normalized(), p), FeatureId::Edge(e)});
    }
  }
  vertex_plane_first_[vertex_count_u] = static_cast<std::int32_t>(voronoi_planes_.size());

  edge_plane_first_ = static_cast<std::int32_t>(voronoi_planes_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const Edge& ed = edges_[e];
    const Eigen::Vector3d& a = vertices_[Index(ed.vertices[0])];
    const Eigen::Vector3d& b = vertices_[Index(ed.vertices[1])];
    const Eigen::Vector3d u = (b - a).normalized();
    voronoi_planes_.push_back({PlaneThrough(u, a), FeatureId::Vertex(ed.vertices[0])});
    voronoi_planes_.push_back({PlaneThrough(-u, b), FeatureId::Vertex(ed.vertices[1])});
    // faces[0] runs a -> b counter-clockwise, so its interior is on n0 x u; the edge side is
    // u x n0. faces[1] runs b -> a, so its interior is on n1 x (-u); the edge side is n1 x u.
    const Eigen::Vector3d& n0 = faces_[Index(ed.faces[0])].plane.normal;
    const Eigen::Vector3d& n1 = faces_[Index(ed.faces[1])].plane.normal;
    voronoi_planes_.push_back(
        {PlaneThrough(u.cross(n0).normalized(), a), FeatureId::Face(ed.faces[0])});
    voronoi_planes_.push_back(
        {PlaneThrough(n1.cross(u).normalized(), a), FeatureId::Face(ed.faces[1])});
  }

  face_plane_first_.assign(faces_.size() + 1, 0);
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    face_plane_first_[f] = static_cast<std::int32_t>(voronoi_planes_.size());
    const Plane& face_plane = faces_[f].plane;
    voronoi_planes_.push_back({face_plane, FeatureId::Interior()});
    const auto loop = FaceHalfEdges(static_cast<int>(f));
    for (const std::int32_t h : loop) {
      // Half-edge a -> b runs counter-clockwise about n, so the face lies on n x (b - a).
      const Eigen::Vector3d& a = vertices_[Index(half_edges_[Index(h)].origin)];
      const Eigen::Vector3d& b = vertices_[Index(half_edges_[Index(h ^ 1)].origin)];
      const Eigen::Vector3d inward = face_plane.normal.cross(b - a).normalized();
      voronoi_planes_.push_back({PlaneThrough(inward, a), FeatureId::Edge(h >> 1)});
    }
  }
  face_plane_first_[faces_.size()] = static_cast<std::int32_t>(voronoi_planes_.size());

  // Mass properties by the divergence theorem on a fan of tetrahedra (r, a, b, c) from a
  // reference point r inside the hull (the vertex mean, which keeps the terms small). For a
  // tetrahedron with edge vectors a, b, c from r and det = a . (b x c):
  //   volume = det / 6,   integral of x = volume * (a + b + c) / 4,
  //   integral of x x^T = det / 120 * (a a^T + b b^T + c c^T + s s^T), s = a + b + c
  // (the canonical tetrahedron's second moments 1/60 and 1/120 mapped by [a b c]; e.g. Tonon
  // 2004, "Explicit exact formulas for the 3-D tetrahedron inertia tensor").
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : vertices_) r += p;
  r /= static_cast<double>(vertex_count_u);
  double six_volume = 0.0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();   // times 24
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();  // times 120
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto loop = FaceVertices(static_cast<int>(f));
    const Eigen::Vector3d a = vertices_[Index(loop[0])] - r;
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      const Eigen::Vector3d b = vertices_[Index(loop[i])] - r;
      const Eigen::Vector3d c = vertices_[Index(loop[i + 1])] - r;
      const double det = a.dot(b.cross(c));
      const Eigen::Vector3d s = a + b + c;
      six_volume += det;
      first_moment += det * s;
      second_moment +=
          det * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
  }
  volume_ = six_volume / 6.0;
  const Eigen::Vector3d centroid_from_r = first_moment / (4.0 * six_volume);
  centroid_ = r + centroid_from_r;
  // Parallel-axis shift of the second moment from r to the centroid, then I = tr(S) 1 - S.
  const Eigen::Matrix3d about_centroid =
      second_moment / 120.0 - volume_ * centroid_from_r * centroid_from_r.transpose();
  inertia_ = about_centroid.trace() * Eigen::Matrix3d::Identity() - about_centroid;
  inertia_ = 0.5 * (inertia_ + inertia_.transpose()).eval();

  bounding_radius_ = 0.0;
  for (const Eigen::Vector3d& p : vertices_) {
    bounding_radius_ = std::max(bounding_radius_, (p - centroid_).norm());
  }
}

Eigen::Vector3d ConvexPolyhedron::ClosestPointOnFeature(FeatureId feature,
                                                        const Eigen::Vector3d& p) const {
  switch (feature.type) {
    case FeatureType::kVertex:
      return vertex(feature.index);
    case FeatureType::kEdge: {
      const Edge& ed = edge(feature.index);
      return ClosestPointOnSegment(vertex(ed.vertices[0]), vertex(ed.vertices[1]), p);
    }
    case FeatureType::kFace: {
      // Project onto the plane; if the projection is left of every (counter-clockwise) edge it
      // is inside the polygon, otherwise the closest point is on the boundary.
      const Plane& plane = face(feature.index).plane;
      const Eigen::Vector3d projected = p - plane.SignedDistance(p) * plane.normal;
      const auto loop = FaceVertices(feature.index);
      bool inside = true;
      for (std::size_t i = 0; i < loop.size() && inside; ++i) {
        const Eigen::Vector3d& a = vertex(loop[i]);
        const Eigen::Vector3d& b = vertex(loop[(i + 1) % loop.size()]);
        inside = (b - a).cross(projected - a).dot(plane.normal) >= 0.0;
      }
      if (inside) return projected;
      Eigen::Vector3d best = vertex(loop[0]);
      double best_distance = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Eigen::Vector3d q =
            ClosestPointOnSegment(vertex(loop[i]), vertex(loop[(i + 1) % loop.size()]), p);
        const double d = (q - p).squaredNorm();
        if (d < best_distance) {
          best_distance = d;
          best = q;
        }
      }
      return best;
    }
    case FeatureType::kNone:
      break;
  }
  SPARSEDYN_ASSERT(false, "ClosestPointOnFeature() of FeatureId::Interior()");
  return p;
}

int ConvexPolyhedron::SupportVertex(const Eigen::Vector3d& direction) const {
  int best = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  for (int v = 0; v < vertex_count(); ++v) {
    const double value = direction.dot(vertex(v));
    if (value > best_value) {
      best_value = value;
      best = v;
    }
  }
  return best;
}

int ConvexPolyhedron::SupportVertexFrom(const Eigen::Vector3d& direction, int start) const {
  int best = start;
  double best_value = direction.dot(vertex(start));
  for (bool climbed = true; climbed;) {
    climbed = false;
    for (const std::int32_t h : VertexHalfEdges(best)) {
      const int next = half_edge(h ^ 1).origin;
      const double value = direction.dot(vertex(next));
      if (value > best_value) {
        best_value = value;
        best = next;
        climbed = true;
        break;  // strictly higher each time: the climb cannot cycle
      }
    }
  }
  return best;
}

ConvexPolyhedron ConvexPolyhedron::Recentered() const {
  ConvexPolyhedron copy = *this;
  const Eigen::Vector3d shift = centroid_;
  for (Eigen::Vector3d& p : copy.vertices_) p -= shift;
  copy.ComputeDerivedData();
  return copy;
}

ConvexPolyhedron ConvexPolyhedron::Scaled(double factor) const {
  SPARSEDYN_ASSERT(factor > 0.0 && std::isfinite(factor), "Scaled() needs a finite factor > 0");
  ConvexPolyhedron copy = *this;
  for (Eigen::Vector3d& p : copy.vertices_) p *= factor;
  copy.ComputeDerivedData();
  return copy;
}

PolygonMesh ConvexPolyhedron::ToMesh() const {
  PolygonMesh mesh;
  mesh.vertices = vertices_;
  mesh.faces.reserve(faces_.size());
  for (int f = 0; f < face_count(); ++f) {
    const auto loop = FaceVertices(f);
    mesh.faces.emplace_back(loop.begin(), loop.end());
  }
  return mesh;
}

}  // namespace sparsedyn
