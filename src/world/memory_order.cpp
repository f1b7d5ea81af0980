// SPDX-License-Identifier: MIT
#include "world/memory_order.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

namespace sparsedyn {
namespace {

// Renumber after this many events per element: often enough to follow the diffusion of the
// elements across cells, rarely enough that the O(N log N) pass is a small part of the cost.
// While the data fit in the caches (fewer elements than the look-ahead's threshold) memory
// order matters little, and a pass (~3M instructions at 10^4, the queue rebuilt, the caches
// cold after it) costs more than it saves: the gas at 10^4 +1.4-2.4% every 256 events per
// element (docs/lab/measurements.md#fifteenth-measurement), which still follows the diffusion.
// Beyond the caches 64 against 32: 10^5 +0.8-2.5%, 10^6 +2.4%; 16: -2%, 128: +0.9% at 10^5
// (docs/lab/measurements.md#eighteenth-measurement).
constexpr std::uint64_t kEventsPerElementBetweenReorders = 64;
constexpr std::uint64_t kEventsPerElementBetweenReordersInCache = 256;

}  // namespace

void MemoryOrder::SetPeriod() {
  // Worked out here rather than per event (the event loop's check is then one comparison).
  const std::uint64_t n = core_.bodies.Size();
  const std::uint64_t per_element = n < SparsePhase::kFetchAheadMinElements
                                        ? kEventsPerElementBetweenReordersInCache
                                        : kEventsPerElementBetweenReorders;
  // AllPairs visits every element anyway; an empty world has nothing to renumber.
  period_ = sparse_.grid() && n > 0 ? per_element * n : std::numeric_limits<std::uint64_t>::max();
}

void MemoryOrder::Reorder() {
  SPARSEDYN_ASSERT(sparse_.grid() && !core_.bodies.envelopes.AnyOwn(),
                   "Reorder: only worlds on the grid (never built with envelopes) are renumbered");
  const Grid& grid = *sparse_.grid();
  const auto n = core_.bodies.Size();
  std::vector<std::uint64_t> key(n);
  for (std::uint32_t i = 0; i < n; ++i) key[i] = grid.MortonKey(grid.CellOf(i));
  std::vector<std::uint32_t> old_of_new(n);
  std::iota(old_of_new.begin(), old_of_new.end(), 0u);
  std::stable_sort(old_of_new.begin(), old_of_new.end(),
                   [&key](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  std::vector<std::uint32_t> new_of_old(n);
  for (std::uint32_t e = 0; e < n; ++e) new_of_old[old_of_new[e]] = e;

  // The queue holds the event times and the predictions.
  ElementQueue& queue = sparse_.queue();
  std::vector<double> time(n, kInfinity);
  std::vector<Prediction> prediction(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    prediction[i] = sparse_.PredictionOf(i);
    if (prediction[i].kind != EventKind::kNone) time[i] = queue.TimeOf(i);
  }
  PermuteVector(time, old_of_new);
  PermuteVector(prediction, old_of_new);
  core_.bodies.Permute(old_of_new);
  for (std::uint32_t e = 0; e < n; ++e) {
    std::uint32_t& target = prediction[e].target;
    if (target != kNoIndex) target = new_of_old[target];
  }
  sparse_.ShareRecords();  // the records moved, their links with them
  sparse_.grid()->Permute(old_of_new);
  detailed_.engagements().Renumber(new_of_old);
  // The queue is keyed by element: refill it (its tie-break by slot now follows the new order,
  // which is itself a deterministic function of the run).
  queue.Clear();
  for (std::uint32_t e = 0; e < n; ++e) {
    sparse_.PredictionOf(e) = prediction[e];
    if (prediction[e].kind != EventKind::kNone) queue.Set(e, time[e], prediction[e].kind);
  }
}

}  // namespace sparsedyn
