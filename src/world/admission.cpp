// SPDX-License-Identifier: MIT
#include "world/admission.hpp"

#include <algorithm>
#include <cmath>

#include "base/format.hpp"
#include "narrow/point_features.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "dynamics/god_plan.hpp"
#include "world/body_checks.hpp"
#include "world/hostile_values.hpp"
#include "world/solid_gap.hpp"

namespace sparsedyn {

std::optional<Error> CheckSchedule(const std::vector<ThrustChange>& schedule, double now,
                                   const std::string& body) {
  for (std::size_t k = 0; k < schedule.size(); ++k) {
    const std::string at = body + "thrust_schedule[" + std::to_string(k) + "]: ";
    const ThrustChange& change = schedule[k];
    if (!std::isfinite(change.time) || !change.thrust.allFinite()) {
      return Error{at + "time and thrust must be finite"};
    }
    if (change.time < now) {
      return Error{at + "time " + FormatExact(change.time) + " is before the World's clock (" +
                   FormatExact(now) + ")"};
    }
    if (k > 0 && !(change.time > schedule[k - 1].time)) {
      return Error{at + "time " + FormatExact(change.time) +
                   " must be later than the change before it (" +
                   FormatExact(schedule[k - 1].time) + ")"};
    }
  }
  return std::nullopt;
}

Result<Admission::Accepted> Admission::Check(const BodyDef& def, std::uint32_t slot,
                                             bool started) const {
  if (std::optional<Error> error = CheckBodyValues(def, slot)) return *error;
  if (std::optional<Error> error = CheckHostileValues(def, core_.settings, slot)) return *error;
  const std::string body = "body " + std::to_string(slot) + ": ";
  const bool polyhedron = def.shape != nullptr;
  if (def.is_static) {
    if (std::optional<Error> error = CheckStatic(def, body)) return *error;
  }
  if (def.god) {
    if (std::optional<Error> error = CheckGod(def, body)) return *error;
  }
  if (polyhedron && !def.envelope.IsZero()) {
    return Error{body + "envelopes are for spheres; a polyhedron's path is exact"};
  }
  if (std::optional<Error> error = CheckDragCombination(def, body)) return *error;
  if (std::optional<Error> error = CheckSchedule(def.thrust_schedule, core_.Now(), body)) {
    return *error;
  }
  Accepted accepted;
  const BodyShape* shape = nullptr;
  if (polyhedron) {
    // Shapes are shared: built once, and added to the World's shapes only with the body.
    const ShapeTable& shapes = core_.bodies.rigid.shapes();
    if (std::optional<std::uint32_t> found = shapes.Find(def.shape.get())) {
      accepted.shape = *found;
      shape = &shapes[*found];
    } else {
      Result<BodyShape> built = shapes.Build(def.shape);
      if (!built) return Error{body + built.error().message};
      accepted.new_shape = std::move(*built);
      shape = &*accepted.new_shape;
    }
  }
  // A polyhedron's element sphere is its bounding sphere about the centroid.
  accepted.radius = polyhedron ? shape->polyhedron->bounding_radius() : def.radius;
  const Placement placement{def.position, def.orientation.normalized(), shape, accepted.radius,
                            def.is_static, def.god.has_value()};
  // A static body may reach beyond a walled box's walls (a floor wider than the room): only
  // moving bodies are kept inside.
  if (!def.is_static) {
    if (std::optional<Error> error = CheckInside(placement, body)) return *error;
  }
  if (std::optional<Error> error = CheckApart(placement, kNoIndex, started, body)) return *error;
  if (std::optional<Error> error = CheckApartFromStatics(placement, body)) return *error;
  return accepted;
}

std::optional<Error> Admission::CheckDragCombination(const BodyDef& def,
                                                     const std::string& body) const {
  // Drag's contacts are predicted on true motions for every pair kind (docs/dynamics.md,
  // "Drag in the World"); a god object's track drives it, and an envelope of its own would
  // stack on the drag segment's.
  if (def.god && def.drag && !def.drag->IsZero()) {
    return Error{body + "drag on a god object is not supported (its track drives it)"};
  }
  if (!DragOf(def, core_.settings.drag).IsZero()) {
    const std::string at = body + "drag ";
    if (!def.envelope.IsZero()) return Error{at + "and an envelope together are not supported"};
    if (core_.settings.contact_tolerance < kMinDragContactTolerance) {
      // The message's 1e-12 is kMinDragContactTolerance.
      return Error{at + "needs settings.contact_tolerance >= 1e-12, got " +
                   FormatExact(core_.settings.contact_tolerance)};
    }
  }
  return std::nullopt;
}

std::optional<Error> Admission::CheckStatic(const BodyDef& def, const std::string& body) const {
  const std::string at = body + "a static body ";
  if (core_.periodic) return Error{at + "cannot be in a periodic box (not supported)"};
  if (!def.velocity.isZero(0.0)) return Error{at + "has no velocity (give zero)"};
  if (!def.angular_velocity.isZero(0.0)) return Error{at + "has no angular_velocity (give zero)"};
  if (!def.thrust.isZero(0.0) || !def.thrust_schedule.empty()) {
    return Error{at + "has no thrust or thrust_schedule"};
  }
  if (!def.envelope.IsZero()) return Error{at + "has no envelope"};
  if (def.drag && !def.drag->IsZero()) return Error{at + "has no drag (it never moves)"};
  return std::nullopt;
}

std::optional<Error> Admission::CheckGodTrack(const GodDef& god, const std::string& body) const {
  const std::string at = body + "god.";
  if (Status track = ValidateGodTrack(god.track, god.max_acceleration); !track) {
    return Error{at + track.error().message};
  }
  if (!god.track.empty() && god.track.front().time < core_.Now()) {
    return Error{at + "track[0].time " + FormatExact(god.track.front().time) +
                 " is before the World's clock (" + FormatExact(core_.Now()) + ")"};
  }
  // Beyond 1e100 a plan's squares overflow (as hostile_values.hpp refuses for other values).
  const auto absurd = [](const Vec3& v) { return v.cwiseAbs().maxCoeff() > 1e100; };
  if (god.max_acceleration > 1e100) return Error{at + "max_acceleration is beyond 1e100"};
  for (std::size_t k = 0; k < god.track.size(); ++k) {
    const GodTarget& target = god.track[k];
    if (std::abs(target.time) > 1e100 || absurd(target.position) ||
        (target.velocity && absurd(*target.velocity))) {
      return Error{at + "track[" + std::to_string(k) + "] has a magnitude beyond 1e100"};
    }
  }
  return std::nullopt;
}

std::optional<Error> Admission::CheckGod(const BodyDef& def, const std::string& body) const {
  if (std::optional<Error> error = CheckGodTrack(*def.god, body)) return error;
  const std::string what = body + "a god object ";
  if (def.is_static) return Error{what + "cannot be static (it moves as it is driven)"};
  if (core_.periodic) return Error{what + "cannot be in a periodic box (not supported)"};
  if (!def.angular_velocity.isZero(0.0)) return Error{what + "has no angular_velocity (give zero)"};
  if (!def.thrust.isZero(0.0) || !def.thrust_schedule.empty()) {
    return Error{what + "has no thrust or thrust_schedule (its track drives it)"};
  }
  if (!def.envelope.IsZero()) return Error{what + "has no envelope (its path is exact)"};
  return std::nullopt;
}

std::optional<Error> Admission::CheckApartFromStatics(const Placement& placement,
                                                      const std::string& body) const {
  const StaticBodies& statics = core_.bodies.statics;
  if (statics.Empty() || placement.is_god) return std::nullopt;
  const Solid solid{placement.shape, placement.radius,
                    Pose{placement.orientation, placement.position}};
  const Aabb box = placement.shape != nullptr
                       ? BoxOfPolyhedron(*placement.shape->polyhedron, solid.pose)
                       : BoxOfSphere(placement.position, placement.radius);
  std::optional<Error> error;
  statics.tree().ForEachOverlapping(box, [&](std::uint32_t s) {
    if (error) return;
    const StaticBodies::Static& st = statics[s];
    const BodyShape* shape = st.shape == kNoIndex ? nullptr : &core_.bodies.rigid.shapes()[st.shape];
    const double gap = SolidGap(solid, Solid{shape, st.radius, st.pose});
    const double allowed = core_.settings.contact_tolerance *
                           (placement.radius + std::min(placement.radius, st.radius));
    if (gap < -allowed) {
      error = Error{body + "overlaps static body " + std::to_string(st.slot) + " by " +
                    FormatExact(-gap) + " at t = " + FormatExact(core_.Now())};
    }
  });
  return error;
}

Status Admission::CheckPose(std::uint32_t i, std::uint32_t slot, const Vec3& position,
                            const Eigen::Quaterniond& orientation, bool started) const {
  const std::string body = "body " + std::to_string(slot) + ": ";
  if (!position.allFinite()) return Error{body + "position must be finite"};
  const Eigen::Vector4d q = orientation.coeffs();
  if (!q.allFinite() || std::abs(q.norm() - 1.0) > 1e-6) {
    return Error{body + "orientation must be a finite unit quaternion, got norm " +
                 FormatExact(q.norm())};
  }
  const BodyStore& bodies = core_.bodies;
  const BodyShape* shape = bodies.IsPolyhedron(i) ? &bodies.rigid.ShapeOf(i) : nullptr;
  const Placement placement{position, orientation.normalized(), shape, bodies.materials.Radius(i),
                            false, bodies.IsGod(i)};
  if (std::optional<Error> error = CheckInside(placement, body)) return *error;
  if (std::optional<Error> error = CheckApart(placement, i, started, body)) return *error;
  if (std::optional<Error> error = CheckApartFromStatics(placement, body)) return *error;
  return Status::Ok();
}

void Admission::Rebuild() {
  overlap_index_.Clear();
  const BodyStore& bodies = core_.bodies;
  for (std::uint32_t j = 0; j < bodies.Size(); ++j) {
    overlap_index_.Add(bodies.paths.Start(j).p0, bodies.materials.Radius(j));
  }
}

std::optional<Error> Admission::CheckInside(const Placement& placement,
                                            const std::string& body) const {
  const Container& box = core_.settings.container;
  const Vec3& position = placement.position;
  const double radius = placement.radius;
  const auto sphere_inside = [&] {
    return ((position.array() - radius) >= box.lo.array()).all() &&
           ((position.array() + radius) <= box.hi.array()).all();
  };
  if (placement.shape != nullptr && box.kind == Container::Kind::kWalledBox && !sphere_inside()) {
    // Only a body whose bounding sphere crosses a wall can have a vertex outside.
    const ConvexPolyhedron& poly = *placement.shape->polyhedron;
    const Eigen::Matrix3d rotation = placement.orientation.toRotationMatrix();
    for (int v = 0; v < poly.vertex_count(); ++v) {
      const Vec3 x = rotation * poly.vertex(v) + position;
      for (int k = 0; k < 3; ++k) {
        if (x[k] < box.lo[k] || x[k] > box.hi[k]) {
          return Error{body + "vertex " + std::to_string(v) + " lies outside the walled box " +
                       "on axis " + std::to_string(k) + " (" + FormatExact(x[k]) + " not in [" +
                       FormatExact(box.lo[k]) + ", " + FormatExact(box.hi[k]) + "])"};
        }
      }
    }
  } else if (placement.shape == nullptr && box.kind == Container::Kind::kWalledBox) {
    for (int k = 0; k < 3; ++k) {
      if (position[k] - radius < box.lo[k] || position[k] + radius > box.hi[k]) {
        return Error{body + "position[" + std::to_string(k) + "] = " + FormatExact(position[k]) +
                     " puts the sphere (radius " + FormatExact(radius) +
                     ") outside the walled box [" + FormatExact(box.lo[k]) + ", " +
                     FormatExact(box.hi[k]) + "]"};
      }
    }
  } else if (box.kind == Container::Kind::kPeriodicBox) {
    for (int k = 0; k < 3; ++k) {
      if (position[k] < box.lo[k] || position[k] >= box.hi[k]) {
        return Error{body + "position[" + std::to_string(k) + "] = " + FormatExact(position[k]) +
                     " is outside the periodic box [" + FormatExact(box.lo[k]) + ", " +
                     FormatExact(box.hi[k]) + ")"};
      }
      if (2 * radius >= 0.5 * (box.hi[k] - box.lo[k])) {
        return Error{body + "radius " + FormatExact(radius) +
                     " is too large for the periodic box (diameter must be < half the box)"};
      }
    }
  }
  return std::nullopt;
}

template <typename Fn>
void Admission::ForEachNear(const Vec3& p, double reach, std::uint32_t exclude, bool started,
                            Fn&& fn) const {
  const BodyStore& bodies = core_.bodies;
  const auto orientation = [&](std::uint32_t j, double t) {
    return bodies.rigid.Tracked() ? bodies.RigidPathOf(j).OrientationAt(t).normalized()
                                  : Eigen::Quaterniond::Identity();
  };
  if (!started) {
    // Before the start every body is still where it was added: use the spatial hash.
    overlap_index_.ForEachNear(p, reach, [&](std::uint32_t j, const Vec3& q, double) {
      if (j != exclude) fn(j, q, bodies.rigid.Tracked() ? bodies.rigid.Orientation0(j)
                                                         : Eigen::Quaterniond::Identity());
    });
    return;
  }
  // While running (rare), every body at the current time.
  const double now = core_.Now();
  for (std::uint32_t j = 0; j < bodies.Size(); ++j) {
    if (j != exclude) fn(j, bodies.paths.PathOf(j).PositionAt(now), orientation(j, now));
  }
}

std::optional<Error> Admission::CheckApart(const Placement& placement, std::uint32_t exclude,
                                           bool started, const std::string& body) const {
  const BodyStore& bodies = core_.bodies;
  const Vec3& p = placement.position;
  std::optional<std::uint32_t> found;  // the lowest public slot touched
  bool spheres = false;                // ... and whether both are spheres
  double distance = 0;
  ForEachNear(p, placement.radius, exclude, started,
              [&](std::uint32_t j, const Vec3& q, const Eigen::Quaterniond& q_j) {
    const Vec3 d = core_.MinimumImage(q - p);
    const double reach = placement.radius + bodies.materials.Radius(j);
    const std::uint32_t slot = bodies.ids.PublicOf(j);
    if (found && slot >= *found) return;
    if (placement.is_god && bodies.IsGod(j)) return;  // god objects pass each other
    const BodyShape* shape_j = bodies.IsPolyhedron(j) ? &bodies.rigid.ShapeOf(j) : nullptr;
    if (placement.shape == nullptr && shape_j == nullptr) {
      // Spheres: overlapping beyond round-off (a static sphere too).
      if (d.squaredNorm() < reach * reach * (1 - 1e-12)) {
        found = slot;
        spheres = true;
        distance = d.norm() - reach;
      }
      return;
    }
    // A polyhedron on either side: touching within the tolerance counts.
    if (d.squaredNorm() >= reach * reach) return;
    double gap = 0;
    if (placement.shape != nullptr && shape_j != nullptr) {
      gap = FindClosestFeatures(*placement.shape->tracked, Pose{placement.orientation, p},
                                *shape_j->tracked, Pose{q_j, p + d})
                .distance;
    } else if (placement.shape != nullptr) {
      gap = FindClosestFeatureToPoint(*placement.shape->tracked, Pose{placement.orientation, p},
                                      p + d)
                .distance -
            bodies.materials.Radius(j);
    } else {
      gap = FindClosestFeatureToPoint(*shape_j->tracked, Pose{q_j, p + d}, p).distance -
            placement.radius;
    }
    // Next to a static body, touching is allowed: the contact is its start.
    const double limit = core_.settings.contact_tolerance * reach;
    if (placement.is_static ? gap < -limit : gap <= limit) {
      found = slot;
      spheres = false;
      distance = gap;
    }
  });
  if (!found) return std::nullopt;
  if (spheres) {
    return Error{body + "overlaps body " + std::to_string(*found) + " at the start (t = " +
                 FormatExact(core_.Now()) + ")"};
  }
  return Error{body + "touches or overlaps body " + std::to_string(*found) +
               " at the start (distance " + FormatExact(distance) + ")"};
}

}  // namespace sparsedyn
