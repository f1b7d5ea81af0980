// SPDX-License-Identifier: MIT
// Memory order: every so often the elements are renumbered along a Morton curve of their grid
// cells, so that elements near in space are near in memory and a prediction's scan of the 27
// cells around an element touches a few cache lines instead of one per neighbour.
#include <algorithm>
#include <limits>
#include <numeric>

#include "world/world_impl.hpp"

namespace sparsedyn {
namespace {

// Renumber after this many events per element: often enough to follow the diffusion of the
// elements across cells, rarely enough that the O(N log N) pass is a small part of the cost.
// While the data fit in the caches (fewer elements than the look-ahead's threshold) memory
// order matters little, and a pass (~3M instructions at 10^4, the queue rebuilt, the caches
// cold after it) costs more than it saves: the gas at 10^4 +1.4-2.4% every 256 events per
// element (docs/benchmarks.md, fifteenth measurement), which still follows the diffusion.
// Beyond the caches 64 against 32: 10^5 +0.8-2.5%, 10^6 +2.4% (eighteenth measurement; 16:
// -2%, 128: +0.9% at 10^5).
constexpr std::uint64_t kEventsPerElementBetweenReorders = 64;
constexpr std::uint64_t kEventsPerElementBetweenReordersInCache = 256;

template <typename Vector>
void PermuteVector(Vector& values, const std::vector<std::uint32_t>& old_of_new) {
  Vector permuted;
  permuted.reserve(values.size());  // exact: the run's memory is part of its cost
  for (const std::uint32_t old : old_of_new) permuted.push_back(values[old]);
  values.swap(permuted);
}

}  // namespace

void World::Impl::SetReorderPeriod() {
  // Worked out here rather than per event (the event loop's check is then one comparison).
  const std::uint64_t n = starts_.size();
  const std::uint64_t per_element = n < kFetchAheadMinElements
                                        ? kEventsPerElementBetweenReordersInCache
                                        : kEventsPerElementBetweenReorders;
  // AllPairs visits every element anyway; an empty world has nothing to renumber.
  reorder_period_ = grid_ && n > 0 ? per_element * n : std::numeric_limits<std::uint64_t>::max();
}

void World::Impl::Reorder() {
  SPARSEDYN_ASSERT(grid_ && !has_envelopes_,
                   "Reorder: only worlds on the grid (never built with envelopes) are renumbered");
  const auto n = static_cast<std::uint32_t>(starts_.size());
  std::vector<std::uint64_t> key(n);
  for (std::uint32_t i = 0; i < n; ++i) key[i] = grid_->MortonKey(grid_->CellOf(i));
  std::vector<std::uint32_t> old_of_new(n);
  std::iota(old_of_new.begin(), old_of_new.end(), 0u);
  std::stable_sort(old_of_new.begin(), old_of_new.end(),
                   [&key](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  std::vector<std::uint32_t> new_of_old(n);
  for (std::uint32_t e = 0; e < n; ++e) new_of_old[old_of_new[e]] = e;

  // The queue holds the event times and the predictions.
  std::vector<double> time(n, kInfinity);
  std::vector<Prediction> prediction(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    prediction[i] = PredictionOf(i);
    if (prediction[i].kind != EventKind::kNone) time[i] = queue_.TimeOf(i);
  }
  PermuteVector(time, old_of_new);
  PermuteVector(prediction, old_of_new);
  PermuteVector(starts_, old_of_new);
  if (own_accelerations_) PermuteVector(acceleration_, old_of_new);
  if (!held_by_.empty()) {
    PermuteVector(held_by_, old_of_new);
    PermuteVector(free_acceleration_, old_of_new);
  }
  PermuteVector(material_, old_of_new);
  if (polyhedra_) {
    PermuteVector(shape_, old_of_new);
    PermuteVector(q0_, old_of_new);
    PermuteVector(omega_, old_of_new);
    PermuteVector(spin_radius_, old_of_new);
  }
  PermuteVector(public_of_, old_of_new);
  for (std::uint32_t e = 0; e < n; ++e) {
    internal_of_[public_of_[e]] = e;
    std::uint32_t& target = prediction[e].target;
    if (target != kNoIndex) target = new_of_old[target];
  }
  ShareStarts();  // the records moved, their links with them
  grid_->Permute(old_of_new);
  engagements_.Renumber(new_of_old);
  // The queue is keyed by element: refill it (its tie-break by slot now follows the new order,
  // which is itself a deterministic function of the run).
  queue_.Clear();
  for (std::uint32_t e = 0; e < n; ++e) {
    PredictionOf(e) = prediction[e];
    if (prediction[e].kind != EventKind::kNone) queue_.Set(e, time[e], prediction[e].kind);
  }
}

}  // namespace sparsedyn
