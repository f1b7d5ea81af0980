// SPDX-License-Identifier: MIT
// Oracles shared by the geometry tests: topology consistency, Voronoi regions against brute
// force over all features, a brute-force convex hull, and paste-able descriptions.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn::testing {

// Relative tolerance of the oracles: far above double round-off on shapes of size ~1 (1e-16),
// far below any geometric feature of the test shapes (>= 1e-4 relative).
inline constexpr double kCheckTolerance = 1e-9;

inline double Uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

inline Eigen::Vector3d RandomUnitVector(std::mt19937_64& rng) {
  while (true) {
    const Eigen::Vector3d p(2 * Uniform01(rng) - 1, 2 * Uniform01(rng) - 1, 2 * Uniform01(rng) - 1);
    if (p.squaredNorm() > 1e-4 && p.squaredNorm() <= 1.0) return p.normalized();
  }
}

// The polyhedron as a PolygonMesh literal with 17 significant digits, for SCOPED_TRACE.
inline std::string Describe(const PolygonMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  out << "PolygonMesh{.vertices = {";
  for (const Eigen::Vector3d& p : mesh.vertices) {
    out << "{" << p.x() << ", " << p.y() << ", " << p.z() << "}, ";
  }
  out << "}, .faces = {";
  for (const auto& face : mesh.faces) {
    out << "{";
    for (const auto v : face) out << v << ",";
    out << "}, ";
  }
  out << "}}";
  return out.str();
}
inline std::string Describe(const ConvexPolyhedron& poly) { return Describe(poly.ToMesh()); }

// Every adjacency relation agrees with every other one, the counts satisfy Euler's formula, and
// the geometry is planar and convex within kCheckTolerance.
inline ::testing::AssertionResult IsConsistent(const ConvexPolyhedron& p) {
  const auto fail = [](const std::string& what) { return ::testing::AssertionFailure() << what; };
  const int v_count = p.vertex_count(), e_count = p.edge_count(), f_count = p.face_count();
  if (v_count - e_count + f_count != 2) return fail("Euler characteristic != 2");
  if (p.half_edge_count() != 2 * e_count) return fail("half-edge count != 2 E");
  for (int h = 0; h < p.half_edge_count(); ++h) {
    const HalfEdge& he = p.half_edge(h);
    const HalfEdge& twin = p.half_edge(h ^ 1);
    if (p.half_edge(he.next).prev != h || p.half_edge(he.prev).next != h)
      return fail("next/prev mismatch at half-edge " + std::to_string(h));
    if (p.half_edge(he.next).face != he.face) return fail("next leaves the face");
    if (twin.face == he.face) return fail("twin in the same face");
    if (p.half_edge(he.next).origin != twin.origin)
      return fail("half-edge " + std::to_string(h) + " does not end at its twin's origin");
    const Edge& e = p.edge(h >> 1);
    if (e.vertices[h & 1] != he.origin || e.faces[h & 1] != he.face)
      return fail("edge record disagrees with half-edge " + std::to_string(h));
  }
  int loop_total = 0;
  for (int f = 0; f < f_count; ++f) {
    const auto hs = p.FaceHalfEdges(f);
    const auto es = p.FaceEdges(f);
    const auto vs = p.FaceVertices(f);
    if (hs.size() < 3) return fail("face with < 3 edges");
    loop_total += static_cast<int>(hs.size());
    const Plane& plane = p.face(f).plane;
    if (std::abs(plane.normal.norm() - 1) > 1e-12) return fail("face normal not unit");
    for (std::size_t i = 0; i < hs.size(); ++i) {
      if (p.half_edge(hs[i]).face != f) return fail("face loop half-edge in another face");
      if (p.half_edge(hs[i]).next != hs[(i + 1) % hs.size()]) return fail("face loop order");
      if (es[i] != hs[i] >> 1 || vs[i] != p.half_edge(hs[i]).origin) return fail("face spans");
      if (std::abs(plane.SignedDistance(p.vertex(vs[i]))) > kCheckTolerance * p.scale())
        return fail("face " + std::to_string(f) + " not planar");
    }
    // Counter-clockwise seen from outside: Newell normal agrees with the plane normal.
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < vs.size(); ++i) {
      newell += p.vertex(vs[i]).cross(p.vertex(vs[(i + 1) % vs.size()]));
    }
    if (newell.dot(plane.normal) <= 0) return fail("face " + std::to_string(f) + " clockwise");
    for (int v = 0; v < v_count; ++v) {
      if (plane.SignedDistance(p.vertex(v)) > kCheckTolerance * p.scale())
        return fail("vertex " + std::to_string(v) + " above face " + std::to_string(f));
    }
  }
  if (loop_total != p.half_edge_count()) return fail("face loops do not cover the half-edges");
  int ring_total = 0;
  for (int v = 0; v < v_count; ++v) {
    const auto hs = p.VertexHalfEdges(v);
    const auto es = p.VertexEdges(v);
    const auto fs = p.VertexFaces(v);
    if (hs.size() < 3) return fail("vertex " + std::to_string(v) + " with < 3 edges");
    ring_total += static_cast<int>(hs.size());
    for (std::size_t i = 0; i < hs.size(); ++i) {
      if (p.half_edge(hs[i]).origin != v) return fail("ring half-edge not leaving its vertex");
      if (p.half_edge(p.half_edge(hs[i]).prev).origin == v) return fail("prev starts at vertex");
      if ((p.half_edge(hs[i]).prev ^ 1) != hs[(i + 1) % hs.size()]) return fail("ring order");
      if (es[i] != hs[i] >> 1 || fs[i] != p.half_edge(hs[i]).face) return fail("ring spans");
      if (p.OtherVertex(es[i], v) != p.half_edge(hs[i] ^ 1).origin) return fail("OtherVertex");
    }
    // Counter-clockwise seen from outside: edge directions a = h_i and b = h_{i+1} bound the
    // face of h_i, whose loop turns left at v, so a x b points along that face's normal.
    for (std::size_t i = 0; i < hs.size(); ++i) {
      const Eigen::Vector3d a = p.vertex(p.half_edge(hs[i] ^ 1).origin) - p.vertex(v);
      const Eigen::Vector3d b =
          p.vertex(p.half_edge(hs[(i + 1) % hs.size()] ^ 1).origin) - p.vertex(v);
      if (a.cross(b).dot(p.face(fs[i]).plane.normal) <= 0) {
        return fail("vertex ring not ccw at " + std::to_string(v));
      }
    }
  }
  if (ring_total != p.half_edge_count()) return fail("vertex rings do not cover half-edges");
  if (!(p.volume() > 0)) return fail("volume not positive");
  return ::testing::AssertionSuccess();
}

// Every Voronoi plane's neighbour has the same plane with the opposite normal, pointing back.
inline ::testing::AssertionResult VoronoiPlanesAreReciprocal(const ConvexPolyhedron& p) {
  const double tol = kCheckTolerance * p.scale();
  std::vector<FeatureId> features;
  for (int v = 0; v < p.vertex_count(); ++v) features.push_back(FeatureId::Vertex(v));
  for (int e = 0; e < p.edge_count(); ++e) features.push_back(FeatureId::Edge(e));
  for (int f = 0; f < p.face_count(); ++f) features.push_back(FeatureId::Face(f));
  for (const FeatureId feature : features) {
    for (const VoronoiPlane& vp : p.VoronoiPlanes(feature)) {
      if (std::abs(vp.plane.normal.norm() - 1) > 1e-12) {
        return ::testing::AssertionFailure() << ToString(feature) << ": normal not unit";
      }
      if (vp.neighbor == FeatureId::Interior()) continue;
      bool found = false;
      for (const VoronoiPlane& back : p.VoronoiPlanes(vp.neighbor)) {
        found = found ||
                (back.neighbor == feature && (back.plane.normal + vp.plane.normal).norm() < 1e-12 &&
                 std::abs(back.plane.offset + vp.plane.offset) < tol);
      }
      if (!found) {
        return ::testing::AssertionFailure()
               << ToString(feature) << " -> " << ToString(vp.neighbor) << " not reciprocal";
      }
    }
  }
  return ::testing::AssertionSuccess();
}

// Random exterior points: the feature holding the closest surface point satisfies its region's
// planes, and every feature whose region holds the point is at the closest distance.
inline ::testing::AssertionResult VoronoiRegionsAgreeWithBruteForce(const ConvexPolyhedron& p,
                                                                    std::uint64_t seed,
                                                                    int samples) {
  std::mt19937_64 rng(seed);
  const double tol = kCheckTolerance * p.scale();
  std::vector<FeatureId> features;
  for (int v = 0; v < p.vertex_count(); ++v) features.push_back(FeatureId::Vertex(v));
  for (int e = 0; e < p.edge_count(); ++e) features.push_back(FeatureId::Edge(e));
  for (int f = 0; f < p.face_count(); ++f) features.push_back(FeatureId::Face(f));
  const auto min_plane = [&](FeatureId feature, const Eigen::Vector3d& q) {
    double m = std::numeric_limits<double>::infinity();
    for (const VoronoiPlane& vp : p.VoronoiPlanes(feature)) {
      m = std::min(m, vp.plane.SignedDistance(q));
    }
    return m;
  };
  for (int s = 0; s < samples; ++s) {
    // Half the samples near a random feature (where regions meet), half anywhere around.
    const FeatureId near = features[static_cast<std::size_t>(rng() % features.size())];
    Eigen::Vector3d q;
    if (s % 2 == 0) {
      const Eigen::Vector3d anchor = p.ClosestPointOnFeature(near, p.centroid());
      const double reach = p.bounding_radius() * std::pow(10.0, -3.0 * Uniform01(rng));
      q = anchor + reach * RandomUnitVector(rng);
    } else {
      q = p.centroid() + p.bounding_radius() * (1 + 2 * Uniform01(rng)) * RandomUnitVector(rng);
    }
    double outside = -std::numeric_limits<double>::infinity();
    for (int f = 0; f < p.face_count(); ++f) {
      outside = std::max(outside, p.face(f).plane.SignedDistance(q));
    }
    if (outside <= 10 * tol) continue;  // the regions partition the exterior only

    // Brute force: closest surface point over all faces, then the lowest-dimensional feature
    // that holds it.
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector3d closest;
    for (int f = 0; f < p.face_count(); ++f) {
      const Eigen::Vector3d c = p.ClosestPointOnFeature(FeatureId::Face(f), q);
      if ((c - q).norm() < best) {
        best = (c - q).norm();
        closest = c;
      }
    }
    FeatureId holder = FeatureId::Interior();
    for (const FeatureId feature : features) {
      if ((p.ClosestPointOnFeature(feature, closest) - closest).norm() <= tol) {
        holder = feature;
        break;  // features are listed vertices first, then edges, then faces
      }
    }
    std::ostringstream where;
    where.precision(17);
    where << "point (" << q.x() << ", " << q.y() << ", " << q.z() << ") sample " << s;
    if (holder == FeatureId::Interior()) {
      return ::testing::AssertionFailure() << where.str() << ": no feature holds the closest point";
    }
    if (min_plane(holder, q) < -2 * tol) {
      return ::testing::AssertionFailure()
             << where.str() << ": closest feature " << ToString(holder)
             << " violates its region by " << -min_plane(holder, q);
    }
    for (const FeatureId feature : features) {
      if (min_plane(feature, q) < 0) continue;
      const double d = (p.ClosestPointOnFeature(feature, q) - q).norm();
      if (d > best + tol) {
        return ::testing::AssertionFailure()
               << where.str() << ": inside the region of " << ToString(feature) << " at distance "
               << d << " but the closest distance is " << best;
      }
    }
  }
  return ::testing::AssertionSuccess();
}

// Brute-force convex hull as a face list (all points kept as vertices): every plane through
// three points with all points on one side, its points ordered counter-clockwise. O(n^4).
inline PolygonMesh ReferenceHull(const std::vector<Eigen::Vector3d>& points) {
  PolygonMesh mesh{points, {}};
  const std::size_t n = points.size();
  double size = 0;
  for (const auto& q : points) size = std::max(size, q.norm());
  const double tol = 1e-9 * size;
  std::set<std::vector<std::int32_t>> seen;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = j + 1; k < n; ++k) {
        Eigen::Vector3d normal = (points[j] - points[i]).cross(points[k] - points[i]);
        if (normal.norm() <= tol * size) continue;
        normal.normalize();
        int above = 0, below = 0;
        for (const auto& q : points) {
          const double d = normal.dot(q - points[i]);
          above += d > tol;
          below += d < -tol;
        }
        if (above > 0 && below > 0) continue;
        if (above > 0) normal = -normal;
        std::vector<std::int32_t> on;
        for (std::size_t m = 0; m < n; ++m) {
          if (std::abs(normal.dot(points[m] - points[i])) <= tol) {
            on.push_back(static_cast<std::int32_t>(m));
          }
        }
        if (!seen.insert(on).second) continue;
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (const auto m : on) mean += points[static_cast<std::size_t>(m)];
        mean /= static_cast<double>(on.size());
        const Eigen::Vector3d u = (points[static_cast<std::size_t>(on[0])] - mean).normalized();
        const Eigen::Vector3d w = normal.cross(u);
        std::sort(on.begin(), on.end(), [&](std::int32_t a, std::int32_t b) {
          const Eigen::Vector3d da = points[static_cast<std::size_t>(a)] - mean;
          const Eigen::Vector3d db = points[static_cast<std::size_t>(b)] - mean;
          return std::atan2(da.dot(w), da.dot(u)) < std::atan2(db.dot(w), db.dot(u));
        });
        mesh.faces.push_back(on);
      }
    }
  }
  return mesh;
}

}  // namespace sparsedyn::testing
