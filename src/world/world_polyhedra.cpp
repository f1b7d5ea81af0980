// SPDX-License-Identifier: MIT
// The detailed phase for polyhedra (§3.3, §5.2, §6): engaged pairs are watched by closest-feature
// tracking and contact prediction, a contact gets the rigid impulse, and the walls are met by
// the polyhedron itself rather than by its sphere.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "dynamics/rigid_collision.hpp"
#include "narrow/advancement.hpp"
#include "world/world_impl.hpp"

namespace sparsedyn {
namespace {

// Zone events or advancement steps per contact prediction before it is resumed by a checkpoint
// event: bounds the work of one event, and a prediction interrupted by a path change is not
// wasted beyond this.
constexpr int kIterationsPerPrediction = 64;

// The time after `now` at which a pair (or a body and a wall) that touches within `tolerance`
// without approaching is looked at again: the band cannot be closed before, since the gap
// changes at most by max_speed (plus the relative acceleration's share) per second. This is what
// keeps a pair that has just bounced from colliding again at once, without missing a contact.
double BandExit(double now, double tolerance, double max_speed, double max_acceleration) {
  double dt = kInfinity;
  if (max_speed > 0) dt = 0.5 * tolerance / max_speed;
  if (max_acceleration > 0) dt = std::min(dt, std::sqrt(tolerance / max_acceleration));
  if (dt == kInfinity) return kInfinity;
  return std::max(now + dt, std::nextafter(now, kInfinity));
}

}  // namespace

Result<std::uint32_t> World::Impl::AddShape(const std::shared_ptr<const ConvexPolyhedron>& shape) {
  const auto found = shape_index_.find(shape.get());
  if (found != shape_index_.end()) return found->second;
  Shape s;
  s.given = shape;
  s.polyhedron = shape;
  if (shape->centroid().norm() > 1e-12 * shape->scale()) {
    s.polyhedron = std::make_shared<const ConvexPolyhedron>(shape->Recentered());
  }
  s.tracked = std::make_shared<const TrackedPolyhedron>(s.polyhedron);
  const Eigen::Matrix3d unit = s.polyhedron->inertia() / s.polyhedron->volume();
  s.unit_inertia = settings_.rotation_model == RotationModel::kSphericalTop
                       ? Eigen::Matrix3d((unit.trace() / 3.0) * Eigen::Matrix3d::Identity())
                       : unit;
  s.unit_inv_inertia = s.unit_inertia.inverse();
  if (!s.unit_inv_inertia.allFinite() || s.unit_inertia.determinant() <= 0) {
    return Error{"shape: its inertia tensor is singular (a degenerate polyhedron)"};
  }
  const auto index = static_cast<std::uint32_t>(shapes_.size());
  shapes_.push_back(std::move(s));
  shape_index_.emplace(shape.get(), index);
  return index;
}

std::optional<std::uint32_t> World::Impl::FindPolyhedronOverlap(const BodyDef& def,
                                                                std::uint32_t shape,
                                                                double& distance) const {
  // Before the start (polyhedra are only added then) index j is the body's public index and
  // its path start is where it was added.
  const TrackedPolyhedron& tracked = *shapes_[shape].tracked;
  const double radius = shapes_[shape].polyhedron->bounding_radius();
  const Pose pose{def.orientation.normalized(), def.position};
  std::optional<std::uint32_t> found;
  overlap_index_.ForEachNear(def.position, radius, [&](std::uint32_t j, const Vec3& q, double r) {
    const Vec3 d = MinimumImage(q - def.position);
    if (d.squaredNorm() >= (radius + r) * (radius + r)) return;
    const Pose other{q0_[j], def.position + d};
    const ClosestFeatures features =
        FindClosestFeatures(tracked, pose, *shapes_[shape_[j]].tracked, other);
    if (features.distance <= settings_.contact_tolerance * (radius + r) &&
        (!found || j < *found)) {
      found = j;
      distance = features.distance;
    }
  });
  return found;
}

double World::Impl::SpinRadiusOf(std::uint32_t i) const {
  return narrow::SpinRadius(*ShapeOf(i).polyhedron, RigidPathOf(i));
}

Vec3 World::Impl::PairShift(std::uint32_t a, std::uint32_t b) const {
  const Vec3 d = PathOf(b).PositionAt(now_) - PathOf(a).PositionAt(now_);
  return MinimumImage(d) - d;
}

double World::Impl::PairTolerance(std::uint32_t a, std::uint32_t b) const {
  return settings_.contact_tolerance * (Radius(a) + Radius(b));
}

ClosestFeatures World::Impl::PairFeatures(std::uint32_t a, std::uint32_t b, const Vec3& shift,
                                          std::optional<FeaturePair> warm) const {
  Pose pose_b = RigidPathOf(b).PoseAt(now_);
  pose_b.translation += shift;
  return FindClosestFeatures(*ShapeOf(a).tracked, RigidPathOf(a).PoseAt(now_),
                             *ShapeOf(b).tracked, pose_b, warm);
}

void World::Impl::EngageOverlappingAtStart() {
  const auto n = static_cast<std::uint32_t>(starts_.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    auto engage = [&](std::uint32_t j, const Vec3&) {
      if (j <= i || engagements_.Engaged(i, j)) return;
      const Vec3 d = MinimumImage(starts_[j].p0 - starts_[i].p0);
      const double reach = Radius(i) + Radius(j);
      if (d.squaredNorm() >= reach * reach) return;
      const std::uint32_t k = engagements_.Add(i, j);
      ++stats_.engagements_started;
      PredictPolyhedralEngagement(k);
    };
    if (grid_) {
      grid_->ForEachNeighbor(i, engage);
    } else {
      all_pairs_->ForEachNeighbor(i, engage);
    }
  }
}

void World::Impl::PredictPolyhedralEngagement(std::uint32_t k) {
  const PhaseTimer timer(settings_.profile_phases, stats_.seconds_detailed);
  Engagements::Engagement& e = engagements_[k];
  const Vec3 shift = PairShift(e.a, e.b);
  RigidPath path_a = RigidPathOf(e.a);
  RigidPath path_b = RigidPathOf(e.b);
  path_b.centre.p0 += shift;
  // The engagement lasts while the element spheres overlap.
  const double separation =
      EventTime(now_, PredictSeparation(MoverOf(e.a, now_), MoverOf(e.b, now_), shift));
  const double tolerance = PairTolerance(e.a, e.b);
  const std::optional<FeaturePair> warm =
      e.has_features ? std::optional<FeaturePair>(e.features) : std::nullopt;
  const ClosestFeatures current = PairFeatures(e.a, e.b, shift, warm);
  if (current.status == ClosestFeatures::Status::kIterationCap) ++stats_.walk_cap_hits;
  e.features = current.features;
  e.has_features = true;
  e.contact_next = false;
  e.checkpoint = false;
  double time = separation;
  if (current.distance <= tolerance) {
    // Touching now: the contact handler decides whether any point approaches.
    e.contact_next = true;
    time = now_;
  } else {
    ++stats_.detail_predictions;
    ContactPredictionOptions options;
    options.tolerance = tolerance;
    options.max_iterations = kIterationsPerPrediction;
    options.spin_radius_a = spin_radius_[e.a];
    options.spin_radius_b = spin_radius_[e.b];
    const ContactPrediction p = PredictContact(*ShapeOf(e.a).tracked, path_a, *ShapeOf(e.b).tracked,
                                               path_b, now_, separation, e.features, options);
    stats_.detail_iterations += static_cast<std::uint64_t>(p.iterations);
    if (p.kind != ContactPrediction::Kind::kNone && p.time <= separation) {
      e.contact_next = p.kind == ContactPrediction::Kind::kContact;
      e.checkpoint = !e.contact_next;
      if (e.checkpoint) ++stats_.detail_checkpoints;
      e.features = p.features.features;
      time = std::max(now_, p.time);
    }
  }
  if (time == kInfinity) {
    engagement_queue_.Erase(k);
  } else {
    engagement_queue_.Set(k, time, EventKind::kEngagement);
  }
}

void World::Impl::HandlePolyhedralEngagement(std::uint32_t k) {
  Engagements::Engagement& e = engagements_[k];
  if (e.checkpoint) {
    PredictPolyhedralEngagement(k);
    return;
  }
  if (!e.contact_next) {
    // The element spheres separate: the engagement ends and a looks for its next meeting
    // (which may be with b again).
    const std::uint32_t a = e.a;
    engagement_queue_.Erase(k);
    engagements_.Remove(k);
    ++stats_.engagements_ended;
    PredictFull(a);
    return;
  }
  const Vec3 shift = PairShift(e.a, e.b);
  ClosestFeatures features;
  {
    const PhaseTimer timer(settings_.profile_phases, stats_.seconds_detailed);
    features = PairFeatures(e.a, e.b, shift, e.features);
  }
  e.features = features.features;
  const double tolerance = PairTolerance(e.a, e.b);
  if (features.distance > tolerance) {
    ++stats_.early_events;
    PredictPolyhedralEngagement(k);
    return;
  }
  if (CollidePolyhedra(e.a, e.b, features, shift)) return;
  // Touching, but no point approaches (they have just bounced, or slide past each other):
  // look again once the tolerance band could have been closed.
  const RigidPath a = RigidPathOf(e.a);
  const RigidPath b = RigidPathOf(e.b);
  const double speed = (b.centre.VelocityAt(now_) - a.centre.VelocityAt(now_)).norm() +
                       a.omega.norm() * Radius(e.a) + b.omega.norm() * Radius(e.b);
  const double acceleration = (b.centre.a - a.centre.a).norm();
  const double separation =
      EventTime(now_, PredictSeparation(MoverOf(e.a, now_), MoverOf(e.b, now_), shift));
  const double again = BandExit(now_, tolerance, speed, acceleration);
  e.contact_next = false;
  e.checkpoint = again < separation;
  const double time = std::min(again, separation);
  if (time == kInfinity) {
    engagement_queue_.Erase(k);
  } else {
    engagement_queue_.Set(k, time, EventKind::kEngagement);
  }
}

void World::Impl::SetMotion(std::uint32_t i, const Vec3& v, const Vec3& omega) {
  const RigidPath path = RigidPathOf(i);
  q0_[i] = path.OrientationAt(now_).normalized();
  omega_[i] = omega;
  spin_radius_[i] = SpinRadiusOf(i);
  SetStart(i, PathStart{path.centre.PositionAt(now_), v, now_});
  ++PredictionOf(i).version;
  if (on_segment_) {
    MotionSegment segment{
        now_, PublicId(i), starts_[i].p0, v, path.centre.a, PredictionOf(i).version};
    segment.orientation = q0_[i];
    segment.angular_velocity = omega;
    on_segment_(segment);
  }
}

bool World::Impl::CollidePolyhedra(std::uint32_t a, std::uint32_t b,
                                   const ClosestFeatures& features, const Vec3& shift) {
  RigidImpulseResult result;
  ContactGeometry contact;
  {
    const PhaseTimer timer(settings_.profile_phases, stats_.seconds_response);
    const RigidPath path_a = RigidPathOf(a);
    RigidPath path_b = RigidPathOf(b);
    path_b.centre.p0 += shift;
    const Pose pose_a = path_a.PoseAt(now_);
    const Pose pose_b = path_b.PoseAt(now_);
    contact = ContactFromFeatures(*ShapeOf(a).polyhedron, pose_a, *ShapeOf(b).polyhedron, pose_b,
                                  features, PairTolerance(a, b));
    RigidBodyState body_a{pose_a.translation, path_a.centre.VelocityAt(now_), omega_[a],
                          InvMass(a), InvInertiaWorld(a, pose_a.rotation)};
    RigidBodyState body_b{pose_b.translation, path_b.centre.VelocityAt(now_), omega_[b],
                          InvMass(b), InvInertiaWorld(b, pose_b.rotation)};
    RigidImpulseOptions options;
    options.restitution = Restitution(a) * Restitution(b);
    options.friction = std::sqrt(Friction(a) * Friction(b));
    options.elastic_below_speed = settings_.elastic_below_speed;
    result = ApplyRigidImpulse(body_a, body_b, contact, options);
    if (result.rounds == 0) return false;
    SetMotion(a, body_a.velocity, body_a.angular_velocity);
    SetMotion(b, body_b.velocity, body_b.angular_velocity);
  }
  NotePenetration(contact.distance);
  ++stats_.collisions;
  if (result.guarded) ++stats_.collapse_guarded;
  if (on_collision_) {
    on_collision_(CollisionEvent{now_, PublicId(a), PublicId(b), -1, result.point, contact.normal,
                                 result.normal_impulse});
  }
  // Both bodies' element predictions are superseded (actor-absent, §4.2), replaced in place.
  for (const std::uint32_t body : {a, b}) {
    if (PredictionOf(body).kind != EventKind::kNone) ++stats_.stale_actor_absent;
  }
  PredictFull(a);
  PredictFull(b);
  PredictEngagementsOf(a);
  PredictEngagementsOf(b, /*done_partner=*/a);
  return true;
}

Event World::Impl::PredictPolyhedronWalls(std::uint32_t i, Event event) {
  const RigidPath path = RigidPathOf(i);
  const ConvexPolyhedron& polyhedron = *ShapeOf(i).polyhedron;
  const double radius = Radius(i);
  const double tolerance = settings_.contact_tolerance * radius;
  const Pose pose = path.PoseAt(now_);
  const Vec3 centre = pose.translation;
  const Vec3 velocity = path.centre.VelocityAt(now_);
  for (int w = 0; w < 6; ++w) {
    const WallPlane plane = BoxWall(settings_.container, w);
    // The polyhedron cannot reach a wall before its bounding sphere does.
    double begin = now_;
    const double clearance = plane.normal.dot(centre) - plane.offset - radius;
    if (clearance > 0) {
      // Most walls are out of reach before the body's next event: the sphere's gap to the wall
      // is clearance + (n . v) dt + (n . a) dt^2 / 2, so only its closing parts can consume the
      // clearance (with a margin for round-off).
      const double closing_speed = std::min(plane.normal.dot(velocity), 0.0);
      const double closing_accel = std::min(plane.normal.dot(path.centre.a), 0.0);
      if (closing_speed == 0.0 && closing_accel == 0.0) continue;
      const double h = event.time - now_;
      if (h < kInfinity &&
          -(closing_speed + 0.5 * closing_accel * h) * h * (1.0 + 1e-9) < clearance) {
        continue;
      }
      const double dt = PredictWallMeeting(BodyMoverOf(i, now_), plane.normal, plane.offset);
      if (dt == kInfinity) continue;
      begin = EventTime(now_, dt);
    }
    if (begin >= event.time) continue;
    if (begin == now_) {
      // Touching the wall now: a contact if some vertex in the band approaches, else (it has
      // just bounced) the wall waits until the band could have been closed.
      const Vec3 n_B = pose.rotation.conjugate() * plane.normal;
      const int nearest = ShapeOf(i).tracked->SupportVertex(-n_B);
      const double gap = plane.normal.dot(pose.ToWorld(polyhedron.vertex(nearest))) - plane.offset;
      if (gap <= tolerance) {
        bool approaching = false;
        const bool skip = wall_band_skip_ && *wall_band_skip_ == std::make_pair(i, w);
        for (int v = 0; v < polyhedron.vertex_count() && !skip && !approaching; ++v) {
          const Vec3 x = pose.ToWorld(polyhedron.vertex(v));
          approaching = plane.normal.dot(x) - plane.offset <= gap + tolerance &&
                        plane.normal.dot(path.PointVelocity(x, now_)) < 0;
        }
        if (approaching) {
          event = Event{now_, EventKind::kWallMeet, static_cast<std::uint8_t>(w), kNoIndex, 0};
          continue;
        }
        begin = BandExit(now_, tolerance, path.centre.VelocityAt(now_).norm() +
                                              path.omega.norm() * radius,
                         path.centre.a.norm());
        if (begin >= event.time) continue;
      }
    }
    ++stats_.detail_predictions;
    const WallContactPrediction p =
        PredictWallContact(*ShapeOf(i).tracked, path, plane.normal, plane.offset, begin, event.time,
                           tolerance, kIterationsPerPrediction, spin_radius_[i]);
    stats_.detail_iterations += static_cast<std::uint64_t>(p.iterations);
    if (p.kind != ContactPrediction::Kind::kNone && p.time < event.time) {
      if (p.kind == ContactPrediction::Kind::kCheckpoint) ++stats_.detail_checkpoints;
      event = Event{std::max(now_, p.time), EventKind::kWallMeet, static_cast<std::uint8_t>(w),
                    kNoIndex, 0};
    }
  }
  return event;
}

void World::Impl::HandlePolyhedronWall(std::uint32_t i) {
  const int w = PredictionOf(i).aux;
  const WallPlane plane = BoxWall(settings_.container, w);
  const RigidPath path = RigidPathOf(i);
  const Pose pose = path.PoseAt(now_);
  const ConvexPolyhedron& polyhedron = *ShapeOf(i).polyhedron;
  const double tolerance = settings_.contact_tolerance * Radius(i);
  std::vector<double> gaps(static_cast<std::size_t>(polyhedron.vertex_count()));
  double nearest = kInfinity;
  for (int v = 0; v < polyhedron.vertex_count(); ++v) {
    gaps[v] = plane.normal.dot(pose.ToWorld(polyhedron.vertex(v))) - plane.offset;
    nearest = std::min(nearest, gaps[v]);
  }
  if (nearest > tolerance) {
    // A checkpoint of the wall prediction, or predicted early (conservative): look again.
    ++stats_.early_events;
    PredictFull(i);
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
  if (contact.points.size() > 2) {
    const Vec3 mean = std::accumulate(contact.points.begin(), contact.points.end(),
                                      Vec3(Vec3::Zero())) / static_cast<double>(contact.points.size());
    const Vec3 u = plane.normal.unitOrthogonal();
    const Vec3 v = plane.normal.cross(u);
    std::sort(contact.points.begin(), contact.points.end(), [&](const Vec3& p, const Vec3& q) {
      return std::atan2((p - mean).dot(v), (p - mean).dot(u)) <
             std::atan2((q - mean).dot(v), (q - mean).dot(u));
    });
  }
  RigidImpulseResult result;
  {
    const PhaseTimer timer(settings_.profile_phases, stats_.seconds_response);
    RigidBodyState body{pose.translation, path.centre.VelocityAt(now_), omega_[i], InvMass(i),
                        InvInertiaWorld(i, pose.rotation)};
    RigidBodyState wall;  // static: no mass to move
    wall.centre = contact.points.front();
    RigidImpulseOptions options;
    options.restitution = Restitution(i);
    options.friction = Friction(i);
    options.elastic_below_speed = settings_.elastic_below_speed;
    result = ApplyRigidImpulse(body, wall, contact, options);
    if (result.rounds > 0) SetMotion(i, body.velocity, body.angular_velocity);
  }
  if (result.rounds == 0) {
    // Touching without approaching: predict again with this wall held off for the band time.
    wall_band_skip_ = std::make_pair(i, w);
    PredictFull(i);
    wall_band_skip_.reset();
    return;
  }
  NotePenetration(nearest);
  ++stats_.wall_collisions;
  if (result.guarded) ++stats_.collapse_guarded;
  if (on_collision_) {
    on_collision_(CollisionEvent{now_, PublicId(i), BodyId{}, w, result.point, contact.normal,
                                 result.normal_impulse});
  }
  PredictFull(i);
  PredictEngagementsOf(i);
}

Status World::Impl::ValidatePolyhedra() const {
  const auto n = static_cast<std::uint32_t>(starts_.size());
  auto format = [](double x) {
    std::ostringstream out;
    out.precision(17);
    out << x;
    return out.str();
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = i + 1; j < n; ++j) {
      const Vec3 shift = PairShift(i, j);
      const Vec3 d = PathOf(j).PositionAt(now_) + shift - PathOf(i).PositionAt(now_);
      const double reach = Radius(i) + Radius(j);
      if (d.squaredNorm() >= reach * reach) continue;
      const ClosestFeatures f = PairFeatures(i, j, shift, std::nullopt);
      if (f.distance < -PairTolerance(i, j)) {
        return Error{"bodies " + std::to_string(public_of_[i]) + " and " +
                     std::to_string(public_of_[j]) + " interpenetrate by " + format(-f.distance) +
                     " at t = " + format(now_)};
      }
    }
    if (settings_.container.kind != Container::Kind::kWalledBox) continue;
    const Pose pose = RigidPathOf(i).PoseAt(now_);
    const ConvexPolyhedron& polyhedron = *ShapeOf(i).polyhedron;
    for (int w = 0; w < 6; ++w) {
      const WallPlane plane = BoxWall(settings_.container, w);
      const Vec3 n_B = pose.rotation.conjugate() * plane.normal;
      const double gap =
          plane.normal.dot(pose.ToWorld(polyhedron.vertex(polyhedron.SupportVertex(-n_B)))) -
          plane.offset;
      if (gap < -settings_.contact_tolerance * Radius(i)) {
        return Error{"body " + std::to_string(public_of_[i]) + " is " + format(-gap) +
                     " beyond wall " + std::to_string(w) + " at t = " + format(now_)};
      }
    }
  }
  return Status::Ok();
}

}  // namespace sparsedyn
