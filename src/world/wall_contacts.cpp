// SPDX-License-Identifier: MIT
#include "world/wall_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dynamics/rigid_collision.hpp"
#include "dynamics/sphere_collision.hpp"
#include "math/event_time.hpp"
#include "narrow/time_of_contact.hpp"
#include "sparse/meeting.hpp"
#include "world/contact_band.hpp"
#include "world/phase_timer.hpp"
#include "world/support_polygon.hpp"

namespace sparsedyn {

void WallContacts::Handle(std::uint32_t i) {
  if (core_.bodies.IsPolyhedron(i)) {
    HandlePolyhedron(i);
  } else {
    HandleSphere(i);
  }
}

bool WallContacts::HoldAgainstWall(std::uint32_t i, int w, const Vec3& normal, const Vec3& v,
                                   double gap) {
  // Coming to rest: touching, moving to or from the wall slower than the collapse guard, and
  // pressed into it by gravity or thrust. Bounces would follow ever faster (the guard keeps
  // them elastic; below the time's resolution they would stall the clock), so the wall holds
  // the body instead: its velocity and acceleration into the wall become zero (the normal
  // force) until a collision with another body moves it.
  const ElementPaths& paths = core_.bodies.paths;
  const double radius = core_.bodies.materials.Radius(i);
  if (gap > core_.settings.contact_tolerance * radius) return false;
  const double approach = normal.dot(v);
  if (!(std::abs(approach) < core_.settings.elastic_below_speed) ||
      !(normal.dot(paths.accelerations().Free(i)) < 0.0)) {
    return false;
  }
  Hold hold = paths.accelerations().HoldOf(i);
  hold.walls = static_cast<std::uint8_t>(hold.walls | 1u << w);
  changes_.SetHeld(i, hold, v);
  ReportHold(i, w, gap, paths.PositionNow(i) - radius * normal, normal, approach);
  return true;
}

void WallContacts::ReportHold(std::uint32_t i, int w, double gap, const Vec3& point,
                              const Vec3& normal, double approach) {
  // A wall collision like any other (its segment comes with one), with the impulse that stops
  // the body's approach; then the body predicts along the wall.
  Statistics& stats = core_.observers.stats();
  core_.observers.NotePenetration(
      gap, core_.settings.contact_tolerance * core_.bodies.materials.Radius(i));
  ++stats.wall_holds;
  ++stats.wall_collisions;
  if (core_.observers.WantsCollisions()) {
    core_.observers.Collision(CollisionEvent{
        core_.Now(), core_.bodies.ids.IdOf(i), BodyId{}, w, point, -normal,
        std::max(-approach, 0.0) / core_.bodies.materials.InvMass(i)});
  }
  sparse_.PredictFull(i);
  detailed_.PredictEngagementsOf(i);
}

bool WallContacts::HoldPolyhedron(std::uint32_t i, int w, const Vec3& normal,
                                  const RigidPath& path, const ContactGeometry& contact) {
  // The end of a bounce series on a face (issue #37 part 1): three or more points on the wall
  // around the centre of mass, each moving to or from it slower than the collapse guard, and
  // the body pressed into the wall. Its velocity and acceleration into the wall become zero
  // and of its spin only the part about the normal stays (the rest would lift the face: what
  // the bounces were taking away), so it rests there, or slides and turns on the face, until
  // a collision moves it. Edges and vertices, and faces of other bodies, are issue #37.
  if (contact.points.size() < 3) return false;
  const ElementPaths& paths = core_.bodies.paths;
  if (!(normal.dot(paths.accelerations().Free(i)) < 0.0)) return false;
  const double now = paths.Now();
  for (const Vec3& x : contact.points) {
    if (!(std::abs(normal.dot(path.PointVelocity(x, now))) < core_.settings.elastic_below_speed)) {
      return false;
    }
  }
  if (!OverPolygon(contact.points, path.centre.PositionAt(now), normal)) return false;
  const Vec3 omega = normal.dot(path.omega) * normal;
  const Vec3 v = path.centre.VelocityAt(now);
  Hold hold = paths.accelerations().HoldOf(i);
  hold.walls = static_cast<std::uint8_t>(hold.walls | 1u << w);
  changes_.SetHeld(i, hold, v, omega);
  ReportHold(i, w, contact.distance, contact.points.front(), normal, normal.dot(v));
  return true;
}

void WallContacts::HandleSphere(std::uint32_t i) {
  const ElementPaths& paths = core_.bodies.paths;
  const BodyMaterials& materials = core_.bodies.materials;
  Statistics& stats = core_.observers.stats();
  const int w = sparse_.PredictionOf(i).aux;
  const WallPlane plane = BoxWall(core_.settings.container, w);
  const double now = paths.Now();
  const Vec3 p = paths.TruePositionAt(i, now);
  const Vec3 v = paths.TrueVelocityAt(i, now);
  const double radius = materials.Radius(i);
  const double gap = plane.normal.dot(p) - plane.offset - radius;
  const double approach = plane.normal.dot(v);
  if (HoldAgainstWall(i, w, plane.normal, v, gap)) return;
  if (gap > core_.settings.contact_tolerance * radius || approach >= 0) {
    if (gap > core_.settings.contact_tolerance * radius) ++stats.early_events;
    sparse_.PredictFull(i);
    return;
  }
  core_.observers.NotePenetration(gap, core_.settings.contact_tolerance * radius);
  double impulse = 0.0;
  bool guarded = false;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_response);
    if (core_.bodies.rigid.Tracked() && materials.Friction(i) > 0) {
      // A rubbing sphere: the rigid impulse at its contact point, with its spin and its own
      // friction coefficient (the wall has no material of its own).
      ContactGeometry contact;
      contact.normal = -plane.normal;
      contact.distance = gap;
      contact.points = {p - radius * plane.normal};
      RigidBodyState body{p, v, core_.bodies.rigid.Omega(i), materials.InvMass(i),
                          core_.bodies.InvInertiaWorld(i, Eigen::Quaterniond::Identity())};
      RigidBodyState wall;  // static: no mass to move
      wall.centre = contact.points.front();
      RigidImpulseOptions options;
      options.restitution = materials.Restitution(i);
      options.friction = materials.Friction(i);
      options.elastic_below_speed = core_.settings.elastic_below_speed;
      const RigidImpulseResult result = ApplyRigidImpulse(body, wall, contact, options);
      changes_.SetMotion(i, body.velocity, body.angular_velocity);
      impulse = result.normal_impulse;
      guarded = result.guarded;
    } else {
      // A static wall has infinite mass: the body's normal velocity is reversed and scaled by
      // e.
      const ImpulseResult result =
          SphereImpulse(v, Vec3::Zero(), materials.InvMass(i), 0.0, -plane.normal,
                        materials.Restitution(i), core_.settings.elastic_below_speed);
      changes_.SetVelocity(i, result.v_a);
      impulse = result.impulse;
      guarded = result.guarded;
    }
  }
  ++stats.wall_collisions;
  if (guarded) ++stats.collapse_guarded;
  if (core_.observers.WantsCollisions()) {
    core_.observers.Collision(CollisionEvent{now, core_.bodies.ids.IdOf(i), BodyId{}, w,
                                             p - radius * plane.normal, -plane.normal, impulse});
  }
  sparse_.PredictFull(i);
  detailed_.PredictEngagementsOf(i);
}

Event WallContacts::PredictDragPolyhedron(std::uint32_t i, Event event) {
  const BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  // The element (its envelope included) reaches a wall no later than the body; one that
  // overlaps a wall already may hold a body that touches it at any time.
  const Mover element = bodies.MoverOf(i, now);
  const double tolerance = core_.settings.contact_tolerance * bodies.materials.Radius(i);
  // No further than its check, which predicts again with a new segment.
  const double end = std::min(event.time, bodies.paths.drags().CheckTime(i));
  const std::uint8_t held = bodies.paths.accelerations().HeldBy(i);
  for (int w = 0; w < 6; ++w) {
    if ((held >> w & 1u) != 0) continue;  // it rests on that face
    const WallPlane plane = BoxWall(core_.settings.container, w);
    double begin = now;
    if (plane.normal.dot(element.p) - plane.offset > element.r0) {
      const double dt = PredictWallMeeting(element, plane.normal, plane.offset);
      if (dt == kInfinity) continue;
      begin = std::max(now, EventTime(now, dt));
    }
    if (band_skip_ && *band_skip_ == std::make_pair(i, w)) {
      // It has just touched this wall without approaching: not before the band could close.
      const RigidPath path = bodies.RigidPathNow(i);
      const double wait = BandExit(now, tolerance,
                                   path.centre.v0.norm() +
                                       path.omega.norm() * bodies.materials.Radius(i),
                                   bodies.AccelerationBound(i));
      begin = std::max(begin, FallBackCap(now, wait, plane.normal.dot(path.centre.v0),
                                          -plane.normal.dot(path.centre.a)));
    }
    const double limit = std::min(end, event.time);
    if (!(begin < limit)) continue;
    ++core_.observers.stats().detail_predictions;
    const double t = drag_.PolyhedronWallContact(i, plane, tolerance, begin, limit);
    // An unfinished search is an early wall event, which predicts again.
    if (t < limit) {
      event = Event{t, EventKind::kWallMeet, static_cast<std::uint8_t>(w), kNoIndex, 0};
    }
  }
  return event;
}

Event WallContacts::PredictPolyhedron(std::uint32_t i, Event event) {
  const BodyStore& bodies = core_.bodies;
  if (bodies.HasDrag(i)) return PredictDragPolyhedron(i, event);
  Statistics& stats = core_.observers.stats();
  const double now = bodies.paths.Now();
  const RigidPath path = bodies.RigidPathOf(i);
  const ConvexPolyhedron& polyhedron = *bodies.rigid.ShapeOf(i).polyhedron;
  const double radius = bodies.materials.Radius(i);
  const double tolerance = core_.settings.contact_tolerance * radius;
  const Pose pose = path.PoseAt(now);
  const Vec3 centre = pose.translation;
  const Vec3 velocity = path.centre.VelocityAt(now);
  const std::uint8_t held = bodies.paths.accelerations().HeldBy(i);
  for (int w = 0; w < 6; ++w) {
    if ((held >> w & 1u) != 0) continue;  // it rests on that face, turning about its normal
    const WallPlane plane = BoxWall(core_.settings.container, w);
    // The polyhedron cannot reach a wall before its bounding sphere does.
    double begin = now;
    const double clearance = plane.normal.dot(centre) - plane.offset - radius;
    if (clearance > 0) {
      // Most walls are out of reach before the body's next event: the sphere's gap to the wall
      // is clearance + (n . v) dt + (n . a) dt^2 / 2, so only its closing parts can consume the
      // clearance (with a margin for round-off).
      const double closing_speed = std::min(plane.normal.dot(velocity), 0.0);
      const double closing_accel = std::min(plane.normal.dot(path.centre.a), 0.0);
      if (closing_speed == 0.0 && closing_accel == 0.0) continue;
      const double h = event.time - now;
      if (h < kInfinity &&
          -(closing_speed + 0.5 * closing_accel * h) * h * (1.0 + 1e-9) < clearance) {
        continue;
      }
      const double dt = PredictWallMeeting(bodies.BodyMoverOf(i, now), plane.normal, plane.offset);
      if (dt == kInfinity) continue;
      begin = EventTime(now, dt);
    }
    if (begin >= event.time) continue;
    if (begin == now) {
      // Touching the wall now: a contact if some vertex in the band approaches, else (it has
      // just bounced) the wall waits until the band could have been closed.
      const Vec3 n_B = pose.rotation.conjugate() * plane.normal;
      const int nearest = bodies.rigid.ShapeOf(i).tracked->SupportVertex(-n_B);
      const double gap = plane.normal.dot(pose.ToWorld(polyhedron.vertex(nearest))) - plane.offset;
      if (gap <= tolerance) {
        bool approaching = false;
        const bool skip = band_skip_ && *band_skip_ == std::make_pair(i, w);
        for (int v = 0; v < polyhedron.vertex_count() && !skip && !approaching; ++v) {
          const Vec3 x = pose.ToWorld(polyhedron.vertex(v));
          approaching = plane.normal.dot(x) - plane.offset <= gap + tolerance &&
                        plane.normal.dot(path.PointVelocity(x, now)) < 0;
        }
        if (approaching) {
          event = Event{now, EventKind::kWallMeet, static_cast<std::uint8_t>(w), kNoIndex, 0};
          continue;
        }
        const GapClosing closing = PlaneGapClosing(plane.normal, path.centre.VelocityAt(now),
                                                   path.centre.a, path.omega, radius);
        begin = BandExit(now, tolerance, closing.speed, closing.acceleration);
        const Vec3 lowest = pose.ToWorld(polyhedron.vertex(nearest));
        begin = FallBackCap(now, begin, plane.normal.dot(path.PointVelocity(lowest, now)),
                            -plane.normal.dot(path.centre.a));
        if (begin >= event.time) continue;
      }
    }
    ++stats.detail_predictions;
    const WallContactPrediction p = PredictWallContact(
        *bodies.rigid.ShapeOf(i).tracked, path, plane.normal, plane.offset, begin, event.time,
        tolerance, kIterationsPerPrediction, bodies.rigid.SpinRadius(i));
    stats.detail_iterations += static_cast<std::uint64_t>(p.iterations);
    if (p.kind != ContactPrediction::Kind::kNone && p.time < event.time) {
      if (p.kind == ContactPrediction::Kind::kCheckpoint) ++stats.detail_checkpoints;
      event = Event{std::max(now, p.time), EventKind::kWallMeet, static_cast<std::uint8_t>(w),
                    kNoIndex, 0};
    }
  }
  return event;
}

void WallContacts::HandlePolyhedron(std::uint32_t i) {
  const BodyStore& bodies = core_.bodies;
  Statistics& stats = core_.observers.stats();
  const double now = bodies.paths.Now();
  const int w = sparse_.PredictionOf(i).aux;
  const WallPlane plane = BoxWall(core_.settings.container, w);
  const RigidPath path = bodies.RigidPathNow(i);
  const Pose pose = path.PoseAt(now);
  const ConvexPolyhedron& polyhedron = *bodies.rigid.ShapeOf(i).polyhedron;
  const double tolerance = core_.settings.contact_tolerance * bodies.materials.Radius(i);
  std::vector<double> gaps(static_cast<std::size_t>(polyhedron.vertex_count()));
  double nearest = kInfinity;
  for (int v = 0; v < polyhedron.vertex_count(); ++v) {
    gaps[v] = plane.normal.dot(pose.ToWorld(polyhedron.vertex(v))) - plane.offset;
    nearest = std::min(nearest, gaps[v]);
  }
  if (nearest > tolerance) {
    // A checkpoint of the wall prediction, or predicted early (conservative): look again.
    ++stats.early_events;
    sparse_.PredictFull(i);
    return;
  }
  // The contact: every vertex within the band (a vertex, an edge or a face on the wall), in
  // order around their mean so that a face's vertices form its polygon.
  ContactGeometry contact;
  contact.normal = -plane.normal;  // from the body towards the wall
  contact.distance = nearest;
  for (int v = 0; v < polyhedron.vertex_count(); ++v) {
    if (gaps[v] <= nearest + tolerance) contact.points.push_back(pose.ToWorld(polyhedron.vertex(v)));
  }
  OrderAroundMean(contact.points, plane.normal);
  if (HoldPolyhedron(i, w, plane.normal, path, contact)) return;
  RigidImpulseResult result;
  {
    const PhaseTimer timer(core_.settings.profile_phases, stats.seconds_response);
    RigidBodyState body{pose.translation, path.centre.VelocityAt(now), bodies.rigid.Omega(i),
                        bodies.materials.InvMass(i), bodies.InvInertiaWorld(i, pose.rotation)};
    RigidBodyState wall;  // static: no mass to move
    wall.centre = contact.points.front();
    RigidImpulseOptions options;
    options.restitution = bodies.materials.Restitution(i);
    options.friction = bodies.materials.Friction(i);
    options.elastic_below_speed = core_.settings.elastic_below_speed;
    result = ApplyRigidImpulse(body, wall, contact, options);
    // An impulse (a side wall met while resting on the floor) may tip it: no wall holds it
    // then, until it comes to rest again.
    if (result.rounds > 0) changes_.SetCollidedMotion(i, body.velocity, body.angular_velocity);
  }
  if (result.rounds == 0) {
    // Touching without approaching: predict again with this wall held off for the band time.
    band_skip_ = std::make_pair(i, w);
    sparse_.PredictFull(i);
    band_skip_.reset();
    return;
  }
  core_.observers.NotePenetration(nearest, tolerance);
  ++stats.wall_collisions;
  if (result.guarded) ++stats.collapse_guarded;
  if (core_.observers.WantsCollisions()) {
    core_.observers.Collision(CollisionEvent{now, bodies.ids.IdOf(i), BodyId{}, w, result.point,
                                             contact.normal, result.normal_impulse});
  }
  sparse_.PredictFull(i);
  detailed_.PredictEngagementsOf(i);
}

}  // namespace sparsedyn
