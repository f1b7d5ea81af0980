// SPDX-License-Identifier: MIT
// ConvexPolyhedron::FromPoints: the convex hull by Qhull (reentrant C API), converted to a face
// list and validated by FromMesh. Degenerate point sets are refused before Qhull sees them
// (shape_checks.hpp): Qhull crashed on some (a SEGV in qh_normalize2, issue #39 part 1), and what
// it returns is checked as well before it is trusted.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include "geometry/shape_checks.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn {

namespace {

// Qhull's error text goes to a memory stream so that it can become an Error message.
class ErrorStream {
 public:
  ErrorStream() : file_(open_memstream(&buffer_, &size_)) {}
  ~ErrorStream() {
    if (file_ != nullptr) std::fclose(file_);
    std::free(buffer_);
  }
  ErrorStream(const ErrorStream&) = delete;
  ErrorStream& operator=(const ErrorStream&) = delete;

  FILE* file() const { return file_; }
  std::string Text() {
    if (file_ != nullptr) std::fflush(file_);
    std::string text = buffer_ != nullptr ? std::string(buffer_, size_) : std::string();
    // Qhull's messages run over many lines; the first one says what went wrong.
    if (const auto end = text.find('\n', 1); end != std::string::npos) text.resize(end);
    return text;
  }

 private:
  char* buffer_ = nullptr;
  std::size_t size_ = 0;
  FILE* file_ = nullptr;
};

// Frees Qhull's memory on every path out of FromPoints.
class QhullSession {
 public:
  explicit QhullSession(FILE* error_file) { qh_zero(&qh_, error_file); }
  ~QhullSession() {
    qh_freeqhull(&qh_, !qh_ALL);
    int current_long = 0, total_long = 0;
    qh_memfreeshort(&qh_, &current_long, &total_long);
  }
  QhullSession(const QhullSession&) = delete;
  QhullSession& operator=(const QhullSession&) = delete;
  qhT* get() { return &qh_; }

 private:
  qhT qh_{};
};

// A Qhull facet's vertices as a loop, counter-clockwise about its outward normal: sorted by angle
// about their mean in a basis (u, w) of the facet's plane with u x w = normal.
std::vector<std::int32_t> FacetLoop(qhT* qh, facetT* facet,
                                    std::span<const Eigen::Vector3d> points) {
  const Eigen::Vector3d normal(facet->normal[0], facet->normal[1], facet->normal[2]);
  std::vector<std::int32_t> ids;
  vertexT* vertex = nullptr;
  vertexT** vertexp = nullptr;
  FOREACHvertex_(facet->vertices) { ids.push_back(qh_pointid(qh, vertex->point)); }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const std::int32_t id : ids) mean += points[static_cast<std::size_t>(id)];
  mean /= static_cast<double>(ids.size());
  const Eigen::Vector3d u = normal.unitOrthogonal();
  const Eigen::Vector3d w = normal.cross(u);
  std::vector<std::pair<double, std::int32_t>> by_angle;
  for (const std::int32_t id : ids) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(id)] - mean;
    by_angle.emplace_back(std::atan2(d.dot(w), d.dot(u)), id);
  }
  std::sort(by_angle.begin(), by_angle.end());
  std::vector<std::int32_t> loop;
  for (const auto& [angle, id] : by_angle) loop.push_back(id);
  return loop;
}

// What FacetLoop and FromMesh rely on in Qhull's output, checked rather than trusted: a 3-d hull
// of at least 4 facets, each with a finite unit normal and at least 3 vertices that are input
// points (not Qhull's own interior or projected points).
Status CheckFacets(qhT* qh, std::size_t point_count) {
  const std::string what = "Qhull returned a broken hull: ";
  if (qh->hull_dim != 3 || qh->num_facets < 4) {
    return Error{what + std::to_string(qh->num_facets) + " facets in dimension " +
                 std::to_string(qh->hull_dim) + " (a polyhedron needs at least 4 in dimension 3)"};
  }
  int index = 0;
  facetT* facet = nullptr;
  FORALLfacets {
    const std::string name = "facet " + std::to_string(index++);
    if (facet->normal == nullptr || facet->vertices == nullptr) {
      return Error{what + name + " has no normal or no vertices"};
    }
    const Eigen::Vector3d normal(facet->normal[0], facet->normal[1], facet->normal[2]);
    const double length = normal.norm();
    if (!std::isfinite(length) || std::abs(length - 1.0) > 1e-6) {
      return Error{what + name + " has a normal of length " + std::to_string(length)};
    }
    const int vertex_count = qh_setsize(qh, facet->vertices);
    if (vertex_count < 3) {
      return Error{what + name + " has " + std::to_string(vertex_count) + " vertices"};
    }
    vertexT* vertex = nullptr;
    vertexT** vertexp = nullptr;
    FOREACHvertex_(facet->vertices) {
      const int id = qh_pointid(qh, vertex->point);
      if (id < 0 || static_cast<std::size_t>(id) >= point_count) {
        return Error{what + name + " has a vertex that is not an input point (id " +
                     std::to_string(id) + ")"};
      }
    }
  }
  return Status::Ok();
}

}  // namespace

Result<ConvexPolyhedron> ConvexPolyhedron::FromPoints(std::span<const Eigen::Vector3d> points,
                                                      MeshValidation options) {
  if (points.size() > static_cast<std::size_t>(INT32_MAX / 3)) {
    return Error{"too many points for a convex hull: " + std::to_string(points.size())};
  }
  if (Status input = CheckHullInput(points, options.tolerance); !input) return input.error();
  std::vector<coordT> coordinates;
  coordinates.reserve(3 * points.size());
  for (const Eigen::Vector3d& p : points) {
    coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  }

  // Qhull's defaults in 3-d include 'C-0': facets that are coplanar or concave within round-off
  // are merged, so its facets are already polygons; 'Pp' silences precision warnings, which
  // FromMesh's own tolerance checks replace.
  ErrorStream errors;
  QhullSession session(errors.file());
  qhT* qh = session.get();
  char flags[] = "qhull Pp";
  const int exit_code = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coordinates.data(),
                                     False, flags, nullptr, errors.file());
  if (exit_code != 0) {
    return Error{"Qhull could not build the convex hull of " + std::to_string(points.size()) +
                 " points (exit code " + std::to_string(exit_code) + "): " + errors.Text()};
  }
  if (Status facets = CheckFacets(qh, points.size()); !facets) return facets.error();

  // All points become mesh vertices so that messages name the caller's indices; FromMesh drops
  // those that no facet uses while keeping the order of the others.
  PolygonMesh mesh;
  mesh.vertices.assign(points.begin(), points.end());
  facetT* facet = nullptr;
  FORALLfacets { mesh.faces.push_back(FacetLoop(qh, facet, points)); }
  Result<ConvexPolyhedron> hull = FromMesh(mesh, options);
  if (!hull) return Error{"the convex hull of the points: " + hull.error().message};
  // Repairs of Qhull's output (merging its near-coplanar facets) are routine, not warnings.
  hull->warnings_.clear();
  return hull;
}

}  // namespace sparsedyn
