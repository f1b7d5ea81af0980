// SPDX-License-Identifier: MIT
// PredictWallContact (header narrow/time_of_contact.hpp): a polyhedron against a static plane.
#include <algorithm>
#include <cmath>

#include "math/roots.hpp"
#include "narrow/advancement.hpp"
#include "narrow/slab_bound.hpp"
#include "narrow/time_of_contact.hpp"
#include "narrow/tolerance_crossing.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

// The vertex nearest the plane (support in -normal) of the body at `pose`, and its gap.
struct Nearest {
  int vertex = -1;
  double gap = 0.0;
};
Nearest NearestVertex(const TrackedPolyhedron& body, const Pose& pose, const Vec3& normal,
                      double offset, int previous = -1) {
  const ConvexPolyhedron& poly = body.polyhedron();
  const Vec3 down_B = pose.rotation.conjugate() * (-normal);
  Nearest out;
  out.vertex = previous < 0 ? body.SupportVertex(down_B) : poly.SupportVertexFrom(down_B, previous);
  out.gap = normal.dot(pose.ToWorld(poly.vertex(out.vertex))) - offset;
  return out;
}

WallContactPrediction Finish(ContactPrediction::Kind kind, double t, Nearest nearest,
                             int iterations) {
  return {kind, t, nearest.vertex, nearest.gap, iterations};
}

}  // namespace

WallContactPrediction PredictWallContact(const TrackedPolyhedron& body, const RigidPath& path,
                                         const Vec3& normal, double offset, double t_begin,
                                         double t_end, double tolerance, int max_iterations,
                                         double spin_radius_given) {
  SPARSEDYN_ASSERT(std::isfinite(t_begin) && t_begin <= t_end,
                   "PredictWallContact needs t_begin finite and <= t_end");
  SPARSEDYN_ASSERT(tolerance > 0.0, "PredictWallContact needs a tolerance > 0");
  using Kind = ContactPrediction::Kind;
  const ConvexPolyhedron& polyhedron = body.polyhedron();
  Nearest nearest = NearestVertex(body, path.PoseAt(t_begin), normal, offset);
  if (nearest.gap <= tolerance) return Finish(Kind::kContact, t_begin, nearest, 0);

  // Not rotating: the nearest vertex stays the nearest, and its gap is a polynomial in time:
  // n . (c(t) + R v) - offset = gap0 + (n . v0) dt + (n . a) dt^2 / 2.
  if (!path.Rotates()) {
    const double horizon = std::min(t_end - t_begin, narrow::kMaxHorizon);
    const Polynomial gap{nearest.gap - tolerance, normal.dot(path.centre.VelocityAt(t_begin)),
                         0.5 * normal.dot(path.centre.a)};
    const std::optional<double> dt = EarliestRoot(gap, 0.0, horizon);
    const double t = dt ? std::min(t_begin + *dt, t_end) : t_end;
    if (!std::isfinite(t)) return Finish(Kind::kNone, t, nearest, 1);  // the gap at t_begin
    nearest = NearestVertex(body, path.PoseAt(t), normal, offset, nearest.vertex);
    if (!dt || nearest.gap <= tolerance)
      return Finish(dt ? Kind::kContact : Kind::kNone, t, nearest, 1);
    // The root left the gap a hair above the tolerance: step onto the first time it is within.
    auto gap_at = [&](double time) {
      return NearestVertex(body, path.PoseAt(time), normal, offset, nearest.vertex).gap;
    };
    const narrow::LevelCrossing crossing =
        narrow::StepIntoLevel(gap_at, t, nearest.gap, tolerance, t_end);
    const double at = crossing.time ? *crossing.time : crossing.apart;
    nearest = NearestVertex(body, path.PoseAt(at), normal, offset, nearest.vertex);
    if (crossing.time) return Finish(Kind::kContact, at, nearest, 1);
    return Finish(at < t_end ? Kind::kCheckpoint : Kind::kNone, at, nearest, 1);
  }

  // Rotating: conservative advancement. A body point moves towards the wall at most at
  // -(v . n) + |n x w| r, with r the SpinRadius (distance from the spin axis); the second-order
  // bound of the gap (SlabBound with the plane in A's place) usually goes much further. Both
  // are valid, so the longer step is taken.
  const double spin_radius =
      spin_radius_given >= 0.0 ? spin_radius_given : narrow::SpinRadius(polyhedron, path);
  const double spin = normal.cross(path.omega).norm() * spin_radius;
  double t = t_begin;
  for (int iteration = 0;; ++iteration) {
    if (nearest.gap <= tolerance) return Finish(Kind::kContact, t, nearest, iteration);
    if (t >= t_end) return Finish(Kind::kNone, t, nearest, iteration);
    if (iteration >= max_iterations) return Finish(Kind::kCheckpoint, t, nearest, iteration);
    const double target = kAdvancementTarget * tolerance;
    const double speed = -normal.dot(path.centre.VelocityAt(t));
    const double accel = -normal.dot(path.centre.a);
    const double horizon = std::min(t_end - t, narrow::kMaxHorizon);
    const std::optional<double> plain =
        narrow::AdvancementStep(nearest.gap - target, speed + spin, accel, horizon);
    if (plain) {
      narrow::SlabBound bound = narrow::SlabBound::Wall(body, path, spin_radius, normal, offset, t);
      const std::optional<double> second_order = bound.Step(target, horizon, *plain);
      t = std::min(t + std::max(*plain, second_order.value_or(0.0)), t_end);
    } else {
      t = t_end;
    }
    if (!std::isfinite(t)) return Finish(Kind::kNone, t, nearest, iteration + 1);
    nearest = NearestVertex(body, path.PoseAt(t), normal, offset, nearest.vertex);
  }
}

}  // namespace sparsedyn
