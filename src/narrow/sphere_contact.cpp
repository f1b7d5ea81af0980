// SPDX-License-Identifier: MIT
// PredictSphereContact (header narrow/sphere_contact.hpp): the driver of time_of_contact.cpp
// with one side a sphere. Zone events for a polyhedron that does not rotate, conservative
// advancement (the same three bounds) for one that does.
#include "narrow/sphere_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "math/roots.hpp"
#include "narrow/advancement.hpp"
#include "narrow/poly_vec3.hpp"
#include "narrow/slab_bound.hpp"
#include "narrow/tolerance_crossing.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

// As in time_of_contact.cpp: how far (x the pair's scale) the centre may stray over a zone
// plane before it counts as leaving the zone, and the round-off allowed on the gap at a
// predicted contact.
constexpr double kZoneSlack = 1e-10;
constexpr double kContactRoundOff = 1e-12;

// The centre relative to the (non-rotating) polyhedron in its frame, dt after t:
// q(dt) = p + v dt + a dt^2 / 2, positions subtracted before they are rotated.
narrow::PolyVec3 RelativeCentre(const RigidPath& path, const Path& centre, double t) {
  const Eigen::Matrix3d R_AW = path.q0.normalized().toRotationMatrix().transpose();
  return narrow::PolyVec3::Motion(R_AW * (centre.PositionAt(t) - path.centre.PositionAt(t)),
                                  R_AW * (centre.VelocityAt(t) - path.centre.VelocityAt(t)),
                                  R_AW * (centre.a - path.centre.a));
}

// What the centre's current feature predicts (zone_events.hpp's ZoneEvent, for a point).
struct PointZoneEvent {
  enum class Kind : std::uint8_t { kContact, kExit, kNone, kStalled };
  Kind kind = Kind::kNone;
  double dt = 0.0;
  FeatureId next;       // kExit, kStalled: the feature across the plane left
  bool within = false;  // kContact: the gap polynomial is already negative at dt = 0, so
                        // dt is where the gap leaves the tolerance band again
};

// The gap polynomial of the centre q(dt) against feature f while f stays closest: <= 0
// exactly when the distance is <= reach (= radius + tolerance). A face: the height over its
// plane less reach (degree 2); an edge: the squared distance from its line, a vertex: from
// the vertex, less reach^2 (degree 4).
Polynomial GapPolynomial(const ConvexPolyhedron& poly, FeatureId f, const narrow::PolyVec3& q,
                         double reach) {
  if (f.type == FeatureType::kFace) {
    const Plane& plane = poly.face(f.index).plane;
    return narrow::Dot(plane.normal, q) - Polynomial{plane.offset + reach};
  }
  narrow::PolyVec3 offset;
  if (f.type == FeatureType::kVertex) {
    offset = q - narrow::PolyVec3::Constant(poly.vertex(f.index));
  } else {
    // Off the line e0 + s u: w - u (u . w) / |u|^2 with w = q - e0.
    const Edge& e = poly.edge(f.index);
    const Vec3& e0 = poly.vertex(e.vertices[0]);
    const Vec3 u = poly.vertex(e.vertices[1]) - e0;
    const narrow::PolyVec3 w = q - narrow::PolyVec3::Constant(e0);
    offset = w - narrow::PolyVec3::Along(u, narrow::Dot(u, w) * (1.0 / u.squaredNorm()));
  }
  return narrow::SquaredNorm(offset) - Polynomial{reach * reach};
}

// True when p (degree <= 2) certainly stays positive on [0, limit]: its constant term beats
// every term that could pull it down, with a margin for this test's own rounding. Saves the
// certified root isolation for the zone planes the centre is nowhere near.
bool CertainlyPositive(const Polynomial& p, double limit) {
  const double c0 = p.Coefficient(0), c1 = p.Coefficient(1) * limit;
  const double c2 = p.Coefficient(2) * limit * limit;
  const double low = c0 + std::min(c1, 0.0) + std::min(c2, 0.0);
  return p.Degree() <= 2 && low > 1e-12 * (std::abs(c0) + std::abs(c1) + std::abs(c2));
}

// The earliest exit of q(dt) from f's zone within [0, horizon] (each zone plane's signed
// distance is a quadratic in dt; a face's own plane is left out: crossing it is contact, which
// the gap finds first), then the earliest root of the gap before it.
PointZoneEvent NextPointZoneEvent(const ConvexPolyhedron& poly, FeatureId f,
                                  const narrow::PolyVec3& q, double reach, double horizon,
                                  double slack) {
  PointZoneEvent event;
  double exit = horizon;
  for (const VoronoiPlane& vp : poly.VoronoiPlanes(f)) {
    if (vp.neighbor.type == FeatureType::kNone) continue;
    const Polynomial g = narrow::Dot(vp.plane.normal, q) - Polynomial{vp.plane.offset - slack};
    if (g(0.0) < 0.0) {  // already over the plane by more than the slack
      event.kind = PointZoneEvent::Kind::kStalled;
      event.next = vp.neighbor;
      return event;
    }
    if (CertainlyPositive(g, exit)) continue;
    const std::optional<double> root = EarliestRoot(g, 0.0, exit);
    if (root && *root < exit) {
      exit = *root;
      event.next = vp.neighbor;
    }
  }
  const Polynomial gap = GapPolynomial(poly, f, q, reach);
  if (const std::optional<double> contact = EarliestRoot(gap, 0.0, exit)) {
    event.kind = PointZoneEvent::Kind::kContact;
    event.dt = *contact;
    event.within = gap(0.0) < 0.0;
  } else if (exit < horizon) {
    event.kind = PointZoneEvent::Kind::kExit;
    event.dt = exit;
  } else {
    event.dt = horizon;
  }
  return event;
}

// One conservative-advancement step for a rotating polyhedron (PairAdvancement's three bounds
// with a sphere in B's place, whose spin does not matter). (1) The gap changes at most at
// |v_s - v_A| + |w| r_A, plus |a_s - a_A| per second (r_A the SpinRadius). (2) The slab along
// the walk's normal n (polyhedron to centre): the centre's height over the polyhedron's
// support plane less the radius; the support rises along n at most at v_A . n + |n x w| r_A.
// (3) The same slab to second order: SlabBound::Wall with the polyhedron seen from the
// centre (a translation of both, so the bound is exact motion) against the plane -n . x = r
// through the sphere's lowest point along n.
std::optional<double> SphereAdvancement(const TrackedPolyhedron& body, const RigidPath& path,
                                        double spin_radius, const Path& centre, double radius,
                                        const PointClosest& closest, double t, double target,
                                        double horizon) {
  const Vec3 dv = centre.VelocityAt(t) - path.centre.VelocityAt(t);
  const Vec3 da = centre.a - path.centre.a;
  const std::optional<double> lipschitz =
      narrow::AdvancementStep(closest.distance - radius - target,
                              dv.norm() + path.omega.norm() * spin_radius, da.norm(), horizon);
  if (!lipschitz) return lipschitz;
  const Vec3& n = closest.normal;
  RigidPath relative = path.RebasedAt(t);
  relative.centre.p0 -= centre.PositionAt(t);
  relative.centre.v0 -= centre.VelocityAt(t);
  relative.centre.a -= centre.a;
  narrow::SlabBound bound = narrow::SlabBound::Wall(body, relative, spin_radius, -n, radius, t);
  const double slab = bound.Separation() - target;
  if (slab <= 0.0) return lipschitz;
  const std::optional<double> plain = narrow::AdvancementStep(
      slab, -n.dot(dv) + n.cross(path.omega).norm() * spin_radius, -n.dot(da), horizon);
  if (!plain) return std::nullopt;
  const double first_order = std::max(*plain, *lipschitz);
  const std::optional<double> second_order = bound.Step(target, horizon, first_order);
  return second_order ? std::max(first_order, *second_order) : first_order;
}

// The closest feature and gap at time t, warm-started from `start`.
struct Seen {
  PointClosest closest;
  double gap = 0.0;
};

}  // namespace

SphereContactPrediction PredictSphereContact(const TrackedPolyhedron& polyhedron,
                                             const RigidPath& path, const Path& centre,
                                             double radius, double t_begin, double t_end,
                                             std::optional<FeatureId> warm,
                                             const ContactPredictionOptions& options) {
  using Kind = ContactPrediction::Kind;
  const ConvexPolyhedron& poly = polyhedron.polyhedron();
  SPARSEDYN_ASSERT(std::isfinite(t_begin) && t_begin <= t_end,
                   "PredictSphereContact needs t_begin finite and <= t_end");
  SPARSEDYN_ASSERT(options.tolerance > 0.0, "PredictSphereContact needs a tolerance > 0");
  SPARSEDYN_ASSERT(radius >= 0.0, "PredictSphereContact needs a radius >= 0");
  SPARSEDYN_ASSERT(options.advancement_target > 0.0 && options.advancement_target < 1.0,
                   "advancement_target must lie in (0, 1)");
  const double tol = options.tolerance;
  const double scale = std::max(poly.scale(), radius);
  const bool translating = !path.Rotates();
  const double target = translating ? tol : options.advancement_target * tol;
  const double spin_radius =
      options.spin_radius_a >= 0.0 ? options.spin_radius_a : narrow::SpinRadius(poly, path);
  auto look = [&](double time, std::optional<FeatureId> start) {
    Seen seen{FindClosestFeatureToPoint(polyhedron, path.PoseAt(time), centre.PositionAt(time),
                                        start, options.walk)};
    seen.gap = seen.closest.distance - radius;
    return seen;
  };
  auto finish = [&](Kind kind, double time, const Seen& seen, SphereContactPrediction out) {
    out.kind = kind;
    out.time = time;
    out.closest = seen.closest;
    out.gap = seen.gap;
    return out;
  };

  SphereContactPrediction out;
  double t = t_begin;
  bool contact_predicted = false;
  double retried_at = -std::numeric_limits<double>::infinity();
  double apart_at = t_begin;  // the last time the gap was seen above the tolerance
  std::optional<FeatureId> start = warm;
  while (true) {
    const Seen now = look(t, start);
    start = now.closest.feature;
    const FeatureId seen_feature = now.closest.feature;
    auto gap = [&](double time) { return look(time, seen_feature).gap; };
    // A zone event that jumped past the contact (the centre's distance is convex in time on a
    // straight line): the first time within the tolerance lies between the last time seen
    // apart and now, and is bisected to adjacent doubles.
    if (translating && now.gap < tol - kContactRoundOff * scale && t > apart_at) {
      const double first = narrow::BisectFirstWithin(gap, apart_at, t, tol);
      return finish(Kind::kContact, first, look(first, seen_feature), out);
    }
    if (now.gap <= tol) return finish(Kind::kContact, t, now, out);
    // A root that left the gap a hair above the tolerance: step onto the first time the walk
    // agrees (or past a gap that only grazed the tolerance).
    if (contact_predicted && now.gap <= tol + kContactRoundOff * scale) {
      const narrow::LevelCrossing crossing = narrow::StepIntoLevel(gap, t, now.gap, tol, t_end);
      if (crossing.time) {
        return finish(Kind::kContact, *crossing.time, look(*crossing.time, seen_feature), out);
      }
      if (crossing.apart > t) {
        t = crossing.apart;
        contact_predicted = false;
        continue;
      }
    }
    apart_at = t;
    if (t >= t_end) return finish(Kind::kNone, t, now, out);
    if (out.iterations >= options.max_iterations) return finish(Kind::kCheckpoint, t, now, out);
    ++out.iterations;
    contact_predicted = false;
    const double horizon = std::min(t_end - t, narrow::kMaxHorizon);

    // Not rotating: the next zone event of the centre's feature, exact up to round-off. A
    // centre already over a zone plane (the walk keeps a feature within its round-off) retries
    // once from the feature across it; a second stall takes one advancement step.
    if (translating) {
      const PointZoneEvent event =
          NextPointZoneEvent(poly, now.closest.feature, RelativeCentre(path, centre, t),
                             radius + tol, horizon, kZoneSlack * scale);
      const bool stalled = event.kind == PointZoneEvent::Kind::kStalled ||
                           (event.kind == PointZoneEvent::Kind::kExit && t + event.dt <= t);
      if (stalled && retried_at != t) {
        retried_at = t;
        start = event.next;
        continue;
      }
      // The polynomial has the gap within the tolerance already while the walk, a hair
      // above it (round-off), stepped past its first root: the gap dips and comes back at dt.
      // Where the dip is deepest, about halfway, the walk must agree if the dip is more than
      // round-off: the first time within is then bisected from t. Otherwise the pass only
      // grazed the tolerance and goes on past the dip.
      if (event.kind == PointZoneEvent::Kind::kContact && event.within && event.dt > 0.0) {
        const double middle = t + 0.5 * std::min(event.dt, horizon);
        const Seen deepest = look(middle, seen_feature);
        if (deepest.gap <= tol) {
          const double first = narrow::BisectFirstWithin(gap, t, middle, tol);
          return finish(Kind::kContact, first, look(first, seen_feature), out);
        }
        t = std::min(t + event.dt, t_end);
        start = deepest.closest.feature;
        continue;
      }
      if (!stalled) {
        const double next_t =
            event.kind == PointZoneEvent::Kind::kNone ? t_end : std::min(t + event.dt, t_end);
        contact_predicted = event.kind == PointZoneEvent::Kind::kContact;
        if (event.kind == PointZoneEvent::Kind::kExit) start = event.next;
        if (!std::isfinite(next_t)) return finish(Kind::kNone, t_end, now, out);
        t = next_t;
        continue;
      }
      ++out.advancement_steps;
    }

    // Rotating (or a stalled zone test): conservative advancement.
    const std::optional<double> step = SphereAdvancement(polyhedron, path, spin_radius, centre,
                                                         radius, now.closest, t, target, horizon);
    t = step ? std::min(t + *step, t_end) : t_end;
    if (!std::isfinite(t)) return finish(Kind::kNone, t_end, now, out);
  }
}

}  // namespace sparsedyn
