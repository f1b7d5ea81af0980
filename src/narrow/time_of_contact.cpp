// SPDX-License-Identifier: MIT
#include "narrow/time_of_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "narrow/advancement.hpp"
#include "narrow/slab_bound.hpp"
#include "narrow/tolerance_crossing.hpp"
#include "narrow/zone_events.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

// How far (x the larger polyhedron's scale) a witness may stray over a zone plane before it
// counts as leaving the zone, and the round-off allowed on the distance at a predicted contact.
// Staying in a zone a little too long changes the distance only to second order (or towards
// the conservative side), far below the 1e-9 accuracy the tests ask for.
constexpr double kZoneSlack = 1e-10;
constexpr double kContactRoundOff = 1e-12;

// B's translation relative to A at time t, in A's frame (positions subtracted before rotating).
narrow::RelativeTranslation RelativeMotion(const RigidPath& path_a, const RigidPath& path_b,
                                           double t) {
  const Eigen::Matrix3d R_AW = path_a.q0.normalized().toRotationMatrix().transpose();
  narrow::RelativeTranslation m;
  m.R_AB = (path_a.q0.conjugate() * path_b.q0).normalized().toRotationMatrix();
  m.p = R_AW * (path_b.centre.PositionAt(t) - path_a.centre.PositionAt(t));
  m.v = R_AW * (path_b.centre.VelocityAt(t) - path_a.centre.VelocityAt(t));
  m.a = R_AW * (path_b.centre.a - path_a.centre.a);
  return m;
}

// One conservative-advancement step; every bound below is valid, so the longest step is too.
// (1) The distance changes at most at |v_B - v_A| + |w_A| r_A + |w_B| r_B, plus |a_B - a_A| per
// second. (2) The separating slab along the walk's normal n (A to B), measured on the support
// vertices so that it is valid even if the walk's normal is off by round-off: A's points move
// towards +n at most at v_A . n + |n x w_A| r_A (r_A its SpinRadius), B's towards -n likewise,
// and the accelerations add (a_A - a_B) . n per second. (3) The same slab bounded to second
// order (SlabBound), which near contact goes nearly all the way.
std::optional<double> PairAdvancement(const TrackedPolyhedron& a, const RigidPath& path_a,
                                      double r_a, const TrackedPolyhedron& b,
                                      const RigidPath& path_b, double r_b,
                                      const ClosestFeatures& cf, double t, double target,
                                      double horizon) {
  const Vec3& n = cf.normal;
  const Vec3 dv = path_a.centre.VelocityAt(t) - path_b.centre.VelocityAt(t);
  const Vec3 da = path_a.centre.a - path_b.centre.a;
  const std::optional<double> lipschitz = narrow::AdvancementStep(
      cf.distance - target, dv.norm() + path_a.omega.norm() * r_a + path_b.omega.norm() * r_b,
      da.norm(), horizon);
  if (!lipschitz) return lipschitz;
  narrow::SlabBound bound(a, path_a, r_a, b, path_b, r_b, n, t, cf.features);
  const double slab = bound.Separation() - target;
  if (slab <= 0.0) return lipschitz;
  const std::optional<double> plain = narrow::AdvancementStep(
      slab, dv.dot(n) + n.cross(path_a.omega).norm() * r_a + n.cross(path_b.omega).norm() * r_b,
      da.dot(n), horizon);
  if (!plain) return std::nullopt;
  const double first_order = std::max(*plain, *lipschitz);
  const std::optional<double> second_order = bound.Step(target, horizon, first_order);
  return second_order ? std::max(first_order, *second_order) : first_order;
}

// No contact ever (t_end = infinity and none within kMaxHorizon): kNone at t_end, with the
// features of the last time evaluated.
ContactPrediction NoneForever(ContactPrediction out, double t_end) {
  out.kind = ContactPrediction::Kind::kNone;
  out.time = t_end;
  return out;
}

// kContact at `t` with the walk's features there.
ContactPrediction ContactAt(const TrackedPolyhedron& a, const RigidPath& path_a,
                            const TrackedPolyhedron& b, const RigidPath& path_b, double t,
                            const ClosestFeaturesOptions& walk, ContactPrediction out) {
  out.kind = ContactPrediction::Kind::kContact;
  out.time = t;
  out.features =
      FindClosestFeatures(a, path_a.PoseAt(t), b, path_b.PoseAt(t), out.features.features, walk);
  return out;
}

}  // namespace

ContactPrediction PredictContact(const TrackedPolyhedron& a, const RigidPath& path_a,
                                 const TrackedPolyhedron& b, const RigidPath& path_b,
                                 double t_begin, double t_end, std::optional<FeaturePair> warm,
                                 const ContactPredictionOptions& options) {
  const ConvexPolyhedron& pa = a.polyhedron();
  const ConvexPolyhedron& pb = b.polyhedron();
  const double scale = std::max(pa.scale(), pb.scale());
  SPARSEDYN_ASSERT(std::isfinite(t_begin) && t_begin <= t_end,
                   "PredictContact needs t_begin finite and <= t_end");
  SPARSEDYN_ASSERT(options.tolerance > 0.0, "PredictContact needs a tolerance > 0");
  SPARSEDYN_ASSERT(options.advancement_target > 0.0 && options.advancement_target < 1.0,
                   "advancement_target must lie in (0, 1)");
  const double tol = options.tolerance;
  const bool translating = !path_a.Rotates() && !path_b.Rotates();
  // Rotating pairs step towards a gap below the tolerance so that they reach it in few steps.
  const double target = translating ? tol : options.advancement_target * tol;
  const double r_a = options.spin_radius_a >= 0.0 ? options.spin_radius_a
                                                 : narrow::SpinRadius(pa, path_a);
  const double r_b = options.spin_radius_b >= 0.0 ? options.spin_radius_b
                                                 : narrow::SpinRadius(pb, path_b);

  ContactPrediction out;
  double t = t_begin;
  bool contact_predicted = false;
  double retried_at = -std::numeric_limits<double>::infinity();
  double apart_at = t_begin;  // the last time the walk saw the pair beyond the tolerance
  std::optional<FeaturePair> start = warm;
  while (true) {
    out.time = t;
    out.features =
        FindClosestFeatures(a, path_a.PoseAt(t), b, path_b.PoseAt(t), start, options.walk);
    // A warm walk that hit its cap holds no answer: start over cold.
    if (out.features.status == ClosestFeatures::Status::kIterationCap) {
      out.features =
          FindClosestFeatures(a, path_a.PoseAt(t), b, path_b.PoseAt(t), std::nullopt, options.walk);
    }
    start = out.features.features;
    const FeaturePair seen = out.features.features;
    auto distance = [&](double time) {
      return FindClosestFeatures(a, path_a.PoseAt(time), b, path_b.PoseAt(time), seen, options.walk)
          .distance;
    };
    // A translating pair's distance is convex in time, so if a zone event jumped past the
    // contact (a pair that was not quite closest, e.g. among parallel features), the first
    // time within the tolerance is the one crossing between the last time seen apart and now.
    if (translating && out.features.distance < tol - kContactRoundOff * scale && t > apart_at) {
      const double first = narrow::BisectFirstWithin(distance, apart_at, t, tol);
      return ContactAt(a, path_a, b, path_b, first, options.walk, out);
    }
    if (out.features.distance <= tol) {
      out.kind = ContactPrediction::Kind::kContact;
      return out;
    }
    // The gap's root left the walk's distance a hair above the tolerance: step onto the first
    // time the walk agrees (or past a distance that only grazed the tolerance).
    if (contact_predicted && out.features.distance <= tol + kContactRoundOff * scale) {
      const narrow::LevelCrossing crossing =
          narrow::StepIntoLevel(distance, t, out.features.distance, tol, t_end);
      if (crossing.time) return ContactAt(a, path_a, b, path_b, *crossing.time, options.walk, out);
      if (crossing.apart > t) {
        t = crossing.apart;
        contact_predicted = false;
        continue;
      }
    }
    apart_at = t;
    if (t >= t_end) {
      out.kind = ContactPrediction::Kind::kNone;
      return out;
    }
    if (out.iterations >= options.max_iterations) {
      out.kind = ContactPrediction::Kind::kCheckpoint;
      return out;
    }
    ++out.iterations;
    contact_predicted = false;
    const double horizon = std::min(t_end - t, narrow::kMaxHorizon);

    // Translating: the next zone event of the current pair, exact up to round-off.
    if (translating) {
      const narrow::RelativeTranslation motion = RelativeMotion(path_a, path_b, t);
      const Pose X_WA = path_a.PoseAt(t);
      const narrow::ZoneEvent event = narrow::NextZoneEvent(
          pa, pb, motion, out.features.features, X_WA.ToBody(out.features.point_a),
          X_WA.ToBody(out.features.point_b), tol, horizon, kZoneSlack * scale);
      const double next_t =
          event.kind == narrow::ZoneEvent::Kind::kNone ? t_end : std::min(t + event.dt, t_end);
      // A witness on (or, by round-off, just over) a zone plane exits at once: the pair across
      // that plane is closest too, or better, so retry from it once at the same time (the walk
      // keeps a nearly-as-close pair within its round-off). A second stall at this time, or a
      // degenerate pair, is left to conservative advancement.
      const bool stalled =
          (event.kind == narrow::ZoneEvent::Kind::kExit && next_t <= t) || event.stalled;
      if (stalled && retried_at != t) {
        retried_at = t;
        start = event.next;
        continue;
      }
      if (event.kind != narrow::ZoneEvent::Kind::kUnsupported && !stalled) {
        contact_predicted = event.kind == narrow::ZoneEvent::Kind::kContact;
        if (event.kind == narrow::ZoneEvent::Kind::kExit) start = event.next;
        if (!std::isfinite(next_t)) return NoneForever(out, t_end);
        t = next_t;
        continue;
      }
      ++out.advancement_steps;
    }

    // Rotating (or a degenerate translating pair): conservative advancement.
    const std::optional<double> step =
        PairAdvancement(a, path_a, r_a, b, path_b, r_b, out.features, t, target, horizon);
    t = step ? std::min(t + *step, t_end) : t_end;
    if (!std::isfinite(t)) return NoneForever(out, t_end);
  }
}

}  // namespace sparsedyn
