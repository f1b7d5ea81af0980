// SPDX-License-Identifier: MIT
// sparsedyn::CapHits() reads the counters of math/cap_counters.hpp: it lives in world/ with
// the public Statistics it fills in, since math/ comes before it in the layer order.
#include "math/cap_counters.hpp"

#include "sparsedyn/statistics.hpp"

namespace sparsedyn {

CapCounters CapHits() {
  const auto load = [](const std::atomic<std::uint64_t>& c) {
    return c.load(std::memory_order_relaxed);
  };
  return CapCounters{load(caps::root_narrowing), load(caps::meeting_certification),
                     load(caps::impulse_rounds), load(caps::level_crossing), load(caps::bisection)};
}

void ResetCapHits() {
  for (std::atomic<std::uint64_t>* c :
       {&caps::root_narrowing, &caps::meeting_certification, &caps::impulse_rounds,
        &caps::level_crossing, &caps::bisection}) {
    c->store(0, std::memory_order_relaxed);
  }
}

}  // namespace sparsedyn
