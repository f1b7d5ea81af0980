// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "base/huge_pages.hpp"
#include "world/material_table.hpp"

namespace sparsedyn {

/// Each body's material (an index into the World's few distinct ones).
class BodyMaterials {
 public:
  void Append(const Material& material) { of_.push_back(table_.Add(material)); }

  double Radius(std::uint32_t i) const { return table_[of_[i]].radius; }
  double InvMass(std::uint32_t i) const { return table_[of_[i]].inv_mass; }
  double Restitution(std::uint32_t i) const { return table_[of_[i]].restitution; }
  double Friction(std::uint32_t i) const { return table_[of_[i]].friction; }

  const MaterialTable& table() const { return table_; }
  /// Per body, the index into table() (the batch pair test reads it without bounds checks).
  const std::uint32_t* PerBody() const { return of_.data(); }

  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    permute(of_);
  }
  std::size_t MemoryBytes() const {
    return table_.MemoryBytes() + of_.capacity() * sizeof(std::uint32_t);
  }

 private:
  MaterialTable table_;
  BigVector<std::uint32_t> of_;  // per body, into table_
};

}  // namespace sparsedyn
