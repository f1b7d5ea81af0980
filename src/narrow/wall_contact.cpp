// SPDX-License-Identifier: MIT
// PredictWallContact (header narrow/time_of_contact.hpp): a polyhedron against a static plane.
#include <algorithm>

#include "math/roots.hpp"
#include "narrow/advancement.hpp"
#include "narrow/time_of_contact.hpp"

namespace sparsedyn {
namespace {

// A rotating body steps until the gap may have closed to this fraction of the tolerance (as
// ContactPredictionOptions::advancement_target for pairs).
constexpr double kWallAdvancementTarget = 0.5;

// The vertex nearest the plane (support in -normal) of the body at `pose`, and its gap.
struct Nearest {
  int vertex = -1;
  double gap = 0.0;
};
Nearest NearestVertex(const ConvexPolyhedron& poly, const Pose& pose, const Vec3& normal,
                      double offset) {
  Nearest out;
  out.vertex = poly.SupportVertex(pose.rotation.conjugate() * (-normal));
  out.gap = normal.dot(pose.ToWorld(poly.vertex(out.vertex))) - offset;
  return out;
}

WallContactPrediction Finish(ContactPrediction::Kind kind, double t, Nearest nearest,
                             int iterations) {
  return {kind, t, nearest.vertex, nearest.gap, iterations};
}

}  // namespace

WallContactPrediction PredictWallContact(const ConvexPolyhedron& polyhedron, const RigidPath& path,
                                         const Vec3& normal, double offset, double t_begin,
                                         double t_end, double tolerance, int max_iterations) {
  using Kind = ContactPrediction::Kind;
  Nearest nearest = NearestVertex(polyhedron, path.PoseAt(t_begin), normal, offset);
  if (nearest.gap <= tolerance) return Finish(Kind::kContact, t_begin, nearest, 0);

  // Not rotating: the nearest vertex stays the nearest, and its gap is a polynomial in time:
  // n . (c(t) + R v) - offset = gap0 + (n . v0) dt + (n . a) dt^2 / 2.
  if (!path.Rotates()) {
    const double horizon = t_end - t_begin;
    const Polynomial gap{nearest.gap - tolerance, normal.dot(path.centre.VelocityAt(t_begin)),
                         0.5 * normal.dot(path.centre.a)};
    const std::optional<double> dt = EarliestRoot(gap, 0.0, horizon);
    const double t = dt ? std::min(t_begin + *dt, t_end) : t_end;
    nearest = NearestVertex(polyhedron, path.PoseAt(t), normal, offset);
    return Finish(dt ? Kind::kContact : Kind::kNone, t, nearest, 1);
  }

  // Rotating: conservative advancement. A body point at distance <= r from the path's centre
  // moves towards the wall at most at -(v . n) + |n x w| r, since (w x r) . n = r . (n x w).
  const double radius = polyhedron.centroid().norm() + polyhedron.bounding_radius();
  const double spin = normal.cross(path.omega).norm() * radius;
  double t = t_begin;
  for (int iteration = 0;; ++iteration) {
    if (nearest.gap <= tolerance) return Finish(Kind::kContact, t, nearest, iteration);
    if (t >= t_end) return Finish(Kind::kNone, t, nearest, iteration);
    if (iteration >= max_iterations) return Finish(Kind::kCheckpoint, t, nearest, iteration);
    const std::optional<double> dt = narrow::AdvancementStep(
        nearest.gap - kWallAdvancementTarget * tolerance,
        spin - normal.dot(path.centre.VelocityAt(t)), -normal.dot(path.centre.a), t_end - t);
    t = dt ? std::min(t + *dt, t_end) : t_end;
    nearest = NearestVertex(polyhedron, path.PoseAt(t), normal, offset);
  }
}

}  // namespace sparsedyn
