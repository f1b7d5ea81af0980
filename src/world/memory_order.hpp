// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <limits>

#include "world/detailed_phase.hpp"
#include "world/sparse_phase.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// Memory order: every so often the elements are renumbered along a Morton curve of their grid
/// cells, so that elements near in space are near in memory and a prediction's scan of the 27
/// cells around an element touches a few cache lines instead of one per neighbour.
class MemoryOrder {
 public:
  MemoryOrder(WorldCore& core, SparsePhase& sparse, DetailedPhase& detailed)
      : core_(core), sparse_(sparse), detailed_(detailed) {}

  /// Counts an event and renumbers the elements when the period's events have passed.
  void CountEvent() {
    if (++events_ < period_) return;
    events_ = 0;
    Reorder();
  }
  /// After the element count or the broad phase changed: the count starts again.
  void Restart() {
    events_ = 0;
    SetPeriod();
  }
  /// The period for the elements and the broad phase there are now.
  void SetPeriod();
  /// Renumbers the elements now (the grid's Morton order).
  void Reorder();

 private:
  WorldCore& core_;
  SparsePhase& sparse_;
  DetailedPhase& detailed_;
  std::uint64_t events_ = 0;
  std::uint64_t period_ = std::numeric_limits<std::uint64_t>::max();  // none: no grid
};

}  // namespace sparsedyn
