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
// The longest trial step, in multiples of the first-order step.
constexpr double kFarTrial = 1e4;

// A vertex of `feature` (-1 for none), to start a support climb from.
int VertexOf(const ConvexPolyhedron& poly, FeatureId feature) {
  switch (feature.type) {
    case FeatureType::kVertex: return feature.index;
    case FeatureType::kEdge: return poly.edge(feature.index).vertices[0];
    case FeatureType::kFace: return poly.FaceVertices(feature.index)[0];
    default: return -1;
  }
}

}  // namespace

SlabBound::SlabBound(const TrackedPolyhedron& b, const RigidPath& path_b, const Vec3& n, double t)
    : b_(b),
      rotation_a_(Eigen::Quaterniond::Identity()),
      rotation_b_(path_b.OrientationAt(t).normalized()),
      n_(n),
      u_a_(Vec3::Zero()),
      u_b_(n.cross(path_b.omega)) {}

void SlabBound::Finish(double spin_radius_b, const RigidPath& path_b, double closing_accel,
                       double curvature_a) {
  curvature_ = curvature_a + path_b.omega.norm() * u_b_.norm() * spin_radius_b -
               std::min(closing_accel, 0.0);
  double scale = b_.polyhedron().scale();
  if (a_ != nullptr) scale = std::max(scale, a_->polyhedron().scale());
  slack_ = kSupportSlack * scale;
  at_zero_ = (*this)(0.0);
  top_a_0_ = top_a_;
  bottom_b_0_ = bottom_b_;
}

SlabBound::SlabBound(const TrackedPolyhedron& a, const RigidPath& path_a, double spin_radius_a,
                     const TrackedPolyhedron& b, const RigidPath& path_b, double spin_radius_b,
                     const Vec3& n, double t, std::optional<FeaturePair> near)
    : SlabBound(b, path_b, n, t) {
  a_ = &a;
  if (near) {
    top_a_ = VertexOf(a.polyhedron(), near->a);
    bottom_b_ = VertexOf(b.polyhedron(), near->b);
  }
  rotation_a_ = path_a.OrientationAt(t).normalized();
  u_a_ = n.cross(path_a.omega);
  gap_ = n.dot(path_b.centre.PositionAt(t) - path_a.centre.PositionAt(t));
  closing_ = n.dot(path_b.centre.VelocityAt(t) - path_a.centre.VelocityAt(t));
  Finish(spin_radius_b, path_b, n.dot(path_b.centre.a - path_a.centre.a),
         path_a.omega.norm() * u_a_.norm() * spin_radius_a);
}

SlabBound SlabBound::Wall(const TrackedPolyhedron& b, const RigidPath& path_b,
                          double spin_radius_b, const Vec3& n, double offset, double t) {
  SlabBound bound(b, path_b, n, t);
  bound.gap_ = n.dot(path_b.centre.PositionAt(t)) - offset;
  bound.closing_ = n.dot(path_b.centre.VelocityAt(t));
  bound.Finish(spin_radius_b, path_b, n.dot(path_b.centre.a), 0.0);
  return bound;
}

double SlabBound::Support(const TrackedPolyhedron& body, const Eigen::Quaterniond& rotation,
                          const Vec3& direction_W, int& vertex) const {
  const Vec3 d_B = rotation.conjugate() * direction_W;
  vertex = vertex < 0 ? body.SupportVertex(d_B)
                      : body.polyhedron().SupportVertexFrom(d_B, vertex);
  return d_B.dot(body.polyhedron().vertex(vertex));
}

double SlabBound::operator()(double dt) {
  const double top_a = a_ == nullptr ? 0.0 : Support(*a_, rotation_a_, n_ + dt * u_a_, top_a_);
  const double bottom_b = -Support(b_, rotation_b_, -n_ - dt * u_b_, bottom_b_);
  return gap_ + closing_ * dt + bottom_b - top_a - 0.5 * curvature_ * dt * dt - slack_;
}

std::optional<double> SlabBound::Step(double level, double horizon, double fallback) {
  const double start = at_zero_ - level;
  if (!(start > 0.0)) return std::nullopt;
  // The tangent model at 0 (the current supports' rates) lies above the concave bound, so its
  // root is at or beyond the bound's: a trial point, checked by evaluation below.
  const Vec3 r_a = a_ == nullptr ? Vec3::Zero() : Vec3(a_->polyhedron().vertex(top_a_0_));
  const Vec3 r_b = b_.polyhedron().vertex(bottom_b_0_);
  const double slope =
      closing_ - (rotation_a_ * r_a).dot(u_a_) + (rotation_b_ * r_b).dot(u_b_);
  // Where the model never closes (or only beyond the horizon), try the horizon itself: a pair
  // passing by is then done in one step. kFarTrial x fallback caps the trial where the horizon
  // is open-ended, so that the chords below start from a sensible bracket.
  const std::optional<double> model = AdvancementStep(start, -slope, curvature_, kMaxHorizon);
  double hi = model ? *model / (1.0 - kStepRoundingSlack)  // undo AdvancementStep's shortening
                    : kInfinity;
  hi = std::min({hi, horizon, kFarTrial * std::max(fallback, 0.0)});
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
