// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "world/world_core.hpp"

namespace sparsedyn {

/// The shift that takes b to its periodic image nearest to a (zero outside periodic boxes).
inline Vec3 PairShift(const WorldCore& core, std::uint32_t a, std::uint32_t b) {
  const ElementPaths& paths = core.bodies.paths;
  const Vec3 d = paths.PathOf(b).PositionAt(paths.Now()) - paths.PathOf(a).PositionAt(paths.Now());
  return core.MinimumImage(d) - d;
}

/// The contact tolerance of a pair whose detailed phase measures gaps (polyhedra, and a sphere
/// against a polyhedron), m: relative to the sum of their element radii.
inline double PairTolerance(const WorldCore& core, std::uint32_t a, std::uint32_t b) {
  const BodyMaterials& materials = core.bodies.materials;
  return core.settings.contact_tolerance * (materials.Radius(a) + materials.Radius(b));
}

}  // namespace sparsedyn
