// SPDX-License-Identifier: MIT
// World::Validate: the invariants at the current time, checked from the paths alone (no
// overlap beyond the contact tolerance, every body inside its walls).
#include <optional>
#include <string>

#include "base/format.hpp"
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

}  // namespace

Status World::Impl::Validate() const {
  const BodyStore& bodies = core_.bodies;
  const auto n = bodies.Size();
  const double now = core_.Now();
  const double tolerance = core_.settings.contact_tolerance;
  if (bodies.rigid.AnyPolyhedron()) {
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = i + 1; j < n; ++j) {
        const Vec3 shift = polyhedra_.PairShift(i, j);
        const Vec3 d = bodies.paths.PathOf(j).PositionAt(now) + shift -
                       bodies.paths.PathOf(i).PositionAt(now);
        const double reach = bodies.materials.Radius(i) + bodies.materials.Radius(j);
        if (d.squaredNorm() >= reach * reach) continue;
        const ClosestFeatures f = polyhedra_.PairFeatures(i, j, shift, std::nullopt);
        if (f.distance < -polyhedra_.PairTolerance(i, j)) {
          return Error{"bodies " + std::to_string(bodies.ids.PublicOf(i)) + " and " +
                       std::to_string(bodies.ids.PublicOf(j)) + " interpenetrate by " +
                       FormatExact(-f.distance) + " at t = " + FormatExact(now)};
        }
      }
      if (!core_.Walled()) continue;
      const Pose pose = bodies.RigidPathOf(i).PoseAt(now);
      const ConvexPolyhedron& polyhedron = *bodies.rigid.ShapeOf(i).polyhedron;
      for (int w = 0; w < 6; ++w) {
        const WallPlane plane = BoxWall(core_.settings.container, w);
        const Vec3 n_B = pose.rotation.conjugate() * plane.normal;
        const double gap =
            plane.normal.dot(pose.ToWorld(polyhedron.vertex(polyhedron.SupportVertex(-n_B)))) -
            plane.offset;
        if (gap < -tolerance * bodies.materials.Radius(i)) {
          return Error{BeyondWall(bodies.ids.PublicOf(i), w, -gap, now)};
        }
      }
    }
    return Status::Ok();
  }
  auto check_pair = [&](std::uint32_t i, std::uint32_t j) -> std::optional<Error> {
    const Vec3 d = core_.MinimumImage(bodies.paths.PathOf(j).PositionAt(now) -
                                      bodies.paths.PathOf(i).PositionAt(now));
    const double reach = bodies.materials.Radius(i) + bodies.materials.Radius(j);
    const double gap = d.norm() - reach;
    if (gap < -tolerance * reach) {
      return Error{Overlap(bodies.ids.PublicOf(i), bodies.ids.PublicOf(j), -gap, now)};
    }
    return std::nullopt;
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
    if (core_.Walled()) {
      const Vec3 p = bodies.paths.PathOf(i).PositionAt(now);
      for (int w = 0; w < 6; ++w) {
        const WallPlane plane = BoxWall(core_.settings.container, w);
        const double gap = plane.normal.dot(p) - plane.offset - bodies.materials.Radius(i);
        if (gap < -tolerance * bodies.materials.Radius(i)) {
          return Error{BeyondWall(bodies.ids.PublicOf(i), w, -gap, now)};
        }
      }
    }
  }
  return Status::Ok();
}

}  // namespace sparsedyn
