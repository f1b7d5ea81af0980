// SPDX-License-Identifier: MIT
#include "narrow/time_of_contact.hpp"

#include <algorithm>
#include <cmath>

#include "narrow/advancement.hpp"
#include "narrow/zone_events.hpp"

namespace sparsedyn {
namespace {

// How far (x the larger polyhedron's scale) a witness may stray over a zone plane before it
// counts as leaving the zone, and the round-off allowed on the distance at a predicted contact.
// Staying in a zone a little too long changes the distance only to second order (or towards
// the conservative side), far below the 1e-9 accuracy the tests ask for.
constexpr double kZoneSlack = 1e-10;
constexpr double kContactRoundOff = 1e-12;

// Largest distance of a body point from its frame origin (the point the path moves and the
// rotation turns about): the centroid's offset plus the bounding radius about the centroid.
double RadiusAboutOrigin(const ConvexPolyhedron& poly) {
  return poly.centroid().norm() + poly.bounding_radius();
}

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

// One conservative-advancement step from the separating plane through the closest points
// (normal n from A to B, gap d): A's points move towards +n at most at v_A . n + |n x w_A| r_A
// (since (w x r) . n = r . (n x w)), B's towards -n likewise, and the accelerations add
// (a_A - a_B) . n per second. No contact can occur before the bound has closed d - target.
std::optional<double> PairAdvancement(const ClosestFeatures& cf, const RigidPath& path_a,
                                      double r_a, const RigidPath& path_b, double r_b, double t,
                                      double target, double horizon) {
  const Vec3& n = cf.normal;
  const double speed = (path_a.centre.VelocityAt(t) - path_b.centre.VelocityAt(t)).dot(n) +
                       n.cross(path_a.omega).norm() * r_a + n.cross(path_b.omega).norm() * r_b;
  const double accel = (path_a.centre.a - path_b.centre.a).dot(n);
  return narrow::AdvancementStep(cf.distance - target, speed, accel, horizon);
}

}  // namespace

ContactPrediction PredictContact(const TrackedPolyhedron& a, const RigidPath& path_a,
                                 const TrackedPolyhedron& b, const RigidPath& path_b,
                                 double t_begin, double t_end, std::optional<FeaturePair> warm,
                                 const ContactPredictionOptions& options) {
  const ConvexPolyhedron& pa = a.polyhedron();
  const ConvexPolyhedron& pb = b.polyhedron();
  const double scale = std::max(pa.scale(), pb.scale());
  const double tol = options.tolerance;
  const bool translating = !path_a.Rotates() && !path_b.Rotates();
  // Rotating pairs step towards a gap below the tolerance so that they reach it in few steps.
  const double target = translating ? tol : options.advancement_target * tol;
  const double r_a = RadiusAboutOrigin(pa), r_b = RadiusAboutOrigin(pb);

  ContactPrediction out;
  double t = t_begin;
  bool contact_predicted = false;
  std::optional<FeaturePair> start = warm;
  while (true) {
    out.time = t;
    out.features = FindClosestFeatures(a, path_a.PoseAt(t), b, path_b.PoseAt(t), start,
                                       options.walk);
    start = out.features.features;
    const double accepted = contact_predicted ? tol + kContactRoundOff * scale : tol;
    if (out.features.distance <= accepted) {
      out.kind = ContactPrediction::Kind::kContact;
      return out;
    }
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
    const double horizon = t_end - t;

    // Translating: the next zone event of the current pair, exact up to round-off.
    if (translating) {
      const narrow::RelativeTranslation motion = RelativeMotion(path_a, path_b, t);
      const Pose X_WA = path_a.PoseAt(t);
      const narrow::ZoneEvent event = narrow::NextZoneEvent(
          pa, pb, motion, out.features.features, X_WA.ToBody(out.features.point_a),
          X_WA.ToBody(out.features.point_b), tol, horizon, kZoneSlack * scale);
      const double next_t =
          event.kind == narrow::ZoneEvent::Kind::kNone ? t_end : std::min(t + event.dt, t_end);
      // An exit that does not move the clock (dt below an ulp of t) could alternate between
      // two pairs on a zone plane: advance conservatively instead.
      const bool stalled = event.kind == narrow::ZoneEvent::Kind::kExit && next_t <= t;
      if (event.kind != narrow::ZoneEvent::Kind::kUnsupported && !stalled) {
        contact_predicted = event.kind == narrow::ZoneEvent::Kind::kContact;
        if (event.kind == narrow::ZoneEvent::Kind::kExit) start = event.next;
        t = next_t;
        continue;
      }
      ++out.advancement_steps;
    }

    // Rotating (or a degenerate translating pair): conservative advancement.
    const std::optional<double> step =
        PairAdvancement(out.features, path_a, r_a, path_b, r_b, t, target, horizon);
    t = step ? std::min(t + *step, t_end) : t_end;
  }
}

}  // namespace sparsedyn
