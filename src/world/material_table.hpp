// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace sparsedyn {

/// What bodies share: their element radius, inverse mass, restitution and friction. A gas has
/// one material, and its hot loops then read no per-body value.
struct Material {
  double radius;
  double inv_mass;
  double restitution;
  double friction;
};

/// The distinct materials of a World, each stored once.
class MaterialTable {
 public:
  /// The index of `material`, added unless an equal one is there.
  std::uint32_t Add(const Material& material) {
    const std::array<double, 4> key{material.radius, material.inv_mass, material.restitution,
                                    material.friction};
    const auto [found, added] =
        index_.try_emplace(key, static_cast<std::uint32_t>(materials_.size()));
    if (added) materials_.push_back(material);
    return found->second;
  }
  const Material& operator[](std::uint32_t m) const { return materials_[m]; }
  std::size_t size() const { return materials_.size(); }
  const Material* data() const { return materials_.data(); }

  std::size_t MemoryBytes() const {
    // A std::map node holds its value and about four pointers.
    return materials_.capacity() * sizeof(Material) +
           index_.size() * (sizeof(std::array<double, 4>) + 40);
  }

 private:
  std::vector<Material> materials_;
  std::map<std::array<double, 4>, std::uint32_t> index_;  // (r, 1/m, e, mu) -> material
};

}  // namespace sparsedyn
