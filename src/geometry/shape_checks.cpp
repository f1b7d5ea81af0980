// SPDX-License-Identifier: MIT
// The refusals of shape_checks.hpp. Each message names what is wrong and the limit it breaks, so
// that a refused scene or mesh says how to fix it.
#include "geometry/shape_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "geometry/point_box_tree.hpp"

namespace sparsedyn {

namespace {

std::string Num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

std::string Point(const Eigen::Vector3d& p) {
  return "(" + Num(p.x()) + ", " + Num(p.y()) + ", " + Num(p.z()) + ")";
}

std::string Name(std::string_view noun, std::size_t i) {
  return std::string(noun) + " " + std::to_string(i);
}

// Componentwise: Eigen's allFinite() computes x - x, which traps for an infinite x.
template <typename Matrix>
bool AllFinite(const Matrix& m) {
  return std::all_of(m.data(), m.data() + m.size(), [](double x) { return std::isfinite(x); });
}

// The index of the point farthest from `distance`'s zero (the first on ties), and its distance.
template <typename Distance>
std::pair<std::size_t, double> Farthest(std::span<const Eigen::Vector3d> points,
                                        Distance distance) {
  std::pair<std::size_t, double> best{0, -1.0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = distance(points[i]);
    if (d > best.second) best = {i, d};
  }
  return best;
}

}  // namespace

Status CheckCoordinates(std::span<const Eigen::Vector3d> points, std::string_view noun) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i];
    if (!AllFinite(p)) {
      return Error{Name(noun, i) + " has a non-finite coordinate " + Point(p)};
    }
    const double magnitude = p.cwiseAbs().maxCoeff();
    if (magnitude > kMaxCoordinate) {
      return Error{Name(noun, i) + " has a coordinate of magnitude " + Num(magnitude) +
                   ", above kMaxCoordinate = " + Num(kMaxCoordinate) + " " + Point(p)};
    }
  }
  return Status::Ok();
}

Status CheckExtent(std::span<const Eigen::Vector3d> points, std::string_view nouns) {
  Eigen::Vector3d lo = points.front(), hi = points.front();
  double magnitude = 0.0;
  for (const Eigen::Vector3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    magnitude = std::max(magnitude, p.cwiseAbs().maxCoeff());
  }
  const std::string the = "the " + std::string(nouns);
  if (lo == hi) {
    return Error{"all " + std::to_string(points.size()) + " " + std::string(nouns) +
                 " coincide at " + Point(lo)};
  }
  const double scale = (hi - lo).norm();
  if (scale < kMinScale) {
    return Error{the + " span only " + Num(scale) +
                 " (bounding-box diagonal), below kMinScale = " + Num(kMinScale)};
  }
  if (scale < kMinRelativeScale * magnitude) {
    return Error{the + " are distinct only at round-off: they span " + Num(scale) +
                 " at coordinates up to " + Num(magnitude) + " (relative " +
                 Num(scale / magnitude) + ", below kMinRelativeScale = " + Num(kMinRelativeScale) +
                 ")"};
  }
  return Status::Ok();
}

Status CheckHasVolume(std::span<const Eigen::Vector3d> points, double relative_tolerance) {
  Eigen::Vector3d lo = points.front(), hi = points.front();
  for (const Eigen::Vector3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double scale = (hi - lo).norm();
  const double thickness = std::max(relative_tolerance, kMinRelativeThickness) * scale;
  const std::string tolerance_text = "tolerance " + Num(thickness) + " = " +
                                     Num(std::max(relative_tolerance, kMinRelativeThickness)) +
                                     " x scale " + Num(scale);

  // Distances relative to point a, so that a set far from the origin keeps its precision.
  const Eigen::Vector3d& a = points.front();
  const auto [b, ab] = Farthest(points, [&](const Eigen::Vector3d& p) { return (p - a).norm(); });
  const Eigen::Vector3d u = (points[b] - a) / ab;
  const auto [c, off_line] =
      Farthest(points, [&](const Eigen::Vector3d& p) { return (p - a).cross(u).norm(); });
  if (off_line <= thickness) {
    return Error{"the points are collinear (no volume): all lie within " + Num(off_line) +
                 " of the line through points 0 and " + std::to_string(b) + " (" + tolerance_text +
                 ")"};
  }
  const Eigen::Vector3d n = u.cross(points[c] - a).normalized();
  const double off_plane =
      Farthest(points, [&](const Eigen::Vector3d& p) { return std::abs(n.dot(p - a)); }).second;
  if (off_plane <= thickness) {
    return Error{"the points are coplanar (no volume): all lie within " + Num(off_plane) +
                 " of the plane through points 0, " + std::to_string(b) + " and " +
                 std::to_string(c) + " (" + tolerance_text + ")"};
  }
  return Status::Ok();
}

Status CheckHullInput(std::span<const Eigen::Vector3d> points, double relative_tolerance) {
  if (points.size() < 4) {
    return Error{"a convex hull needs at least 4 points, got " + std::to_string(points.size())};
  }
  if (Status s = CheckCoordinates(points, "point"); !s) return s;
  if (Status s = CheckExtent(points, "points"); !s) return s;
  return CheckHasVolume(points, relative_tolerance);
}

Status CheckFinishedPolyhedron(const ConvexPolyhedron& polyhedron) {
  const ConvexPolyhedron& p = polyhedron;
  // Closed: half-edge h and its twin h ^ 1 run between the same vertices in opposite
  // directions, and next / prev link every face loop.
  for (int h = 0; h < p.half_edge_count(); ++h) {
    const HalfEdge& half = p.half_edge(h);
    if (p.half_edge(half.next).prev != h || p.half_edge(half.prev).next != h ||
        p.half_edge(h ^ 1).origin != p.half_edge(half.next).origin ||
        p.half_edge(h ^ 1).face == half.face) {
      return Error{"internal error: the finished polyhedron is not closed at half-edge " +
                   std::to_string(h)};
    }
  }
  if (p.vertex_count() - p.edge_count() + p.face_count() != 2) {
    return Error{"internal error: the finished polyhedron has V - E + F = " +
                 std::to_string(p.vertex_count() - p.edge_count() + p.face_count()) +
                 ", expected 2"};
  }
  // Convex: no vertex above a face plane (the final planes, as the narrow phase sees them).
  const double allowed = std::max(p.tolerance(), kMinRelativeThickness) * p.scale();
  for (int v = 0; v < p.vertex_count(); ++v) {
    if (!AllFinite(p.vertex(v))) {
      return Error{"internal error: the finished polyhedron's vertex " + std::to_string(v) +
                   " is " + Point(p.vertex(v))};
    }
  }
  // Only the boxes of vertices that reach above a plane are looked into (PointBoxTree).
  const PointBoxTree tree(p.vertices());
  for (int f = 0; f < p.face_count(); ++f) {
    std::optional<std::pair<int, double>> beyond;
    tree.ForEachAbove(
        p.face(f).plane.normal, p.face(f).plane.offset, [&] { return allowed; },
        [&](std::uint32_t v, double above) {
          const int vertex = static_cast<int>(v);
          if (!(above <= allowed) && (!beyond || vertex < beyond->first)) {
            beyond = std::make_pair(vertex, above);
          }
        });
    if (beyond) {
      return Error{"internal error: the finished polyhedron is not convex: vertex " +
                   std::to_string(beyond->first) + " lies " + Num(beyond->second) +
                   " above face " + std::to_string(f) + " (allowed " + Num(allowed) + ")"};
    }
  }
  if (!(p.volume() > 0.0 && std::isfinite(p.volume()) && AllFinite(p.centroid()) &&
        AllFinite(p.inertia()) && std::isfinite(p.bounding_radius()))) {
    return Error{"internal error: the finished polyhedron has volume " + Num(p.volume()) +
                 " and centroid " + Point(p.centroid()) +
                 "; a polyhedron needs a finite, positive volume and finite mass properties"};
  }
  return Status::Ok();
}

}  // namespace sparsedyn
