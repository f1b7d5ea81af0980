// SPDX-License-Identifier: MIT
// ApplyRigidImpulse (thesis §6): the collision impulse of two rigid bodies with rotation, Newton
// restitution and Coulomb friction at impact; a region gets a few impulses (docs/dynamics.md).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "dynamics/rigid_collision.hpp"
#include "math/cap_counters.hpp"

namespace sparsedyn {
namespace {

// A region needs at most this many impulses; each one stops the most approaching point.
constexpr int kMaxRounds = 16;
// After the first impulse a point counts as still approaching only faster than this fraction of
// the first approach speed: round-off left over by an impulse is not an approach.
constexpr double kRoundSpeedFraction = 1e-10;

Eigen::Matrix3d Cross(const Vec3& r) {
  Eigen::Matrix3d m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

// Velocity of B's material point at p relative to A's.
Vec3 RelativeVelocity(const RigidBodyState& a, const RigidBodyState& b, const Vec3& p) {
  return (b.velocity + b.angular_velocity.cross(p - b.centre)) -
         (a.velocity + a.angular_velocity.cross(p - a.centre));
}

// The collision matrix: an impulse J on B (-J on A) at p changes the relative velocity there
// by K J (Mirtich 1996, "Impulse-based dynamic simulation of rigid body systems", eq. 4.6).
Eigen::Matrix3d CollisionMatrix(const RigidBodyState& a, const RigidBodyState& b, const Vec3& p) {
  const Eigen::Matrix3d ra = Cross(p - a.centre);
  const Eigen::Matrix3d rb = Cross(p - b.centre);
  return (a.inv_mass + b.inv_mass) * Eigen::Matrix3d::Identity() - ra * a.inv_inertia * ra -
         rb * b.inv_inertia * rb;
}

void Apply(RigidBodyState& a, RigidBodyState& b, const Vec3& p, const Vec3& impulse) {
  a.velocity -= a.inv_mass * impulse;
  b.velocity += b.inv_mass * impulse;
  a.angular_velocity -= a.inv_inertia * (p - a.centre).cross(impulse);
  b.angular_velocity += b.inv_inertia * (p - b.centre).cross(impulse);
}

// The kinetic energy change of an impulse J at a point with pre-impact relative velocity u:
// dT = J.(u + u')/2 with u' = u + K J (K symmetric).
double EnergyChange(const Eigen::Matrix3d& k, const Vec3& u, const Vec3& j) {
  return j.dot(u) + 0.5 * j.dot(k * j);
}

struct PointImpulse {
  Vec3 impulse = Vec3::Zero();
  bool sliding = false;
};

// Coulomb friction at impact with Newton restitution u_n' = -e u_n (u_n < 0) at one point.
PointImpulse FrictionImpulse(const Eigen::Matrix3d& k, const Vec3& u, const Vec3& n, double e,
                             double mu) {
  const double un = u.dot(n);
  // Frictionless: J = j n with n.(u + K J) = -e u_n.
  const Vec3 frictionless = (-(1.0 + e) * un / n.dot(k * n)) * n;
  if (mu <= 0.0) return {frictionless, false};

  // Sticking: u' = -e u_n n, so J = K^-1 (u' - u); accepted inside the cone |j_t| <= mu j_n.
  PointImpulse out;
  const Vec3 stick = k.ldlt().solve(Vec3(-(1.0 + e) * un * n - (u - un * n)));
  const double jn = stick.dot(n);
  const Vec3 jt = stick - jn * n;
  if (jn >= 0.0 && jt.norm() <= mu * jn) {
    out.impulse = stick;
  } else {
    // Sliding: J = j_n (n - mu t) opposes the initial sliding direction t; the normal
    // condition fixes j_n. Without tangential velocity, t opposes the sticking impulse.
    const Vec3 ut = u - un * n;
    Vec3 t = ut.norm() > 0.0 ? Vec3(ut.normalized()) : Vec3(-jt.normalized());
    const Vec3 d = n - mu * t;
    const double denominator = n.dot(k * d);
    // A non-positive denominator is Painleve's paradox (friction would pull the bodies
    // together): no finite sliding impulse exists; fall back to frictionless.
    if (!(denominator > 0.0)) return {frictionless, false};
    out.impulse = (-(1.0 + e) * un / denominator) * d;
    out.sliding = true;
  }

  // Newton restitution with friction can gain energy (Stronge 2000, "Impact mechanics" §5):
  // then blend towards the frictionless impulse, J(s) = F + s (J - F), which keeps u_n' and
  // stays in the cone, taking the largest s in [0, 1] with dT(s) <= 0 (dT(0) <= 0 for e <= 1).
  if (EnergyChange(k, u, out.impulse) > 0.0) {
    const Vec3 delta = out.impulse - frictionless;
    const double qa = 0.5 * delta.dot(k * delta);
    const double qb = delta.dot(u) + frictionless.dot(k * delta);
    const double qc = std::min(EnergyChange(k, u, frictionless), 0.0);
    // qa s^2 + qb s + qc = 0 with qa > 0, qc <= 0: the positive root, stable form.
    const double root = std::sqrt(std::max(qb * qb - 4.0 * qa * qc, 0.0));
    const double s = qb >= 0.0 ? (-2.0 * qc) / (qb + root) : (root - qb) / (2.0 * qa);
    // qa = 0 only when friction changed nothing, so the gain was round-off.
    out.impulse = qa > 0.0 ? Vec3(frictionless + std::clamp(s, 0.0, 1.0) * delta) : frictionless;
  }
  return out;
}

Vec3 RegionCentroid(const std::vector<Vec3>& points, const Vec3& n) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  if (points.size() < 3) return mean;
  // Area centroid of the polygon: fan of triangles from the mean, signed areas along n.
  Vec3 sum = Vec3::Zero();
  double area = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    const Vec3& q = points[(i + 1) % points.size()];
    const double w = (p - mean).cross(q - mean).dot(n);
    sum += w * (mean + p + q) / 3.0;
    area += w;
  }
  return std::abs(area) > 0.0 ? Vec3(sum / area) : mean;
}

// The region point that approaches fastest, with its normal relative velocity.
std::pair<Vec3, double> MostApproaching(const RigidBodyState& a, const RigidBodyState& b,
                                        const std::vector<Vec3>& points, const Vec3& n) {
  std::pair<Vec3, double> best{points.front(), kInfinity};
  for (const Vec3& p : points) {
    const double un = RelativeVelocity(a, b, p).dot(n);
    if (un < best.second) best = {p, un};
  }
  return best;
}

}  // namespace

RigidImpulseResult ApplyRigidImpulse(RigidBodyState& a, RigidBodyState& b,
                                     const ContactGeometry& contact,
                                     const RigidImpulseOptions& options) {
  RigidImpulseResult result;
  // Two static bodies cannot exchange an impulse (K = 0).
  if (contact.points.empty() || a.inv_mass + b.inv_mass <= 0.0) return result;
  const Vec3& n = contact.normal;
  double point_weight = 0.0;
  Vec3 weighted_point = Vec3::Zero();
  double threshold = 0.0;

  // First the centroid (a flush, non-rotating contact then only translates), then the most
  // approaching point while one still approaches: one impulse cannot stop a rotating region.
  Vec3 p = RegionCentroid(contact.points, n);
  double un = RelativeVelocity(a, b, p).dot(n);
  if (!(un < 0.0)) std::tie(p, un) = MostApproaching(a, b, contact.points, n);
  while (un < -threshold && result.rounds < kMaxRounds) {
    // The guard applies to every round: the slow rounds after the first are what would
    // otherwise collapse; `guarded` then reports that any round was made elastic.
    double e = options.restitution;
    if (-un < options.elastic_below_speed && e < 1.0) {
      e = 1.0;
      result.guarded = true;
    }
    const Eigen::Matrix3d k = CollisionMatrix(a, b, p);
    const PointImpulse j = FrictionImpulse(k, RelativeVelocity(a, b, p), n, e, options.friction);
    Apply(a, b, p, j.impulse);
    if (result.rounds == 0) threshold = kRoundSpeedFraction * -un;
    ++result.rounds;
    result.sliding = result.sliding || j.sliding;
    result.impulse += j.impulse;
    const double jn = j.impulse.dot(n);
    result.normal_impulse += jn;
    weighted_point += jn * p;
    point_weight += jn;
    if (contact.points.size() == 1) break;
    std::tie(p, un) = MostApproaching(a, b, contact.points, n);
  }
  // Still approaching after the last round: the next event meets the pair again at once.
  if (un < -threshold && result.rounds >= kMaxRounds) caps::Count(caps::impulse_rounds);
  if (point_weight > 0.0) result.point = weighted_point / point_weight;
  return result;
}

}  // namespace sparsedyn
