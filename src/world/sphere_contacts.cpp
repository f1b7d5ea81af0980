// SPDX-License-Identifier: MIT
#include "world/sphere_contacts.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/rigid_collision.hpp"
#include "dynamics/sphere_collision.hpp"
#include "math/event_time.hpp"
#include "sparse/meeting.hpp"
#include "world/phase_timer.hpp"

namespace sparsedyn {

bool SphereContacts::TouchingAndApproaching(std::uint32_t i, std::uint32_t j, Vec3& normal,
                                            double& gap) const {
  const ElementPaths& paths = core_.bodies.paths;
  const BodyMaterials& materials = core_.bodies.materials;
  const Vec3 d = core_.MinimumImage(paths.PositionNow(j) - paths.PositionNow(i));
  const double reach = materials.Radius(i) + materials.Radius(j);
  const double distance = d.norm();
  gap = distance - reach;
  normal = d / distance;
  const Vec3 dv = paths.VelocityNow(j) - paths.VelocityNow(i);
  return gap <= core_.settings.contact_tolerance * reach && d.dot(dv) < 0;
}

void SphereContacts::Collide(std::uint32_t i, std::uint32_t j, const Vec3& normal, double gap) {
  const ElementPaths& paths = core_.bodies.paths;
  const BodyMaterials& materials = core_.bodies.materials;
  Statistics& stats = core_.observers.stats();
  core_.observers.NotePenetration(
      gap, core_.settings.contact_tolerance * (materials.Radius(i) + materials.Radius(j)));
  if (core_.bodies.rigid.Tracked() && materials.Friction(i) * materials.Friction(j) > 0) {
    CollideWithFriction(i, j, normal, gap);
    return;
  }
  ImpulseResult result;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_response);
    result = SphereImpulse(paths.VelocityNow(i), paths.VelocityNow(j), materials.InvMass(i),
                           materials.InvMass(j), normal,
                           materials.Restitution(i) * materials.Restitution(j),
                           core_.settings.elastic_below_speed);
    if (!paths.accelerations().AnyHeld()) {
      changes_.SetVelocity(i, result.v_a);
      changes_.SetVelocity(j, result.v_b);
    } else {
      // A collision with another body ends a hold (the wall or static takes it up again if
      // the body is still at rest against it).
      changes_.SetHeld(i, Hold{}, result.v_a);
      changes_.SetHeld(j, Hold{}, result.v_b);
    }
  }
  ++stats.collisions;
  if (result.guarded) ++stats.collapse_guarded;
  if (core_.observers.WantsCollisions()) {
    const Vec3 p_i = paths.Start(i).p0;
    core_.observers.Collision(CollisionEvent{paths.Now(), core_.bodies.ids.IdOf(i),
                                             core_.bodies.ids.IdOf(j), -1,
                                             p_i + materials.Radius(i) * normal, normal,
                                             result.impulse});
  }
  sparse_.PredictCollided(i, j);
  if (!core_.bodies.EngagesOnMeet()) return;  // a gas: no engagements, and no call to find that out
  detailed_.PredictEngagementsOf(i);
  detailed_.PredictEngagementsOf(j, /*done_partner=*/i);
}

void SphereContacts::CollideWithFriction(std::uint32_t i, std::uint32_t j, const Vec3& normal,
                                         double gap) {
  // Rubbing spheres: the rigid impulse at the one contact point, with the spins (solid spheres,
  // I = 2/5 m r^2) and Coulomb friction of sqrt(mu_i mu_j).
  const BodyStore& bodies = core_.bodies;
  const ElementPaths& paths = bodies.paths;
  Statistics& stats = core_.observers.stats();
  const double ri = bodies.materials.Radius(i);
  const Vec3 centre_i = paths.PositionNow(i);
  const Vec3 centre_j = centre_i + (ri + bodies.materials.Radius(j) + gap) * normal;
  ContactGeometry contact;
  contact.normal = normal;
  contact.distance = gap;
  contact.points = {centre_i + (ri + 0.5 * gap) * normal};
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  RigidBodyState a{centre_i, paths.VelocityNow(i), bodies.rigid.Omega(i),
                   bodies.materials.InvMass(i), bodies.InvInertiaWorld(i, identity)};
  RigidBodyState b{centre_j, paths.VelocityNow(j), bodies.rigid.Omega(j),
                   bodies.materials.InvMass(j), bodies.InvInertiaWorld(j, identity)};
  RigidImpulseOptions options;
  options.restitution = bodies.materials.Restitution(i) * bodies.materials.Restitution(j);
  options.friction = std::sqrt(bodies.materials.Friction(i) * bodies.materials.Friction(j));
  options.elastic_below_speed = core_.settings.elastic_below_speed;
  RigidImpulseResult result;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_response);
    result = ApplyRigidImpulse(a, b, contact, options);
    changes_.SetCollidedMotion(i, a.velocity, a.angular_velocity);
    changes_.SetCollidedMotion(j, b.velocity, b.angular_velocity);
  }
  ++stats.collisions;
  if (result.guarded) ++stats.collapse_guarded;
  if (core_.observers.WantsCollisions()) {
    core_.observers.Collision(CollisionEvent{paths.Now(), bodies.ids.IdOf(i), bodies.ids.IdOf(j),
                                             -1, contact.points.front(), normal,
                                             result.normal_impulse});
  }
  sparse_.PredictCollided(i, j);
  detailed_.PredictEngagementsOf(i);
  detailed_.PredictEngagementsOf(j, /*done_partner=*/i);
}

void SphereContacts::PredictEngagement(std::uint32_t k) {
  const BodyStore& bodies = core_.bodies;
  Engagements::Engagement& e = detailed_.engagements()[k];
  const double now = bodies.paths.Now();
  // The periodic image of b nearest to a (zero shift outside periodic boxes).
  const Vec3 d = bodies.paths.PathOf(e.b).PositionAt(now) - bodies.paths.PathOf(e.a).PositionAt(now);
  const Vec3 shift = core_.MinimumImage(d) - d;
  // Contact of the bodies themselves (the detailed phase for spheres) or separation of the
  // element spheres, whichever comes first.
  const double separation =
      PredictSeparation(bodies.MoverOf(e.a, now), bodies.MoverOf(e.b, now), shift);
  if (bodies.HasDrag(e.a) || bodies.HasDrag(e.b)) {
    // A body with drag: the contact on the true motions, up to the separation or a check.
    const DragMotions& drags = bodies.paths.drags();
    const double end = std::min({EventTime(now, separation), drags.CheckTime(e.a),
                                 drags.CheckTime(e.b)});
    const double contact = drag_.PairContact(e.a, e.b, shift, now, end);
    e.contact_next = contact <= EventTime(now, separation);
    detailed_.Schedule(k, std::min(contact, EventTime(now, separation)));
    return;
  }
  const double contact =
      PredictMeeting(bodies.BodyMoverOf(e.a, now), bodies.BodyMoverOf(e.b, now), shift);
  e.contact_next = contact <= separation;
  detailed_.Schedule(k, EventTime(now, std::min(contact, separation)));
}

void SphereContacts::HandleContact(std::uint32_t k) {
  const Engagements::Engagement e = detailed_.engagements()[k];
  Vec3 normal;
  double gap = 0;
  if (TouchingAndApproaching(e.a, e.b, normal, gap)) {
    Collide(e.a, e.b, normal, gap);
    return;
  }
  const BodyMaterials& materials = core_.bodies.materials;
  if (gap > core_.settings.contact_tolerance * (materials.Radius(e.a) + materials.Radius(e.b))) {
    ++core_.observers.stats().early_events;
  }
  PredictEngagement(k);
}

}  // namespace sparsedyn
