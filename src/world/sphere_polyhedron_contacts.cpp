// SPDX-License-Identifier: MIT
#include "world/sphere_polyhedron_contacts.hpp"

#include <cmath>

#include "dynamics/rigid_collision.hpp"
#include "dynamics/sphere_polyhedron_contact.hpp"
#include "math/event_time.hpp"
#include "narrow/sphere_contact.hpp"
#include "sparse/meeting.hpp"
#include "world/contact_band.hpp"
#include "world/pair_frame.hpp"
#include "world/phase_timer.hpp"

namespace sparsedyn {

SpherePolyhedronContacts::Pair SpherePolyhedronContacts::PairOf(std::uint32_t k) const {
  const Engagements::Engagement& e = detailed_.engagements()[k];
  if (core_.bodies.IsPolyhedron(e.a)) return {e.a, e.b};
  return {e.b, e.a};
}

PointClosest SpherePolyhedronContacts::Closest(std::uint32_t p, std::uint32_t s,
                                               std::optional<FeatureId> warm) const {
  const BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  const Vec3 centre = bodies.paths.TruePositionAt(s, now) + PairShift(core_, p, s);
  return FindClosestFeatureToPoint(*bodies.rigid.ShapeOf(p).tracked,
                                   bodies.RigidPathNow(p).PoseAt(now), centre, warm);
}

void SpherePolyhedronContacts::PredictEngagement(std::uint32_t k) {
  Statistics& stats = core_.observers.stats();
  const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_detailed);
  const BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  const Pair pair = PairOf(k);
  Engagements::Engagement& e = detailed_.engagements()[k];
  const Vec3 shift = PairShift(core_, pair.polyhedron, pair.sphere);
  const double separation =
      EventTime(now, PredictSeparation(bodies.MoverOf(pair.polyhedron, now),
                                       bodies.MoverOf(pair.sphere, now), shift));
  const double tolerance = PairTolerance(core_, pair.polyhedron, pair.sphere);
  const double radius = bodies.materials.Radius(pair.sphere);
  const std::optional<FeatureId> warm =
      e.has_features ? std::optional<FeatureId>(e.features.a) : std::nullopt;
  const PointClosest current = Closest(pair.polyhedron, pair.sphere, warm);
  e.features.a = current.feature;
  e.has_features = true;
  e.contact_next = false;
  e.checkpoint = false;
  double time = separation;
  if (current.distance - radius <= tolerance) {
    // Touching now: the contact handler decides whether any point approaches.
    e.contact_next = true;
    time = now;
  } else if (bodies.HasDrag(pair.polyhedron) || bodies.HasDrag(pair.sphere)) {
    // On the true motions; a search left unfinished is an early contact that predicts again.
    ++stats.detail_predictions;
    std::optional<FeatureId> feature = e.features.a;
    const double contact = drag_.PolyhedronSphereContact(
        DragContacts::Side{pair.polyhedron}, DragContacts::Side{pair.sphere, shift}, radius,
        tolerance, now, separation, feature);
    e.features.a = *feature;
    if (contact < separation) {
      e.contact_next = true;
      time = contact;
    }
  } else {
    ++stats.detail_predictions;
    ContactPredictionOptions options;
    options.tolerance = tolerance;
    options.max_iterations = kIterationsPerPrediction;
    options.spin_radius_a = bodies.rigid.SpinRadius(pair.polyhedron);
    Path centre = bodies.paths.PathOf(pair.sphere);
    centre.p0 += shift;
    const SphereContactPrediction p =
        PredictSphereContact(*bodies.rigid.ShapeOf(pair.polyhedron).tracked,
                             bodies.RigidPathOf(pair.polyhedron), centre, radius, now, separation,
                             e.features.a, options);
    stats.detail_iterations += static_cast<std::uint64_t>(p.iterations);
    if (p.kind != ContactPrediction::Kind::kNone && p.time <= separation) {
      e.contact_next = p.kind == ContactPrediction::Kind::kContact;
      e.checkpoint = !e.contact_next;
      if (e.checkpoint) ++stats.detail_checkpoints;
      e.features.a = p.closest.feature;
      time = std::max(now, p.time);
    }
  }
  detailed_.Schedule(k, time);
}

void SpherePolyhedronContacts::HandleContact(std::uint32_t k) {
  Engagements::Engagement& e = detailed_.engagements()[k];
  Statistics& stats = core_.observers.stats();
  const Pair pair = PairOf(k);
  PointClosest closest;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_detailed);
    closest = Closest(pair.polyhedron, pair.sphere, e.features.a);
  }
  e.features.a = closest.feature;
  const BodyStore& bodies = core_.bodies;
  const double tolerance = PairTolerance(core_, pair.polyhedron, pair.sphere);
  if (closest.distance - bodies.materials.Radius(pair.sphere) > tolerance) {
    ++stats.early_events;
    PredictEngagement(k);
    return;
  }
  if (Collide(pair, closest)) return;
  // Touching, but no point approaches: look again once the tolerance band could have been
  // closed (the sphere's spin moves no surface; the polyhedron's moves at most |w| R).
  const double now = bodies.paths.Now();
  const Path& p = bodies.paths.PathOf(pair.polyhedron);
  const Path& s = bodies.paths.PathOf(pair.sphere);
  const double speed = (bodies.paths.TrueVelocityAt(pair.sphere, now) -
                        bodies.paths.TrueVelocityAt(pair.polyhedron, now))
                           .norm() +
                       bodies.rigid.Omega(pair.polyhedron).norm() *
                           bodies.materials.Radius(pair.polyhedron);
  // With drag, the paths' accelerations are not the true ones: their bounds.
  const double acceleration =
      bodies.HasDrag(pair.polyhedron) || bodies.HasDrag(pair.sphere)
          ? bodies.AccelerationBound(pair.polyhedron) + bodies.AccelerationBound(pair.sphere)
          : (s.a - p.a).norm();
  const Vec3 shift = PairShift(core_, pair.polyhedron, pair.sphere);
  const double separation =
      EventTime(now, PredictSeparation(bodies.MoverOf(pair.polyhedron, now),
                                       bodies.MoverOf(pair.sphere, now), shift));
  const double again = BandExit(now, tolerance, speed, acceleration);
  e.contact_next = false;
  e.checkpoint = again < separation;
  detailed_.Schedule(k, std::min(again, separation));
}

bool SpherePolyhedronContacts::Collide(const Pair& pair, const PointClosest& closest) {
  const BodyStore& bodies = core_.bodies;
  Statistics& stats = core_.observers.stats();
  const double now = bodies.paths.Now();
  const std::uint32_t p = pair.polyhedron, s = pair.sphere;
  const ContactGeometry contact = SphereContactGeometry(closest, bodies.materials.Radius(s));
  RigidImpulseResult result;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_response);
    const RigidPath path_p = bodies.RigidPathNow(p);
    const Pose pose_p = path_p.PoseAt(now);
    // The sphere's image nearest to the polyhedron: the contact's frame.
    const Vec3 centre = closest.point + closest.distance * closest.normal;
    RigidBodyState body_p{pose_p.translation, path_p.centre.VelocityAt(now),
                          bodies.rigid.Omega(p), bodies.materials.InvMass(p),
                          bodies.InvInertiaWorld(p, pose_p.rotation)};
    RigidBodyState body_s{centre, bodies.paths.VelocityNow(s), bodies.rigid.Omega(s),
                          bodies.materials.InvMass(s),
                          bodies.InvInertiaWorld(s, Eigen::Quaterniond::Identity())};
    RigidImpulseOptions options;
    options.restitution = bodies.materials.Restitution(p) * bodies.materials.Restitution(s);
    options.friction = std::sqrt(bodies.materials.Friction(p) * bodies.materials.Friction(s));
    options.elastic_below_speed = core_.settings.elastic_below_speed;
    result = ApplyRigidImpulse(body_p, body_s, contact, options);
    if (result.rounds == 0) return false;
    changes_.SetCollidedMotion(p, body_p.velocity, body_p.angular_velocity);
    changes_.SetCollidedMotion(s, body_s.velocity, body_s.angular_velocity);
  }
  detailed_.AfterRigidCollision(p, s, contact, result);
  return true;
}

}  // namespace sparsedyn
