// SPDX-License-Identifier: MIT
#include "world/detailed_phase.hpp"

#include "math/event_time.hpp"
#include "sparse/meeting.hpp"
#include "sparsedyn/assert.hpp"
#include "world/pair_frame.hpp"
#include "world/polyhedron_contacts.hpp"
#include "world/sphere_contacts.hpp"
#include "world/sphere_polyhedron_contacts.hpp"
#include "world/static_contacts.hpp"

namespace sparsedyn {

PairKind DetailedPhase::KindOf(std::uint32_t a, std::uint32_t b) const {
  if (StaticBodies::IsKey(b)) return PairKind::kStatic;
  if (core_.bodies.IsGod(a) && core_.bodies.IsGod(b)) return PairKind::kInert;
  const bool poly_a = core_.bodies.IsPolyhedron(a), poly_b = core_.bodies.IsPolyhedron(b);
  if (poly_a && poly_b) return PairKind::kPolyhedra;
  if (poly_a || poly_b) return PairKind::kSpherePolyhedron;
  return PairKind::kSpheres;
}

void DetailedPhase::Engage(std::uint32_t a, std::uint32_t b) {
  if (engagements_.Engaged(a, b)) return;
  const std::uint32_t k = engagements_.Add(a, b);
  ++core_.observers.stats().engagements_started;
  Predict(k);
}

void DetailedPhase::Predict(std::uint32_t k) {
  const Engagements::Engagement& e = engagements_[k];
  switch (KindOf(e.a, e.b)) {
    case PairKind::kSpheres:
      spheres_->PredictEngagement(k);
      break;
    case PairKind::kPolyhedra:
      polyhedra_->PredictEngagement(k);
      break;
    case PairKind::kSpherePolyhedron:
      mixed_->PredictEngagement(k);
      break;
    case PairKind::kStatic:
      statics_->PredictEngagement(k);
      break;
    case PairKind::kInert:
      PredictSeparation(k);
      break;
  }
}

void DetailedPhase::PredictSeparation(std::uint32_t k) {
  Engagements::Engagement& e = engagements_[k];
  const double now = core_.Now();
  e.contact_next = false;
  e.checkpoint = false;
  const BodyStore& bodies = core_.bodies;
  Schedule(k, EventTime(now, sparsedyn::PredictSeparation(bodies.MoverOf(e.a, now),
                                                          bodies.MoverOf(e.b, now),
                                                          Vec3::Zero())));
}

void DetailedPhase::Handle(std::uint32_t k) {
  const Engagements::Engagement& e = engagements_[k];
  // A checkpoint resumes the prediction, a separation ends the engagement, whatever the kind;
  // a contact is the model's.
  if (e.checkpoint) {
    Predict(k);
    return;
  }
  if (!e.contact_next) {
    End(k);
    return;
  }
  switch (KindOf(e.a, e.b)) {
    case PairKind::kSpheres:
      spheres_->HandleContact(k);
      break;
    case PairKind::kPolyhedra:
      polyhedra_->HandleContact(k);
      break;
    case PairKind::kSpherePolyhedron:
      mixed_->HandleContact(k);
      break;
    case PairKind::kStatic:
      statics_->HandleContact(k);
      break;
    case PairKind::kInert:
      SPARSEDYN_ASSERT(false, "an inert pair has no contact");
  }
}

void DetailedPhase::Schedule(std::uint32_t k, double time) {
  if (time == kInfinity) {
    queue_.Erase(k);
  } else {
    queue_.Set(k, time, EventKind::kEngagement);
  }
}

void DetailedPhase::End(std::uint32_t k) {
  const std::uint32_t a = engagements_[k].a;
  queue_.Erase(k);
  engagements_.Remove(k);
  ++core_.observers.stats().engagements_ended;
  sparse_.PredictFull(a);
}

void DetailedPhase::AfterRigidCollision(std::uint32_t a, std::uint32_t b,
                                        const ContactGeometry& contact,
                                        const RigidImpulseResult& result) {
  Statistics& stats = core_.observers.stats();
  core_.observers.NotePenetration(contact.distance, PairTolerance(core_, a, b));
  ++stats.collisions;
  if (result.guarded) ++stats.collapse_guarded;
  if (core_.observers.WantsCollisions()) {
    const BodyIds& ids = core_.bodies.ids;
    core_.observers.Collision(CollisionEvent{core_.Now(), ids.IdOf(a), ids.IdOf(b), -1,
                                             result.point, contact.normal,
                                             result.normal_impulse});
  }
  // Both bodies' element predictions are superseded (actor-absent, §4.2), replaced in place.
  for (const std::uint32_t body : {a, b}) {
    if (sparse_.PredictionOf(body).kind != EventKind::kNone) ++stats.stale_actor_absent;
  }
  sparse_.PredictFull(a);
  sparse_.PredictFull(b);
  PredictEngagementsOf(a);
  PredictEngagementsOf(b, /*done_partner=*/a);
}

void DetailedPhase::PredictEngagementsOf(std::uint32_t i, std::uint32_t done_partner) {
  if (!core_.bodies.EngagesOnMeet() || !engagements_.HasAny(i)) return;
  for (const std::uint32_t k : engagements_.Of(i)) {
    const Engagements::Engagement& e = engagements_[k];
    if (e.a != done_partner && e.b != done_partner) Predict(k);
  }
}

void DetailedPhase::EngageOverlapping() {
  const ElementPaths& paths = core_.bodies.paths;
  const BodyMaterials& materials = core_.bodies.materials;
  for (std::uint32_t i = 0; i < paths.Size(); ++i) {
    sparse_.ForEachNeighbor(i, [&](std::uint32_t j, const Vec3&) {
      if (j <= i || engagements_.Engaged(i, j)) return;
      const Vec3 d = core_.MinimumImage(paths.Start(j).p0 - paths.Start(i).p0);
      const double reach = materials.Radius(i) + materials.Radius(j);
      if (d.squaredNorm() >= reach * reach) return;
      const std::uint32_t k = engagements_.Add(i, j);
      ++core_.observers.stats().engagements_started;
      Predict(k);
    });
  }
}

void DetailedPhase::Clear() {
  queue_.Clear();
  engagements_.Clear();
}

}  // namespace sparsedyn
