// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// Which element holds which body. Internal (element) indices follow space (the World's memory
/// order, world/memory_order.cpp renumbers them); the public BodyId index is the order of
/// AddBody.
class BodyIds {
 public:
  /// The internal index of a new body whose public index and element index are both `index`.
  void Append(std::uint32_t index) {
    public_of_.push_back(index);
    internal_of_.push_back(index);
  }
  std::uint32_t PublicOf(std::uint32_t element) const { return public_of_[element]; }
  std::uint32_t InternalOf(std::uint32_t index) const { return internal_of_[index]; }
  BodyId IdOf(std::uint32_t element) const { return BodyId{public_of_[element], 0}; }
  /// The elements in public order (sums over bodies in this order do not depend on the memory
  /// order).
  const std::vector<std::uint32_t>& InPublicOrder() const { return internal_of_; }

  /// The elements were renumbered: new element e is old element old_of_new[e]; `permute`
  /// reorders a per-element vector that way.
  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    permute(public_of_);
    for (std::uint32_t e = 0; e < public_of_.size(); ++e) internal_of_[public_of_[e]] = e;
  }

  std::size_t MemoryBytes() const {
    return (public_of_.capacity() + internal_of_.capacity()) * sizeof(std::uint32_t);
  }

 private:
  std::vector<std::uint32_t> public_of_;    // internal index -> public index
  std::vector<std::uint32_t> internal_of_;  // public index -> internal index
};

}  // namespace sparsedyn
