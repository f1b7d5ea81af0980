// SPDX-License-Identifier: MIT
// The conventional method's broad phase: sort and sweep of axis-aligned boxes along x
// (Baraff 1992, "Dynamic simulation of non-penetrating rigid bodies", §7: sort-and-sweep with
// coherent insertion sort).
#pragma once

#include <cstdint>
#include <vector>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// An axis-aligned box: a body's bounding sphere grown to a cube.
struct Aabb {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
};

/// Keeps the boxes sorted by lo.x between steps: bodies move little per step, so an insertion
/// sort of the previous order costs O(N + swaps) instead of O(N lg N).
class SweepAndPrune {
 public:
  /// Takes this step's boxes (index = body) and re-sorts; returns the swaps made.
  std::uint64_t Update(const std::vector<Aabb>& boxes);

  /// Calls visit(a, b) with a < b for every pair of overlapping boxes, each pair once.
  template <typename Visit>
  void ForEachOverlap(Visit&& visit) const {
    for (std::size_t k = 0; k < order_.size(); ++k) {
      const Aabb& p = boxes_[order_[k]];
      // Sorted by lo.x: every box that starts before p ends on x follows p directly.
      for (std::size_t m = k + 1; m < order_.size(); ++m) {
        const Aabb& q = boxes_[order_[m]];
        if (q.lo.x() > p.hi.x()) break;
        if (q.lo.y() > p.hi.y() || p.lo.y() > q.hi.y()) continue;
        if (q.lo.z() > p.hi.z() || p.lo.z() > q.hi.z()) continue;
        const std::uint32_t a = order_[k];
        const std::uint32_t b = order_[m];
        visit(a < b ? a : b, a < b ? b : a);
      }
    }
  }

  const std::vector<std::uint32_t>& order() const { return order_; }

 private:
  std::vector<Aabb> boxes_;
  std::vector<std::uint32_t> order_;  // body indices by increasing lo.x
};

}  // namespace sparsedyn
