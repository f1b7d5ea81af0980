// SPDX-License-Identifier: MIT
#include "world/body_store.hpp"

#include <algorithm>

#include "narrow/advancement.hpp"

namespace sparsedyn {

double BodyStore::SpinRadiusOf(std::uint32_t i) const {
  if (!IsPolyhedron(i)) return 0.0;  // a sphere's turning moves no surface
  return narrow::SpinRadius(*rigid.ShapeOf(i).polyhedron, RigidPathOf(i));
}

double BodyStore::MaxSurfaceAcceleration(std::uint32_t count) const {
  const Accelerations& accelerations = paths.accelerations();
  double most = 0.0;
  for (std::uint32_t i = 0; i < count; ++i) {
    // A sphere's turning moves no surface.
    const double turning =
        IsPolyhedron(i) ? rigid.Omega(i).squaredNorm() * rigid.SpinRadius(i) : 0.0;
    const double free = HasDrag(i) ? AccelerationBound(i) : accelerations.Free(i).norm();
    most = std::max(most, free + turning);
  }
  return most;
}

void BodyStore::Permute(const std::vector<std::uint32_t>& old_of_new) {
  const auto permute = [&old_of_new](auto& values) { PermuteVector(values, old_of_new); };
  permute(paths.Records());
  paths.accelerations().Permute(permute);
  paths.drags().Permute(permute);
  materials.Permute(permute);
  rigid.Permute(permute);
  envelopes.Permute(permute);
  thrusts.Permute(permute);
  gods.Permute(permute);
  ids.Permute(permute);
}

std::size_t BodyStore::MemoryBytes() const {
  return paths.MemoryBytes() + materials.MemoryBytes() + rigid.MemoryBytes() +
         envelopes.MemoryBytes() + thrusts.MemoryBytes() + gods.MemoryBytes() + ids.MemoryBytes() +
         statics.MemoryBytes();
}

}  // namespace sparsedyn
