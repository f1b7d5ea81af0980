// SPDX-License-Identifier: MIT
#include "world/sphere_contacts.hpp"

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
  core_.observers.NotePenetration(gap);
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
      // A collision with another body ends a wall's hold (the wall takes it up again if the
      // body is still at rest against it).
      changes_.SetHeld(i, 0, result.v_a);
      changes_.SetHeld(j, 0, result.v_b);
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

void SphereContacts::PredictEngagement(std::uint32_t k) {
  const BodyStore& bodies = core_.bodies;
  Engagements::Engagement& e = detailed_.engagements()[k];
  const double now = bodies.paths.Now();
  // The periodic image of b nearest to a (zero shift outside periodic boxes).
  const Vec3 d = bodies.paths.PathOf(e.b).PositionAt(now) - bodies.paths.PathOf(e.a).PositionAt(now);
  const Vec3 shift = core_.MinimumImage(d) - d;
  // Contact of the bodies themselves (the detailed phase for spheres) or separation of the
  // element spheres, whichever comes first.
  const double contact =
      PredictMeeting(bodies.BodyMoverOf(e.a, now), bodies.BodyMoverOf(e.b, now), shift);
  const double separation =
      PredictSeparation(bodies.MoverOf(e.a, now), bodies.MoverOf(e.b, now), shift);
  e.contact_next = contact <= separation;
  detailed_.Schedule(k, EventTime(now, std::min(contact, separation)));
}

void SphereContacts::HandleEngagement(std::uint32_t k) {
  const Engagements::Engagement e = detailed_.engagements()[k];
  if (!e.contact_next) {
    detailed_.End(k);
    return;
  }
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
