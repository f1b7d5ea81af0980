// SPDX-License-Identifier: MIT
#include "conventional/sweep_and_prune.hpp"

#include <utility>

namespace sparsedyn {

std::uint64_t SweepAndPrune::Update(const std::vector<Aabb>& boxes) {
  boxes_ = boxes;  // into the capacity of the last step
  // Bodies added since the last update join at the end; the sort places them.
  while (order_.size() < boxes_.size()) order_.push_back(static_cast<std::uint32_t>(order_.size()));
  std::uint64_t swaps = 0;
  for (std::size_t k = 1; k < order_.size(); ++k) {
    const std::uint32_t moving = order_[k];
    const double key = boxes_[moving].lo.x();
    std::size_t m = k;
    for (; m > 0 && boxes_[order_[m - 1]].lo.x() > key; --m) {
      order_[m] = order_[m - 1];
      ++swaps;
    }
    order_[m] = moving;
  }
  return swaps;
}

}  // namespace sparsedyn
