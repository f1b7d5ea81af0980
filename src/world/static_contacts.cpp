// SPDX-License-Identifier: MIT
#include "world/static_contacts.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/sphere_polyhedron_contact.hpp"
#include "math/event_time.hpp"
#include "narrow/point_features.hpp"
#include "narrow/sphere_contact.hpp"
#include "narrow/time_of_contact.hpp"
#include "sparse/meeting.hpp"
#include "world/contact_band.hpp"
#include "world/phase_timer.hpp"
#include "world/static_leave.hpp"
#include "world/support_polygon.hpp"

namespace sparsedyn {

double StaticContacts::Tolerance(std::uint32_t i, std::uint32_t s) const {
  const double r = core_.bodies.materials.Radius(i);
  return core_.settings.contact_tolerance * (r + std::min(r, core_.bodies.statics[s].radius));
}

double StaticContacts::ExitTime(std::uint32_t i, std::uint32_t s) const {
  // The tree's entry is never late, so at the engagement's start the sphere may still be a
  // rounding error short of the box: the exit is that of a sphere a little larger (never
  // earlier than the true one), else the engagement would end at once and start again.
  const double now = core_.Now();
  Mover mover = core_.bodies.MoverOf(i, now);
  mover.r0 += 1e-9 * (mover.r0 + mover.p.cwiseAbs().maxCoeff());
  return EventTime(now, core_.bodies.statics.tree().Exit(mover, s));
}

RigidPath StaticContacts::PathOfStatic(std::uint32_t s) const {
  const StaticBodies::Static& body = core_.bodies.statics[s];
  return RigidPath{Path{body.pose.translation, Vec3::Zero(), Vec3::Zero(), core_.Now()},
                   body.pose.rotation, Vec3::Zero()};
}

StaticContacts::Touch StaticContacts::TouchNow(std::uint32_t i, std::uint32_t s,
                                               std::optional<FeaturePair> warm) const {
  const BodyStore& bodies = core_.bodies;
  const StaticBodies::Static& st = bodies.statics[s];
  const double now = core_.Now();
  const bool moving_polyhedron = bodies.IsPolyhedron(i);
  const bool static_polyhedron = st.shape != kNoIndex;
  // A body with drag is where its true motion is (its element's path is within an envelope).
  const Pose pose_i = bodies.RigidPathNow(i).PoseAt(now);
  Touch touch;
  if (moving_polyhedron && static_polyhedron) {
    const BodyShape& shape_i = bodies.rigid.ShapeOf(i);
    const BodyShape& shape_s = bodies.rigid.shapes()[st.shape];
    const ClosestFeatures features =
        FindClosestFeatures(*shape_i.tracked, pose_i, *shape_s.tracked, st.pose, warm);
    touch.features = features.features;
    touch.contact = ContactFromFeatures(*shape_i.polyhedron, pose_i, *shape_s.polyhedron,
                                        st.pose, features, Tolerance(i, s));
    return touch;
  }
  if (moving_polyhedron || static_polyhedron) {
    // The polyhedron is body A: the normal points from it to the sphere's centre.
    const BodyShape& shape = moving_polyhedron ? bodies.rigid.ShapeOf(i)
                                               : bodies.rigid.shapes()[st.shape];
    const Pose& pose = moving_polyhedron ? pose_i : st.pose;
    const Vec3 centre = moving_polyhedron ? st.pose.translation : pose_i.translation;
    const double radius = moving_polyhedron ? st.radius : bodies.materials.Radius(i);
    const std::optional<FeatureId> start = warm ? std::optional<FeatureId>(warm->a) : std::nullopt;
    const PointClosest closest = FindClosestFeatureToPoint(*shape.tracked, pose, centre, start);
    touch.features.a = closest.feature;
    touch.contact = SphereContactGeometry(closest, radius);
    touch.static_is_a = static_polyhedron;
    return touch;
  }
  // Two spheres: the static is body A.
  const Vec3 d = pose_i.translation - st.pose.translation;
  const double distance = d.norm();
  touch.static_is_a = true;
  touch.contact.normal = d / distance;
  touch.contact.distance = distance - st.radius - bodies.materials.Radius(i);
  touch.contact.points = {st.pose.translation +
                          (st.radius + 0.5 * touch.contact.distance) * touch.contact.normal};
  return touch;
}

std::optional<Vec3> StaticContacts::StaticFaceNormal(std::uint32_t s, const Touch& touch) const {
  const StaticBodies::Static& st = core_.bodies.statics[s];
  if (st.shape == kNoIndex) return std::nullopt;
  // The static's feature: body A's for a sphere on it, else B's (the moving body is A).
  const FeatureId feature = touch.static_is_a ? touch.features.a : touch.features.b;
  if (feature.type != FeatureType::kFace) return std::nullopt;
  const ConvexPolyhedron& polyhedron = *core_.bodies.rigid.shapes()[st.shape].polyhedron;
  return st.pose.rotation * polyhedron.face(feature.index).plane.normal;
}

void StaticContacts::PredictEngagement(std::uint32_t k) {
  Statistics& stats = core_.observers.stats();
  const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_detailed);
  const BodyStore& bodies = core_.bodies;
  const double now = core_.Now();
  Engagements::Engagement& e = detailed_.engagements()[k];
  const std::uint32_t i = e.a, s = StaticBodies::IndexOf(e.b);
  const StaticBodies::Static& st = bodies.statics[s];
  // The engagement lasts while the element's sphere is within the static's (inflated) box.
  const double exit = ExitTime(i, s);
  const double tolerance = Tolerance(i, s);
  const std::optional<FeaturePair> warm =
      e.has_features ? std::optional<FeaturePair>(e.features) : std::nullopt;
  if (bodies.HasDrag(i)) {
    PredictDragEngagement(k, now);
    return;
  }
  const Touch touch = TouchNow(i, s, warm);
  e.features = touch.features;
  e.has_features = true;
  e.contact_next = false;
  e.checkpoint = false;
  double time = exit;
  if (bodies.paths.accelerations().HoldOf(i).on_static == s) {
    // Held on a face of this convex static: the body is on the far side of the face's plane,
    // all of the static on the near side, so no other contact is possible; the hold ends when
    // its centre leaves the face (a body timer, StaticLeaveTime) or a collision moves it.
    detailed_.Schedule(k, exit);
    return;
  }
  if (touch.contact.distance <= tolerance) {
    e.contact_next = true;  // touching now: the handler decides whether any point approaches
    detailed_.Schedule(k, now);
    return;
  }
  ++stats.detail_predictions;
  ContactPredictionOptions options;
  options.tolerance = tolerance;
  options.max_iterations = kIterationsPerPrediction;
  const RigidPath path_i = bodies.RigidPathOf(i);
  const bool moving_polyhedron = bodies.IsPolyhedron(i), static_polyhedron = st.shape != kNoIndex;
  ContactPrediction::Kind kind = ContactPrediction::Kind::kNone;
  double found = kInfinity;
  int iterations = 0;
  if (moving_polyhedron && static_polyhedron) {
    options.spin_radius_a = bodies.rigid.SpinRadius(i);
    options.spin_radius_b = 0.0;
    const ContactPrediction p =
        PredictContact(*bodies.rigid.ShapeOf(i).tracked, path_i,
                       *bodies.rigid.shapes()[st.shape].tracked, PathOfStatic(s), now, exit,
                       e.features, options);
    kind = p.kind;
    found = p.time;
    iterations = p.iterations;
    if (kind != ContactPrediction::Kind::kNone) e.features = p.features.features;
  } else if (moving_polyhedron || static_polyhedron) {
    const TrackedPolyhedron& polyhedron = moving_polyhedron
                                              ? *bodies.rigid.ShapeOf(i).tracked
                                              : *bodies.rigid.shapes()[st.shape].tracked;
    const RigidPath path = moving_polyhedron ? path_i : PathOfStatic(s);
    const Path centre = moving_polyhedron ? PathOfStatic(s).centre : path_i.centre;
    const double radius = moving_polyhedron ? st.radius : bodies.materials.Radius(i);
    options.spin_radius_a = moving_polyhedron ? bodies.rigid.SpinRadius(i) : 0.0;
    const SphereContactPrediction p = PredictSphereContact(polyhedron, path, centre, radius, now,
                                                           exit, e.features.a, options);
    kind = p.kind;
    found = p.time;
    iterations = p.iterations;
    if (kind != ContactPrediction::Kind::kNone) e.features.a = p.closest.feature;
  } else {
    const Mover fixed{st.pose.translation, Vec3::Zero(), Vec3::Zero(), st.radius, 0.0, 0.0};
    found = EventTime(now, PredictMeeting(bodies.BodyMoverOf(i, now), fixed, Vec3::Zero()));
    if (found <= exit) kind = ContactPrediction::Kind::kContact;
  }
  stats.detail_iterations += static_cast<std::uint64_t>(iterations);
  if (kind != ContactPrediction::Kind::kNone && found <= exit) {
    e.contact_next = kind == ContactPrediction::Kind::kContact;
    e.checkpoint = !e.contact_next;
    if (e.checkpoint) ++stats.detail_checkpoints;
    time = std::max(now, found);
  }
  detailed_.Schedule(k, time);
}

void StaticContacts::HandleContact(std::uint32_t k) {
  Engagements::Engagement& e = detailed_.engagements()[k];
  Statistics& stats = core_.observers.stats();
  const std::uint32_t i = e.a, s = StaticBodies::IndexOf(e.b);
  Touch touch;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_detailed);
    touch = TouchNow(i, s, e.features);
  }
  e.features = touch.features;
  const double tolerance = Tolerance(i, s);
  if (touch.contact.distance > tolerance) {
    ++stats.early_events;
    PredictEngagement(k);
    return;
  }
  if (HoldOnFace(i, s, touch) || Collide(i, s, touch)) return;
  const BodyStore& bodies = core_.bodies;
  const double now = core_.Now();
  if (bodies.HasDrag(i) && !bodies.IsPolyhedron(i)) {
    // Touching, but not approaching: the true motion from just after now (its steps know
    // whether a sphere closes).
    PredictDragEngagement(k, std::nextafter(now, kInfinity));
    return;
  }
  // Touching, but no point approaches: look again once the band could have been closed.
  double speed = bodies.paths.TrueVelocityAt(i, now).norm() +
                 bodies.rigid.SpinRadius(i) * bodies.rigid.Omega(i).norm();
  double acceleration = bodies.AccelerationBound(i);
  if (const std::optional<Vec3> n = StaticFaceNormal(s, touch); n && !bodies.HasDrag(i)) {
    // On a face of a convex static, the body is as far from the static as from the face's
    // plane at least: only its motion across that plane can close the band.
    const RigidPath path = bodies.RigidPathNow(i);
    const GapClosing closing = PlaneGapClosing(*n, path.centre.VelocityAt(now), path.centre.a,
                                               path.omega, bodies.rigid.SpinRadius(i));
    speed = closing.speed;
    acceleration = closing.acceleration;
  }
  const double exit = ExitTime(i, s);
  // A polyhedron with drag too: the checkpoint predicts on its true motion from there.
  const double again = BandExit(now, tolerance, speed, acceleration);
  e.contact_next = false;
  e.checkpoint = again < exit;
  detailed_.Schedule(k, std::min(again, exit));
}

void StaticContacts::PredictDragEngagement(std::uint32_t k, double begin) {
  Statistics& stats = core_.observers.stats();
  const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_detailed);
  Engagements::Engagement& e = detailed_.engagements()[k];
  const std::uint32_t i = e.a, s = StaticBodies::IndexOf(e.b);
  const double exit = ExitTime(i, s);
  const double end = std::min(exit, core_.bodies.paths.drags().CheckTime(i));
  std::optional<FeatureId> feature =
      e.has_features ? std::optional<FeatureId>(e.features.a) : std::nullopt;
  ++stats.detail_predictions;
  const BodyStore& bodies = core_.bodies;
  const StaticBodies::Static& st = bodies.statics[s];
  double contact = kInfinity;
  if (bodies.IsPolyhedron(i)) {
    // The static on its fixed path; a polyhedron's pair keeps both features.
    const DragContacts::Side moving{i};
    DragContacts::Side fixed{kNoIndex, Vec3::Zero(), PathOfStatic(s)};
    if (st.shape != kNoIndex) {
      fixed.shape = bodies.rigid.shapes()[st.shape].tracked.get();
      std::optional<FeaturePair> features =
          e.has_features ? std::optional<FeaturePair>(e.features) : std::nullopt;
      contact = drag_.PolyhedraContact(moving, fixed, Tolerance(i, s), begin, end, features);
      if (features) e.features = *features;
    } else {
      contact = drag_.PolyhedronSphereContact(moving, fixed, st.radius, Tolerance(i, s), begin,
                                              end, feature);
      if (feature) e.features.a = *feature;
    }
    e.has_features = true;
  } else {
    contact = drag_.StaticContact(i, s, Tolerance(i, s), begin, end, feature);
    if (feature) {
      e.features.a = *feature;
      e.has_features = true;
    }
  }
  // An unfinished search (a time before end) is an early contact event that predicts again.
  e.contact_next = contact < end;
  e.checkpoint = false;
  detailed_.Schedule(k, e.contact_next ? contact : exit);
}

bool StaticContacts::HoldOnFace(std::uint32_t i, std::uint32_t s, const Touch& touch) {
  // As on a wall (WallContacts::HoldAgainstWall, HoldPolyhedron): touching a face of the
  // static, moving to or from it slower than the collapse guard at every contact point, pressed
  // into it by gravity or thrust, and (a polyhedron) on a face of its own with the centre of
  // mass over the contact polygon. Its velocity and acceleration along the face's normal go,
  // and of a polyhedron's spin only the part about the normal stays. Bodies with drag, and a
  // body held by another static already, are left to bounce.
  const BodyStore& bodies = core_.bodies;
  const std::optional<Vec3> n = StaticFaceNormal(s, touch);
  if (!n || bodies.HasDrag(i)) return false;
  const Accelerations& accelerations = bodies.paths.accelerations();
  Hold hold = accelerations.HoldOf(i);
  if (hold.on_static != kNoIndex || !(n->dot(accelerations.Free(i)) < 0.0)) return false;
  const double now = core_.Now();
  const RigidPath path = bodies.RigidPathNow(i);
  const double guard = core_.settings.elastic_below_speed;
  std::optional<Vec3> omega;
  if (bodies.IsPolyhedron(i)) {
    std::vector<Vec3> points = touch.contact.points;
    if (points.size() < 3) return false;
    for (const Vec3& x : points) {
      if (!(std::abs(n->dot(path.PointVelocity(x, now))) < guard)) return false;
    }
    OrderAroundMean(points, *n);
    if (!OverPolygon(points, path.centre.PositionAt(now), *n)) return false;
    omega = n->dot(path.omega) * *n;
  } else if (!(std::abs(n->dot(path.centre.VelocityAt(now))) < guard)) {
    return false;
  }
  hold.on_static = s;
  hold.normal = *n;
  hold.face = (touch.static_is_a ? touch.features.a : touch.features.b).index;
  const Vec3 v = path.centre.VelocityAt(now);
  // Its centre must be inside the face, with time to go (else it would leave as it lands).
  const Path centre{path.centre.PositionAt(now), Accelerations::HeldAcceleration(v, hold),
                    Accelerations::HeldAcceleration(accelerations.Free(i), hold), now};
  if (!(FaceLeaveTime(StaticFaceLoop(bodies, s, hold.face), *n, centre, now) > now)) return false;
  changes_.SetHeld(i, hold, v, omega);
  Statistics& stats = core_.observers.stats();
  core_.observers.NotePenetration(touch.contact.distance, Tolerance(i, s));
  ++stats.static_holds;
  ++stats.collisions;
  ++stats.static_collisions;
  if (core_.observers.WantsCollisions()) {
    const BodyId moving_id = bodies.ids.IdOf(i);
    const BodyId static_id = bodies.ids.IdOfSlot(bodies.statics[s].slot);
    const double impulse = std::max(-n->dot(v), 0.0) / bodies.materials.InvMass(i);
    core_.observers.Collision(CollisionEvent{now, touch.static_is_a ? static_id : moving_id,
                                             touch.static_is_a ? moving_id : static_id, -1,
                                             touch.contact.points.front(), touch.contact.normal, impulse});
  }
  if (sparse_.PredictionOf(i).kind != EventKind::kNone) ++stats.stale_actor_absent;
  sparse_.PredictFull(i);
  detailed_.PredictEngagementsOf(i);
  return true;
}

bool StaticContacts::Collide(std::uint32_t i, std::uint32_t s, const Touch& touch) {
  const BodyStore& bodies = core_.bodies;
  Statistics& stats = core_.observers.stats();
  const double now = core_.Now();
  const StaticBodies::Static& st = bodies.statics[s];
  RigidImpulseResult result;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_response);
    const Pose pose_i = bodies.RigidPathNow(i).PoseAt(now);
    RigidBodyState moving{pose_i.translation, bodies.paths.VelocityNow(i), bodies.rigid.Omega(i),
                          bodies.materials.InvMass(i),
                          bodies.InvInertiaWorld(i, pose_i.rotation)};
    RigidBodyState fixed{st.pose.translation, Vec3::Zero(), Vec3::Zero(), 0.0,
                         Eigen::Matrix3d::Zero()};
    RigidImpulseOptions options;
    options.restitution = bodies.materials.Restitution(i) * st.restitution;
    options.friction = std::sqrt(bodies.materials.Friction(i) * st.friction);
    options.elastic_below_speed = core_.settings.elastic_below_speed;
    result = touch.static_is_a ? ApplyRigidImpulse(fixed, moving, touch.contact, options)
                               : ApplyRigidImpulse(moving, fixed, touch.contact, options);
    if (result.rounds == 0) return false;
    changes_.SetCollidedMotion(i, moving.velocity, moving.angular_velocity);
  }
  core_.observers.NotePenetration(touch.contact.distance, Tolerance(i, s));
  ++stats.collisions;
  ++stats.static_collisions;
  if (result.guarded) ++stats.collapse_guarded;
  if (core_.observers.WantsCollisions()) {
    const BodyId moving_id = bodies.ids.IdOf(i), static_id = bodies.ids.IdOfSlot(st.slot);
    core_.observers.Collision(CollisionEvent{now, touch.static_is_a ? static_id : moving_id,
                                             touch.static_is_a ? moving_id : static_id, -1,
                                             result.point, touch.contact.normal,
                                             result.normal_impulse});
  }
  if (sparse_.PredictionOf(i).kind != EventKind::kNone) ++stats.stale_actor_absent;
  sparse_.PredictFull(i);
  detailed_.PredictEngagementsOf(i);  // this one with s too: i's path changed
  return true;
}

}  // namespace sparsedyn
