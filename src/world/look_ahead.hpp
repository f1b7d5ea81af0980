// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "world/sparse_phase.hpp"

namespace sparsedyn {

/// The look-ahead of a gas beyond the caches (SparsePhase::FetchesAhead): fetches what the next
/// events will read while this one is handled. Fetches only: it changes no result.
class LookAhead {
 public:
  LookAhead(const ElementPaths& paths, const SparsePhase& sparse) : paths_(paths), sparse_(sparse) {}

  /// After an event: starts the fetches of the coming events' data. Out of line: inlined in
  /// the event loop, GCC tested the cell count's divisor for 1 at every fetch instead of once
  /// (+53 M instructions in a gas of 10^5, +2%).
  [[gnu::noinline]] void Fetch() const;

 private:
  void FetchElement(std::uint32_t e) const;
  std::uint32_t CellAhead(std::uint32_t e) const;

  const ElementPaths& paths_;
  const SparsePhase& sparse_;
};

}  // namespace sparsedyn
