// SPDX-License-Identifier: MIT
// World::Validate: the invariants at the current time, checked from the paths alone (no
// overlap beyond the contact tolerance, every body inside its walls, every body with drag
// inside its element's envelope; god objects may pass through each other, statics and walls).
#include <optional>
#include <string>

#include "base/format.hpp"
#include "world/pair_frame.hpp"
#include "world/world_impl.hpp"

namespace sparsedyn {
namespace {

std::string Overlap(std::uint32_t a, std::uint32_t b, double depth, double t) {
  return "bodies " + std::to_string(a) + " and " + std::to_string(b) + " overlap by " +
         FormatExact(depth) + " at t = " + FormatExact(t);
}

std::string BeyondWall(std::uint32_t a, int wall, double depth, double t) {
  return "body " + std::to_string(a) + " is " + FormatExact(depth) + " beyond wall " +
         std::to_string(wall) + " at t = " + FormatExact(t);
}

// A body with drag whose true position has left its element's envelope about the Taylor path
// (the margin: a few roundings of the positions compared).
std::optional<Error> CheckInsideEnvelope(const BodyStore& bodies, std::uint32_t i, double now) {
  if (!bodies.HasDrag(i)) return std::nullopt;
  const Path path = bodies.paths.PathOf(i);
  const Vec3 p = bodies.paths.TruePositionAt(i, now);
  const double off = (p - path.PositionAt(now)).norm();
  const double allowed = bodies.envelopes.Of(i).At(now - path.t0) + 0x1p-50 * (p.norm() + 1.0);
  if (off <= allowed) return std::nullopt;
  return Error{"body " + std::to_string(bodies.ids.PublicOf(i)) + " is " + FormatExact(off) +
               " from its element's path at t = " + FormatExact(now) + ", beyond its envelope " +
               FormatExact(allowed)};
}

}  // namespace

double World::Impl::GapNow(std::uint32_t i, std::uint32_t j) const {
  const BodyStore& bodies = core_.bodies;
  const bool poly_i = bodies.IsPolyhedron(i), poly_j = bodies.IsPolyhedron(j);
  if (!poly_i && !poly_j) {
    const double now = core_.Now();
    const Vec3 d = core_.MinimumImage(bodies.paths.TruePositionAt(j, now) -
                                      bodies.paths.TruePositionAt(i, now));
    return d.norm() - bodies.materials.Radius(i) - bodies.materials.Radius(j);
  }
  if (poly_i && poly_j) {
    return polyhedra_.PairFeatures(i, j, PairShift(core_, i, j), std::nullopt).distance;
  }
  const std::uint32_t p = poly_i ? i : j, s = poly_i ? j : i;
  return mixed_.Closest(p, s, std::nullopt).distance - bodies.materials.Radius(s);
}

double World::Impl::WallGapNow(std::uint32_t i, int wall) const {
  const BodyStore& bodies = core_.bodies;
  const double now = core_.Now();
  const WallPlane plane = BoxWall(core_.settings.container, wall);
  if (!bodies.IsPolyhedron(i)) {
    return plane.normal.dot(bodies.paths.TruePositionAt(i, now)) - plane.offset -
           bodies.materials.Radius(i);
  }
  const Pose pose = bodies.RigidPathOf(i).PoseAt(now);
  const ConvexPolyhedron& polyhedron = *bodies.rigid.ShapeOf(i).polyhedron;
  const Vec3 n_B = pose.rotation.conjugate() * plane.normal;
  return plane.normal.dot(pose.ToWorld(polyhedron.vertex(polyhedron.SupportVertex(-n_B)))) -
         plane.offset;
}

std::optional<Error> World::Impl::CheckAgainstStatics(std::uint32_t i) const {
  const BodyStore& bodies = core_.bodies;
  if (bodies.statics.Empty()) return std::nullopt;
  const double now = core_.Now();
  const Aabb box = BoxOfSphere(bodies.paths.TruePositionAt(i, now), bodies.materials.Radius(i));
  std::optional<Error> error;
  bodies.statics.tree().ForEachOverlapping(box, [&](std::uint32_t s) {
    if (error) return;
    const double gap = statics_.TouchNow(i, s, std::nullopt).contact.distance;
    if (gap < -statics_.Tolerance(i, s)) {
      error = Error{"body " + std::to_string(bodies.ids.PublicOf(i)) + " and static body " +
                    std::to_string(bodies.statics[s].slot) + " interpenetrate by " +
                    FormatExact(-gap) + " at t = " + FormatExact(now)};
    }
  });
  return error;
}

Status World::Impl::Validate() const {
  const BodyStore& bodies = core_.bodies;
  const auto n = bodies.Size();
  const double now = core_.Now();
  const double tolerance = core_.settings.contact_tolerance;
  // Pairs whose element spheres overlap (the elements of polyhedra are their bounding spheres),
  // from the grid's neighbours when there is one, else every pair.
  auto check_pair = [&](std::uint32_t i, std::uint32_t j) -> std::optional<Error> {
    const Vec3 d = core_.MinimumImage(bodies.paths.TruePositionAt(j, now) -
                                      bodies.paths.TruePositionAt(i, now));
    const double reach = bodies.materials.Radius(i) + bodies.materials.Radius(j);
    if (d.squaredNorm() >= reach * reach) return std::nullopt;
    if (bodies.IsGod(i) && bodies.IsGod(j)) return std::nullopt;  // they pass each other
    const double gap = GapNow(i, j);
    if (gap >= -tolerance * reach) return std::nullopt;
    const std::uint32_t a = bodies.ids.PublicOf(i), b = bodies.ids.PublicOf(j);
    if (bodies.IsPolyhedron(i) || bodies.IsPolyhedron(j)) {
      return Error{"bodies " + std::to_string(a) + " and " + std::to_string(b) +
                   " interpenetrate by " + FormatExact(-gap) + " at t = " + FormatExact(now)};
    }
    return Error{Overlap(a, b, -gap, now)};
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    if (sparse_.grid()) {
      std::optional<Error> error;
      sparse_.grid()->ForEachNeighbor(i, [&](std::uint32_t j, const Vec3&) {
        if (!error && j > i) error = check_pair(i, j);
      });
      if (error) return *error;
    } else {
      for (std::uint32_t j = i + 1; j < n; ++j) {
        if (std::optional<Error> error = check_pair(i, j)) return *error;
      }
    }
    // A god object goes where it is driven, through statics and walls.
    if (bodies.IsGod(i)) continue;
    if (std::optional<Error> error = CheckAgainstStatics(i)) return *error;
    if (std::optional<Error> error = CheckInsideEnvelope(bodies, i, now)) return *error;
    if (!core_.Walled()) continue;
    for (int w = 0; w < 6; ++w) {
      const double gap = WallGapNow(i, w);
      if (gap < -tolerance * bodies.materials.Radius(i)) {
        return Error{BeyondWall(bodies.ids.PublicOf(i), w, -gap, now)};
      }
    }
  }
  return Status::Ok();
}

}  // namespace sparsedyn
