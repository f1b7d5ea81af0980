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

  /// After an event: starts the fetches of the coming events' data. Out of line, as before the
  /// World split: inlined in the event loop (with the test of d = 1 FastDivisor::Remainder had
  /// then) it was 24 M more instructions in a gas of 10^5, at the same speed.
  [[gnu::noinline]] void Fetch() const;

 private:
  void FetchElement(std::uint32_t e) const;
  std::uint32_t CellAhead(std::uint32_t e) const;

  const ElementPaths& paths_;
  const SparsePhase& sparse_;
};

}  // namespace sparsedyn
