// SPDX-License-Identifier: MIT
#include "narrow/slab_bound.hpp"

#include <algorithm>
#include <cmath>

#include "narrow/advancement.hpp"

namespace sparsedyn::narrow {
namespace {

// The supports are exact but for near-ties (ConvexPolyhedron::SupportVertexFrom) and the bound
// sums a few products of O(scale) numbers: this much of the scale covers their round-off.
constexpr double kSupportSlack = 1e-12;
// Regula falsi refinements after the first chord (each costs two support climbs).
constexpr int kRefinements = 2;

}  // namespace

SlabBound::SlabBound(const TrackedPolyhedron& a, const RigidPath& path_a, double spin_radius_a,
                     const TrackedPolyhedron& b, const RigidPath& path_b, double spin_radius_b,
                     const Vec3& n, double t)
    : a_(a),
      b_(b),
      rotation_a_(path_a.OrientationAt(t).normalized()),
      rotation_b_(path_b.OrientationAt(t).normalized()),
      n_(n),
      u_a_(n.cross(path_a.omega)),
      u_b_(n.cross(path_b.omega)) {
  gap_ = n.dot(path_b.centre.PositionAt(t) - path_a.centre.PositionAt(t));
  closing_ = n.dot(path_b.centre.VelocityAt(t) - path_a.centre.VelocityAt(t));
  const double accel = n.dot(path_b.centre.a - path_a.centre.a);
  curvature_ = path_a.omega.norm() * u_a_.norm() * spin_radius_a +
               path_b.omega.norm() * u_b_.norm() * spin_radius_b - std::min(accel, 0.0);
  slack_ = kSupportSlack * std::max(a.polyhedron().scale(), b.polyhedron().scale());
}

double SlabBound::Support(const TrackedPolyhedron& body, const Eigen::Quaterniond& rotation,
                          const Vec3& direction_W, int& vertex) const {
  const Vec3 d_B = rotation.conjugate() * direction_W;
  vertex = vertex < 0 ? body.SupportVertex(d_B)
                      : body.polyhedron().SupportVertexFrom(d_B, vertex);
  return d_B.dot(body.polyhedron().vertex(vertex));
}

double SlabBound::operator()(double dt) {
  const double top_a = Support(a_, rotation_a_, n_ + dt * u_a_, top_a_);
  const double bottom_b = -Support(b_, rotation_b_, -n_ - dt * u_b_, bottom_b_);
  return gap_ + closing_ * dt + bottom_b - top_a - 0.5 * curvature_ * dt * dt - slack_;
}

std::optional<double> SlabBound::Step(double level, double horizon, double fallback) {
  const double start = (*this)(0.0) - level;
  if (!(start > 0.0)) return std::nullopt;
  // The tangent model at 0 (the current supports' rates) lies above the concave bound, so its
  // root is at or beyond the bound's: a trial point, checked by evaluation below.
  const Vec3 r_a = a_.polyhedron().vertex(top_a_);
  const Vec3 r_b = b_.polyhedron().vertex(bottom_b_);
  const double slope =
      closing_ - (rotation_a_ * r_a).dot(u_a_) + (rotation_b_ * r_b).dot(u_b_);
  std::optional<double> trial = AdvancementStep(start, -slope, curvature_, horizon);
  if (!trial) trial = std::min(horizon, 4.0 * fallback);
  double hi = *trial / (1.0 - kStepRoundingSlack);  // undo AdvancementStep's shortening
  hi = std::min(hi, horizon);
  if (!(hi > 0.0)) return std::nullopt;
  double value_hi = (*this)(hi) - level;
  if (value_hi >= 0.0) return hi;
  // Chords from a point known above the level to one below it stay below the concave bound.
  double lo = 0.0, value_lo = start;
  for (int i = 0; i <= kRefinements; ++i) {
    const double chord = lo + (hi - lo) * (value_lo / (value_lo - value_hi));
    const double x = lo + (chord - lo) * (1.0 - kStepRoundingSlack);
    if (!(x > lo) || !(x < hi)) break;
    const double value = (*this)(x) - level;
    if (value >= 0.0) {
      lo = x;
      value_lo = value;
    } else {  // round-off at the chord's end: keep the last point known above
      hi = x;
      value_hi = value;
    }
  }
  if (!(lo > 0.0)) return std::nullopt;
  return lo;
}

}  // namespace sparsedyn::narrow
