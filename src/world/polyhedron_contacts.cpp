// SPDX-License-Identifier: MIT
#include "world/polyhedron_contacts.hpp"

#include <cmath>

#include "dynamics/rigid_collision.hpp"
#include "math/event_time.hpp"
#include "narrow/time_of_contact.hpp"
#include "sparse/meeting.hpp"
#include "world/contact_band.hpp"
#include "world/pair_frame.hpp"
#include "world/phase_timer.hpp"

namespace sparsedyn {

ClosestFeatures PolyhedronContacts::PairFeatures(std::uint32_t a, std::uint32_t b,
                                                 const Vec3& shift,
                                                 std::optional<FeaturePair> warm) const {
  const BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  Pose pose_b = bodies.RigidPathNow(b).PoseAt(now);
  pose_b.translation += shift;
  return FindClosestFeatures(*bodies.rigid.ShapeOf(a).tracked, bodies.RigidPathNow(a).PoseAt(now),
                             *bodies.rigid.ShapeOf(b).tracked, pose_b, warm);
}

void PolyhedronContacts::PredictEngagement(std::uint32_t k) {
  Statistics& stats = core_.observers.stats();
  const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_detailed);
  const BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  Engagements::Engagement& e = detailed_.engagements()[k];
  const Vec3 shift = PairShift(core_, e.a, e.b);
  RigidPath path_a = bodies.RigidPathOf(e.a);
  RigidPath path_b = bodies.RigidPathOf(e.b);
  path_b.centre.p0 += shift;
  // The engagement lasts while the element spheres overlap.
  const double separation = EventTime(
      now, PredictSeparation(bodies.MoverOf(e.a, now), bodies.MoverOf(e.b, now), shift));
  const double tolerance = PairTolerance(core_, e.a, e.b);
  const std::optional<FeaturePair> warm =
      e.has_features ? std::optional<FeaturePair>(e.features) : std::nullopt;
  const ClosestFeatures current = PairFeatures(e.a, e.b, shift, warm);
  if (current.status == ClosestFeatures::Status::kIterationCap) ++stats.walk_cap_hits;
  e.features = current.features;
  e.has_features = true;
  e.contact_next = false;
  e.checkpoint = false;
  double time = separation;
  if (current.distance <= tolerance) {
    // Touching now: the contact handler decides whether any point approaches.
    e.contact_next = true;
    time = now;
  } else if (bodies.HasDrag(e.a) || bodies.HasDrag(e.b)) {
    // On the true motions; a search left unfinished is an early contact that predicts again.
    ++stats.detail_predictions;
    std::optional<FeaturePair> features = e.features;
    const double contact = drag_.PolyhedraContact(DragContacts::Side{e.a},
                                                  DragContacts::Side{e.b, shift}, tolerance,
                                                  now, separation, features);
    e.features = *features;
    if (contact < separation) {
      e.contact_next = true;
      time = contact;
    }
  } else {
    ++stats.detail_predictions;
    ContactPredictionOptions options;
    options.tolerance = tolerance;
    options.max_iterations = kIterationsPerPrediction;
    options.spin_radius_a = bodies.rigid.SpinRadius(e.a);
    options.spin_radius_b = bodies.rigid.SpinRadius(e.b);
    const ContactPrediction p =
        PredictContact(*bodies.rigid.ShapeOf(e.a).tracked, path_a,
                       *bodies.rigid.ShapeOf(e.b).tracked, path_b, now, separation, e.features,
                       options);
    stats.detail_iterations += static_cast<std::uint64_t>(p.iterations);
    if (p.kind != ContactPrediction::Kind::kNone && p.time <= separation) {
      e.contact_next = p.kind == ContactPrediction::Kind::kContact;
      e.checkpoint = !e.contact_next;
      if (e.checkpoint) ++stats.detail_checkpoints;
      e.features = p.features.features;
      time = std::max(now, p.time);
    }
  }
  detailed_.Schedule(k, time);
}

void PolyhedronContacts::HandleContact(std::uint32_t k) {
  Engagements::Engagement& e = detailed_.engagements()[k];
  Statistics& stats = core_.observers.stats();
  const Vec3 shift = PairShift(core_, e.a, e.b);
  ClosestFeatures features;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_detailed);
    features = PairFeatures(e.a, e.b, shift, e.features);
  }
  e.features = features.features;
  const double tolerance = PairTolerance(core_, e.a, e.b);
  if (features.distance > tolerance) {
    ++stats.early_events;
    PredictEngagement(k);
    return;
  }
  if (Collide(e.a, e.b, features, shift)) return;
  // Touching, but no point approaches (they have just bounced, or slide past each other):
  // look again once the tolerance band could have been closed.
  const BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  const RigidPath a = bodies.RigidPathNow(e.a);
  const RigidPath b = bodies.RigidPathNow(e.b);
  const double speed = (b.centre.VelocityAt(now) - a.centre.VelocityAt(now)).norm() +
                       a.omega.norm() * bodies.materials.Radius(e.a) +
                       b.omega.norm() * bodies.materials.Radius(e.b);
  // With drag, the paths' accelerations are not the true ones: their bounds.
  const double acceleration =
      bodies.HasDrag(e.a) || bodies.HasDrag(e.b)
          ? bodies.AccelerationBound(e.a) + bodies.AccelerationBound(e.b)
          : (b.centre.a - a.centre.a).norm();
  const double separation = EventTime(
      now, PredictSeparation(bodies.MoverOf(e.a, now), bodies.MoverOf(e.b, now), shift));
  const double again = BandExit(now, tolerance, speed, acceleration);
  e.contact_next = false;
  e.checkpoint = again < separation;
  detailed_.Schedule(k, std::min(again, separation));
}

bool PolyhedronContacts::Collide(std::uint32_t a, std::uint32_t b,
                                 const ClosestFeatures& features, const Vec3& shift) {
  const BodyStore& bodies = core_.bodies;
  Statistics& stats = core_.observers.stats();
  const double now = bodies.paths.Now();
  RigidImpulseResult result;
  ContactGeometry contact;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_response);
    const RigidPath path_a = bodies.RigidPathNow(a);
    RigidPath path_b = bodies.RigidPathNow(b);
    path_b.centre.p0 += shift;
    const Pose pose_a = path_a.PoseAt(now);
    const Pose pose_b = path_b.PoseAt(now);
    contact = ContactFromFeatures(*bodies.rigid.ShapeOf(a).polyhedron, pose_a,
                                  *bodies.rigid.ShapeOf(b).polyhedron, pose_b, features,
                                  PairTolerance(core_, a, b));
    RigidBodyState body_a{pose_a.translation, path_a.centre.VelocityAt(now),
                          bodies.rigid.Omega(a), bodies.materials.InvMass(a),
                          bodies.InvInertiaWorld(a, pose_a.rotation)};
    RigidBodyState body_b{pose_b.translation, path_b.centre.VelocityAt(now),
                          bodies.rigid.Omega(b), bodies.materials.InvMass(b),
                          bodies.InvInertiaWorld(b, pose_b.rotation)};
    RigidImpulseOptions options;
    options.restitution = bodies.materials.Restitution(a) * bodies.materials.Restitution(b);
    options.friction = std::sqrt(bodies.materials.Friction(a) * bodies.materials.Friction(b));
    options.elastic_below_speed = core_.settings.elastic_below_speed;
    result = ApplyRigidImpulse(body_a, body_b, contact, options);
    if (result.rounds == 0) return false;
    changes_.SetCollidedMotion(a, body_a.velocity, body_a.angular_velocity);
    changes_.SetCollidedMotion(b, body_b.velocity, body_b.angular_velocity);
  }
  detailed_.AfterRigidCollision(a, b, contact, result);
  return true;
}

}  // namespace sparsedyn
