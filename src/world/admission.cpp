// SPDX-License-Identifier: MIT
#include "world/admission.hpp"

#include <cmath>

#include "base/format.hpp"
#include "world/body_checks.hpp"

namespace sparsedyn {

Result<Admission::Accepted> Admission::Check(const BodyDef& def, std::uint32_t index,
                                             bool started) const {
  if (std::optional<Error> error = CheckBodyValues(def, index)) return *error;
  const std::string body = "body " + std::to_string(index) + ": ";
  const bool polyhedron = def.shape != nullptr;
  const BodyStore& bodies = core_.bodies;
  if (index > 0 && polyhedron != bodies.rigid.Any()) {
    return Error{body + "a World holds spheres or polyhedra, not both (this body is a " +
                 (polyhedron ? "polyhedron" : "sphere") + ", body 0 is not)"};
  }
  if (polyhedron && !def.envelope.IsZero()) {
    return Error{body + "envelopes are for spheres; a polyhedron's path is exact"};
  }
  if (polyhedron && started) {
    return Error{body + "polyhedra are added before the first AdvanceTo"};
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
  if (std::optional<Error> error = CheckInside(def, shape, accepted.radius, body)) return *error;
  if (polyhedron) {
    double distance = 0;
    if (std::optional<std::uint32_t> other = FindPolyhedronOverlap(def, *shape, distance)) {
      return Error{body + "touches or overlaps body " + std::to_string(*other) +
                   " at the start (distance " + FormatExact(distance) + ")"};
    }
  } else if (std::optional<std::uint32_t> other = FindOverlap(def.position, def.radius, started)) {
    return Error{body + "overlaps body " + std::to_string(*other) + " at the start (t = " +
                 FormatExact(core_.Now()) + ")"};
  }
  return accepted;
}

std::optional<Error> Admission::CheckInside(const BodyDef& def, const BodyShape* shape,
                                            double radius, const std::string& body) const {
  const Container& box = core_.settings.container;
  const auto sphere_inside = [&] {
    return ((def.position.array() - radius) >= box.lo.array()).all() &&
           ((def.position.array() + radius) <= box.hi.array()).all();
  };
  if (shape != nullptr && box.kind == Container::Kind::kWalledBox && !sphere_inside()) {
    // Only a body whose bounding sphere crosses a wall can have a vertex outside.
    const ConvexPolyhedron& poly = *shape->polyhedron;
    const Eigen::Matrix3d rotation = def.orientation.normalized().toRotationMatrix();
    for (int v = 0; v < poly.vertex_count(); ++v) {
      const Vec3 x = rotation * poly.vertex(v) + def.position;
      for (int k = 0; k < 3; ++k) {
        if (x[k] < box.lo[k] || x[k] > box.hi[k]) {
          return Error{body + "vertex " + std::to_string(v) + " lies outside the walled box " +
                       "on axis " + std::to_string(k) + " (" + FormatExact(x[k]) + " not in [" +
                       FormatExact(box.lo[k]) + ", " + FormatExact(box.hi[k]) + "])"};
        }
      }
    }
  } else if (shape == nullptr && box.kind == Container::Kind::kWalledBox) {
    for (int k = 0; k < 3; ++k) {
      if (def.position[k] - radius < box.lo[k] || def.position[k] + radius > box.hi[k]) {
        return Error{body + "position[" + std::to_string(k) + "] = " +
                     FormatExact(def.position[k]) + " puts the sphere (radius " +
                     FormatExact(radius) + ") outside the walled box [" + FormatExact(box.lo[k]) +
                     ", " + FormatExact(box.hi[k]) + "]"};
      }
    }
  } else if (box.kind == Container::Kind::kPeriodicBox) {
    for (int k = 0; k < 3; ++k) {
      if (def.position[k] < box.lo[k] || def.position[k] >= box.hi[k]) {
        return Error{body + "position[" + std::to_string(k) + "] = " +
                     FormatExact(def.position[k]) + " is outside the periodic box [" +
                     FormatExact(box.lo[k]) + ", " + FormatExact(box.hi[k]) + ")"};
      }
      if (2 * radius >= 0.5 * (box.hi[k] - box.lo[k])) {
        return Error{body + "radius " + FormatExact(radius) +
                     " is too large for the periodic box (diameter must be < half the box)"};
      }
    }
  }
  return std::nullopt;
}

std::optional<std::uint32_t> Admission::FindOverlap(const Vec3& p, double radius,
                                                    bool started) const {
  auto overlaps = [&](const Vec3& q, double r) {
    const Vec3 d = core_.MinimumImage(q - p);
    const double reach = radius + r;
    return d.squaredNorm() < reach * reach * (1 - 1e-12);
  };
  std::optional<std::uint32_t> found;
  if (!started) {
    // Before the start every body is still at its initial position: use the spatial hash.
    overlap_index_.ForEachNear(p, radius, [&](std::uint32_t j, const Vec3& q, double r) {
      if (overlaps(q, r) && (!found || j < *found)) found = j;
    });
    return found;
  }
  // Bodies added while running (rare) are compared with every body at the current time.
  const BodyStore& bodies = core_.bodies;
  for (std::uint32_t j = 0; j < bodies.Size(); ++j) {
    if (overlaps(bodies.paths.PathOf(j).PositionAt(core_.Now()), bodies.materials.Radius(j))) {
      return bodies.ids.PublicOf(j);
    }
  }
  return std::nullopt;
}

std::optional<std::uint32_t> Admission::FindPolyhedronOverlap(const BodyDef& def,
                                                              const BodyShape& shape,
                                                              double& distance) const {
  // Before the start (polyhedra are only added then) index j is the body's public index and
  // its path start is where it was added.
  const BodyStore& bodies = core_.bodies;
  const TrackedPolyhedron& tracked = *shape.tracked;
  const double radius = shape.polyhedron->bounding_radius();
  const Pose pose{def.orientation.normalized(), def.position};
  std::optional<std::uint32_t> found;
  overlap_index_.ForEachNear(def.position, radius, [&](std::uint32_t j, const Vec3& q, double r) {
    const Vec3 d = core_.MinimumImage(q - def.position);
    if (d.squaredNorm() >= (radius + r) * (radius + r)) return;
    const Pose other{bodies.rigid.Orientation0(j), def.position + d};
    const ClosestFeatures features =
        FindClosestFeatures(tracked, pose, *bodies.rigid.ShapeOf(j).tracked, other);
    if (features.distance <= core_.settings.contact_tolerance * (radius + r) &&
        (!found || j < *found)) {
      found = j;
      distance = features.distance;
    }
  });
  return found;
}

}  // namespace sparsedyn
